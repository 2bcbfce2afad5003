#include "nck/spindle/positioning.hpp"

#include <cmath>

namespace nck::spindle {

double detail::wrap_modulo_by_fmod(double pos_deg, double lo_deg, double hi_deg) noexcept {
  const double range = hi_deg - lo_deg;
  if (!(range > 0) || !std::isfinite(pos_deg) || !std::isfinite(range)) return lo_deg;
  double r = std::fmod(pos_deg - lo_deg, range);
  if (r < 0) r += range;
  if (r >= range) r = 0;  // fmod rounding at the upper edge
  return lo_deg + r;
}

Direction preferred_direction(const config::AxisConfig& ax) noexcept {
  if (!ax.has_preferred_direction) return Direction::none;
  return ax.preferred_direction_positive ? Direction::positive : Direction::negative;
}

std::expected<void, ErrorId> check_preferred_direction(const config::AxisConfig& ax, Direction dir) noexcept {
  if (!direction_allowed(preferred_direction(ax), dir))
    return std::unexpected(ErrorId::SpindlePreferredDirection);
  return {};
}

double m19_travel_deg(double current_deg, double target_deg, Direction programmed,
                      double current_speed_deg_s, double lo_deg, double hi_deg) noexcept {
  const double range = hi_deg - lo_deg;
  if (!(range > 0) || !std::isfinite(range)) return 0;
  const double from = wrap_modulo(current_deg, lo_deg, hi_deg);
  const double to = wrap_modulo(target_deg, lo_deg, hi_deg);
  const double ahead = wrap_modulo(to - from, 0, range);  // travel going positive, [0, range)
  Direction dir = programmed;
  if (dir == Direction::none && current_speed_deg_s != 0 && std::isfinite(current_speed_deg_s))
    dir = current_speed_deg_s > 0 ? Direction::positive : Direction::negative;
  if (dir == Direction::positive) return ahead;
  if (dir == Direction::negative) return ahead == 0 ? 0.0 : ahead - range;
  return ahead <= range / 2 ? ahead : ahead - range;
}

bool speed_reached(double act_rpm, double cmd_rpm, double tolerance_permille) noexcept {
  if (!std::isfinite(act_rpm) || !std::isfinite(cmd_rpm)) return false;
  const double band = tolerance_permille * std::fabs(cmd_rpm) / 1000.0;  // exact at the edges
  return std::fabs(act_rpm - cmd_rpm) <= band;
}

bool zero_speed(double act_deg_s, double vb_min_null_deg_s) noexcept {
  return std::isfinite(act_deg_s) && std::fabs(act_deg_s) < vb_min_null_deg_s;
}

}  // namespace nck::spindle
