#pragma once
// `nck run --trace-columns LIST`: optional trace columns after the default
// ones (the default trace stays as it is). path.v is each channel's path
// velocity (mm/s, the kernel's, as the final state and a session report
// it); path.a and path.j are the path acceleration (mm/s^2) and jerk
// (mm/s^3), the backward differences of the path velocity over the cycles
// — what the set points do, so a jerk-limited slope shows its bound and
// STEP its steps.
#include <expected>
#include <string>
#include <string_view>
#include <vector>

#include "nck/core/kept_quotient.hpp"

namespace nck::app {

struct TraceColumns {
  bool path_v = false, path_a = false, path_j = false;
  bool any() const { return path_v || path_a || path_j; }
};

// "path.v,path.a,path.j" (any of them, in any order); an unknown name is an error text.
std::expected<TraceColumns, std::string> parse_trace_columns(std::string_view list);

// The path acceleration and jerk of one channel, updated every cycle.
class PathDerivatives {
 public:
  explicit PathDerivatives(double dt_s = 0.001) : dt_s_(dt_s) {}
  void update(double v_mm_s) {
    const double a = a_step_.divide(v_mm_s - v_mm_s_, dt_s_);
    j_mm_s3_ = j_step_.divide(a - a_mm_s2_, dt_s_);
    a_mm_s2_ = a;
    v_mm_s_ = v_mm_s;
  }
  double a_mm_s2() const { return a_mm_s2_; }
  double j_mm_s3() const { return j_mm_s3_; }

 private:
  KeptQuotient a_step_, j_step_;  // at a steady speed or acceleration the same quotients
  double dt_s_;
  double v_mm_s_ = 0, a_mm_s2_ = 0, j_mm_s3_ = 0;  // from rest
};

}  // namespace nck::app
