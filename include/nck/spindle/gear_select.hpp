#pragma once
// Gear stage selection of the main spindle (FCT-S1 2.8.2): which of the six
// stages (M40..M45 = 1..6) runs a programmed speed. Pure function; speeds in
// rpm as in spindel[i].range_table.
#include <cstdint>
#include <expected>
#include <optional>

#include "nck/config/machine.hpp"
#include "nck/core/diagnostic.hpp"

namespace nck::spindle {

struct GearDecision {
  std::uint32_t stage = 1;  // 1..6
  bool change = false;      // true: output M(39+stage) to the PLC and shift
};

// True when range_table[stage-1] is in use and min <= |speed| <= max. // rt
bool gear_covers(const config::ChannelSpindle& sp, std::uint32_t stage, double speed_rpm) noexcept;

// Rules: a programmed stage (M40..M45 -> 1..6) must cover |S| (else
// SpindleGearStageWrong). Without one, the current stage is kept when it
// covers |S| (fewest changes); otherwise with autom_range the table is searched
// in range_way order and the first covering stage is taken (none:
// SpindleSpeedTooHigh / TooLow / NoRange); without autom_range that is
// SpindleGearStageRequired. S0 keeps the current stage. // rt
std::expected<GearDecision, ErrorId> select_gear(const config::ChannelSpindle& sp,
                                                 std::uint32_t current_stage, double speed_rpm,
                                                 std::optional<std::uint32_t> programmed_stage) noexcept;

}  // namespace nck::spindle
