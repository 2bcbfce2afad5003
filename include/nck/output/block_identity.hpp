#pragma once
// What an NC block is, whatever line it stands on: `nck diff` pairs the
// blocks of two runs by it (docs/decisions.md, "Run diff"), so that lines
// inserted into a program shift no block onto another. --final's block rows
// carry it.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace nck::app {

struct BlockIdentity {
  std::string text;     // the line without its `;` comment, blanks collapsed ("" when unknown)
  std::string section;  // the `%L` local subroutine it belongs to (upper case), "" in the program
  // The how-manieth line of this text in its section (a subroutine's two
  // `G0 Z2`), 1-based; 0 when the line could not be read.
  std::uint32_t pass = 0;
};

// A line as its identity's text: the `;` comment cut, blanks collapsed.
std::string identity_text(std::string_view line);
// The same into `out` (its buffer reused).
void identity_text(std::string_view line, std::string& out);

// The identities of `lines` (1-based line numbers) of the file at `path`,
// in the order given. Two reads of the file; the memory held is that of
// the lines asked for, so a program of millions of lines costs nothing
// more. A file that cannot be read gives identities with pass 0.
std::vector<BlockIdentity> block_identities(const std::string& path, const std::vector<std::uint32_t>& lines);

}  // namespace nck::app
