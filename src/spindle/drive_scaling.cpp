#include "nck/spindle/drive_scaling.hpp"

#include <cmath>

namespace nck::spindle {

double drive_output_value(std::uint32_t v_reso_num, std::uint32_t v_reso_denom,
                          std::uint32_t v_time_base, double speed_rpm, double cycle_s) noexcept {
  if (v_reso_denom == 0 || !std::isfinite(speed_rpm)) return 0;
  const double mdeg_per_s = speed_rpm * 360.0 * 1000.0 / 60.0;  // internal unit 0.001 deg
  double per_base = 0;
  switch (v_time_base) {
    case 0: per_base = mdeg_per_s * 60.0; break;   // per minute
    case 1: per_base = mdeg_per_s; break;          // per second
    case 2:                                        // per interpolation cycle
      if (!(cycle_s > 0) || !std::isfinite(cycle_s)) return 0;
      per_base = mdeg_per_s * cycle_s;
      break;
    default: return 0;
  }
  return per_base * static_cast<double>(v_reso_num) / static_cast<double>(v_reso_denom);
}

}  // namespace nck::spindle
