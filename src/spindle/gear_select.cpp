#include "nck/spindle/gear_select.hpp"

#include <cmath>

namespace nck::spindle {
namespace {

bool range_used(const config::SpindleRange& r) { return r.max_speed_rpm > 0; }

bool valid_stage(const config::ChannelSpindle& sp, std::uint32_t stage) {
  return stage >= 1 && stage <= config::kMaxGearStages && range_used(sp.range_table[stage - 1]);
}

// Why no range covers the speed: above all, below all, or in a gap.
ErrorId no_range_reason(const config::ChannelSpindle& sp, double speed_rpm) {
  bool any = false, above_all = true, below_all = true;
  for (const auto& r : sp.range_table) {
    if (!range_used(r)) continue;
    any = true;
    if (speed_rpm <= r.max_speed_rpm) above_all = false;
    if (speed_rpm >= r.min_speed_rpm) below_all = false;
  }
  if (!any) return ErrorId::SpindleGearStageInvalid;
  if (above_all) return ErrorId::SpindleSpeedTooHigh;
  if (below_all) return ErrorId::SpindleSpeedTooLow;
  return ErrorId::SpindleSpeedNoRange;
}

}  // namespace

bool gear_covers(const config::ChannelSpindle& sp, std::uint32_t stage, double speed_rpm) noexcept {
  if (!valid_stage(sp, stage)) return false;
  const auto& r = sp.range_table[stage - 1];
  const double s = std::fabs(speed_rpm);
  return s >= r.min_speed_rpm && s <= r.max_speed_rpm;
}

std::expected<GearDecision, ErrorId> select_gear(const config::ChannelSpindle& sp,
                                                 std::uint32_t current_stage, double speed_rpm,
                                                 std::optional<std::uint32_t> programmed_stage) noexcept {
  if (!std::isfinite(speed_rpm)) return std::unexpected(ErrorId::SpindleBadValue);
  const double s = std::fabs(speed_rpm);
  if (programmed_stage) {
    const std::uint32_t st = *programmed_stage;
    if (!valid_stage(sp, st)) return std::unexpected(ErrorId::SpindleGearStageInvalid);
    if (s != 0 && !gear_covers(sp, st, s)) return std::unexpected(ErrorId::SpindleGearStageWrong);
    return GearDecision{st, st != current_stage};
  }
  // Minimise shifting: the current stage stays as long as it can run S.
  if (s == 0 || gear_covers(sp, current_stage, s)) return GearDecision{current_stage, false};
  if (!sp.autom_range) {
    if (no_range_reason(sp, s) == ErrorId::SpindleSpeedTooHigh)
      return std::unexpected(ErrorId::SpindleSpeedTooHigh);
    return std::unexpected(ErrorId::SpindleGearStageRequired);
  }
  for (std::uint8_t st : sp.range_way)
    if (gear_covers(sp, st, s)) return GearDecision{st, st != current_stage};
  return std::unexpected(no_range_reason(sp, s));
}

}  // namespace nck::spindle
