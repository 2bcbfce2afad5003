#pragma once
// nck run --start-at / --start-at-block / --start-at-offset / --covered:
// a block search (TF5200 types 4, 3 and 1) from the command line; the run
// decodes without motion up to the mark, returns to the contour and goes on
// from there (docs/operating.md).
#include <optional>
#include <string_view>

#include "nck/prep/search_mark.hpp"

namespace nck::app {

// N<n>[:<pass>][@<program>] (type 4); nullopt when malformed.
std::optional<prep::SearchMark> parse_start_at(std::string_view text);
// <bytes>[:<pass>][@<program>] (type 1); nullopt when malformed.
std::optional<prep::SearchMark> parse_start_at_offset(std::string_view text);
// <K> (type 3): the K-th NC row read, comment and empty rows included.
std::optional<prep::SearchMark> parse_start_at_block(std::string_view text);

}  // namespace nck::app
