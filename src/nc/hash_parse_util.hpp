#pragma once
// Shared by the # command parsers: the context one command is parsed in,
// the argument helpers, and the parser of each command family. The table
// that maps keywords to parsers is in hash_commands.cpp.
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "block_words.hpp"

namespace nck::nc::detail {

inline bool args_error(BlockCtx& b, std::size_t pos, std::string msg) {
  return b.x.err.fail(ErrorId::NcHashArguments, pos, std::move(msg));
}

// Matches the keywords in order, spaces between; empty entries are skipped.
// On a mismatch the cursor stays where it was.
inline bool keywords(Cursor& c, std::span<const std::string_view> kws) {
  std::size_t save = c.pos;
  for (auto k : kws) {
    if (k.empty()) continue;
    c.skip_spaces();
    if (!c.match_keyword(k)) {
      c.pos = save;
      return false;
    }
  }
  return true;
}

inline bool keywords(Cursor& c, std::initializer_list<std::string_view> kws) {
  return keywords(c, std::span(kws.begin(), kws.size()));
}

// --- argument helpers (hash_commands.cpp) ----------------------------------
// An integer expression in lo..hi.
bool int_arg(Cursor& c, BlockCtx& b, int& out, int lo, int hi, std::string_view what);
// "[<int>]" -> value
bool bracket_int(Cursor& c, BlockCtx& b, int& out, int lo, int hi, std::string_view what);
// An identifier, upper case; empty if none.
std::string name_token(Cursor& c);
// [a, b, ...] with up to n expressions, empty = 0.
bool value_list(Cursor& c, BlockCtx& b, double* vals, int n, int& count);
// [NAME, NAME, ...] with up to max names.
bool named_list(Cursor& c, BlockCtx& b, std::vector<std::string>& names, std::size_t max);

// One # command being parsed, after its keywords.
struct HashCtx {
  Cursor& c;
  BlockCtx& b;
  Words& w;
  std::size_t pos;               // of the '#', for messages
  HashCommand cmd = ExplSyn{};   // what the command yields
  bool yields_command = true;    // false: it sets other words (#TIME) or nothing (#MSG)
  bool exclusive = true;         // false: other words may share the block
};

// --- command families, each parses what follows its keywords --------------
// hash_links.cpp: axis couplings
bool parse_set_ax_link(HashCtx& h);      // #SET AX LINK
bool parse_ax_link(HashCtx& h);          // #AX LINK [ON|OFF|NBR] ...
bool parse_enable_ax_link(HashCtx& h);   // #ENABLE AX LINK
bool parse_disable_ax_link(HashCtx& h);  // #DISABLE AX LINK
// hash_cs.cpp: coordinate systems, rotation, offsets
bool parse_cs(HashCtx& h);               // #CS
bool parse_acs(HashCtx& h);              // #ACS
bool parse_ecs(HashCtx& h);              // #ECS
bool parse_mcs(HashCtx& h);              // #MCS
bool parse_rotation(HashCtx& h);         // #ROTATION
bool parse_suppress_offsets(HashCtx& h); // #SUPPRESS OFFSETS
bool parse_tlc(HashCtx& h);              // #TLC
// contour_mode_syntax.cpp: #CONTOUR MODE [DEV PATH_DEV=..] (corner blending)
bool parse_contour_mode(HashCtx& h);
// slope_syntax.cpp: #SLOPE [TYPE=..] / #SLOPE DEFAULT, #SET SLOPE PROFIL[n]
bool parse_slope(HashCtx& h);
bool parse_set_slope_profil(HashCtx& h);
// A technology's command declares its parse_hash_command
// beside its type, in its own home (src/<tech>/nc/).

}  // namespace nck::nc::detail
