#include "nck/output/trace_columns.hpp"

#include <fmt/format.h>

namespace nck::app {

std::expected<TraceColumns, std::string> parse_trace_columns(std::string_view list) {
  TraceColumns c;
  std::size_t from = 0;
  while (from <= list.size()) {
    const std::size_t comma = std::min(list.find(',', from), list.size());
    const std::string_view name = list.substr(from, comma - from);
    if (name == "path.v") c.path_v = true;
    else if (name == "path.a") c.path_a = true;
    else if (name == "path.j") c.path_j = true;
    else return std::unexpected(fmt::format("'{}' is not a trace column (path.v, path.a, path.j)", name));
    from = comma + 1;
  }
  return c;
}

}  // namespace nck::app
