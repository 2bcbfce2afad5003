#pragma once
// The HMI's point lists (the preview, the path so far) as JSON columns:
// "x","y","z" in machine and "px","py","pz" in program coordinates (mm, 4
// decimals), the NC line moving there and 1 for a rapid.
#include <fmt/format.h>

#include <string>

#include "nck/report/report_series.hpp"

namespace nck::app::serve {

// Points: a range of items with mcs[3], pcs[3], line and rapid.
template <class Points>
void append_point_columns(std::string& s, const Points& points) {
  using Point = typename Points::value_type;
  for (std::size_t k = 0; k < 3; ++k) {
    s += fmt::format(R"(,"{}":)", "xyz"[k]) + array_of(points, [k](std::string& o, const Point& p) { append_number(o, p.mcs[k], 4); });
    s += fmt::format(R"(,"p{}":)", "xyz"[k]) + array_of(points, [k](std::string& o, const Point& p) { append_number(o, p.pcs[k], 4); });
  }
  s += R"(,"line":)" + array_of(points, [](std::string& o, const Point& p) { o += fmt::format("{}", p.line); });
  s += R"(,"rapid":)" + array_of(points, [](std::string& o, const Point& p) { o += p.rapid ? '1' : '0'; });
}

}  // namespace nck::app::serve
