#pragma once
// Where a block search restarts (TF5200 block search types 1, 3 and 4),
// as the command line, the PLC scenario and the HLI give it. Plain data,
// apart from the search itself (block_search.hpp), so that the scenario
// parser can name it.
#include <cstdint>
#include <string>

namespace nck::prep {

struct SearchMark {
  enum class Kind : std::uint8_t {
    file_offset = 1,    // the block whose text holds this byte offset of its file
    block_counter = 3,  // the first block at or after this NC row (Block::row)
    block_number = 4,   // the block with this N
  };
  Kind kind = Kind::block_number;
  std::int64_t value = 0;
  std::uint32_t pass = 1;  // types 1 and 4: the pass-th time the mark is met (loops)
  // Types 1 and 4: the file the mark lies in, by name ("sub.nc") or path;
  // empty: the main program for type 1, any file for type 4.
  std::string program;
  // How much of the restart block's path is already done, per mille
  // (0..1000): the real motion starts there.
  double covered_permille = 0;
  // HLI no_hold_at_restart: false (the default) holds after the return to
  // the contour until cycle start.
  bool no_hold_at_restart = false;
};

}  // namespace nck::prep
