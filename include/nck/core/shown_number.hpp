#pragma once
// A number without floating-point noise (issue 48 item 4): rounded where
// arithmetic leaves it, so that 23.47 does not show as 23.47000000000009
// nor a lost time as -4.4e-16. Two steps:
// - what a person reads (the state document of the API and the HMI, the
//   offsets page): the control's internal resolution, 0.1 µm / 0.0001°
//   (TF5200 holds positions as integers of it; its resolution parameters
//   are not modelled, so the step is fixed);
// - files other programs compare (events, --final): 1e-6, the trace's six
//   decimals, so that a comparison at a tolerance of a micrometre still
//   holds and only the noise goes.
#include <cmath>

namespace nck {

inline constexpr double kShownSteps = 1e4;    // per mm, per °, per rpm: what a person reads
inline constexpr double kWrittenSteps = 1e6;  // per mm, per °, per rpm, per s: the output files

// `v` rounded to 1/steps (half away from zero), without -0; NaN and the
// infinities pass. nlohmann and fmt print the shortest representation of
// the double, so no noise digits show.
inline double shown(double v, double steps = kShownSteps) {
  if (!std::isfinite(v)) return v;
  const double r = std::round(v * steps) / steps;
  return r == 0 ? 0.0 : r;
}

// In an output file (events, --final).
inline double written(double v) { return shown(v, kWrittenSteps); }

}  // namespace nck
