#pragma once
// Small helpers shared by the # command parsers.
#include <initializer_list>
#include <string>
#include <string_view>

#include "block_words.hpp"

namespace nck::nc::detail {

inline bool args_error(BlockCtx& b, std::size_t pos, std::string msg) {
  return b.x.err.fail(ErrorId::NcHashArguments, pos, std::move(msg));
}

inline bool keywords(Cursor& c, std::initializer_list<std::string_view> kws) {
  std::size_t save = c.pos;
  for (auto k : kws) {
    c.skip_spaces();
    if (!c.match_keyword(k)) {
      c.pos = save;
      return false;
    }
  }
  return true;
}

// #DIST CTRL (dist_ctrl_syntax.cpp).
bool parse_dist_ctrl(Cursor& c, BlockCtx& b, std::size_t pos, HashCommand& out);

}  // namespace nck::nc::detail
