#pragma once
// What a block asks of a spindle, planned (setup side) into plain data the
// channel executes in the cycle: the spindle command itself, whether it is
// output to the PLC, and when the channel synchronises with it.
#include <cstdint>
#include <optional>

#include "nck/config/machine.hpp"
#include "nck/plc/hli.hpp"
#include "nck/spindle/positioning.hpp"

namespace nck::kernel {

enum class SpindleOp : std::uint8_t {
  rotate,            // M3 / M4 / S while rotating: rpm signed (+ M3, - M4)
  speed,             // S alone, rpm unsigned: the channel decides when it executes it
                     // (speed_change_rpm): a spindle in endless rotation takes the new
                     // speed in its direction, any other only stores it
  stop,              // M5
  position,          // M19: pos_deg, direction, rpm
  home,              // G74 (the channel never waits for it)
  gear_change,       // M40..M45 or automatic: stage (approach, PLC shift, new data)
  load_gear_data,    // G112: stage
  accel_weight,      // G130: value = percent
  feedforward_on,    // G135
  feedforward_off,   // G137
  feedforward_weight,  // G136: value = percent
  suppress_override,   // G167 alone
  tool_dynamics,     // D / #TOOL DATA with wz[i].log_ax_nr_spdl: value fields below
  get_dynamic_data,  // GET_DYNAMIC_DATA
  default_dynamic_data,  // DEFAULT_DYNAMIC_DATA
  user_function,     // M=.. / H=.. in spindle syntax: output only
};

// When the function is output and when the channel waits for it (FCT-S1 2.5).
enum class SyncPoint : std::uint8_t {
  none,          // MOS: output, no wait
  before,        // MVS_SVS: output before the motion, wait before it
  before_after,  // MVS_SNS: output before, wait after the motion
  after,         // MNS_SNS / MNE_SNS: output after the motion, wait after it
  late_motion,   // MVS_SLM: output now, wait at the next transition to G1/G2/G3
  late_explicit, // MVS_SLP: output now, wait at #EXPL SYN
};

// The sync point of configured synchronisation bits (FCT-S1 §2.5);
// nullopt = NO_SYNCH (no output; a spindle M function is then not executed).
constexpr std::optional<SyncPoint> sync_point(std::uint32_t bits) noexcept {
  namespace s = config::sync;
  // PLC_INFO is additive; what is left is the synchronisation type proper.
  const std::uint32_t type = bits & ~s::PLC_INFO;
  if (type & (s::MVS_SVS | s::MEP_SVS | s::MET_SVS)) return SyncPoint::before;
  if (type & s::MVS_SNS) return SyncPoint::before_after;
  if (type & (s::MNS_SNS | s::MNE_SNS)) return SyncPoint::after;
  if (type & s::MVS_SLM) return SyncPoint::late_motion;
  if (type & s::MVS_SLP) return SyncPoint::late_explicit;
  // MOS and its variants (MOS_TS, MEP_MOS, MET_MOS) output without waiting;
  // so does any other bit we do not model, rather than dropping the function.
  if (type != s::NO_SYNCH) return SyncPoint::none;
  return std::nullopt;
}

// What the wait is for: the spindle's own acknowledgement.
enum class SpindleWait : std::uint8_t { none, speed_reached, standstill, in_position, gear_change };

struct SpindleAction {
  std::int8_t spindle = -1;        // kernel spindle index
  SpindleOp op = SpindleOp::rotate;
  double rpm = 0;                  // signed for rotate
  double pos_deg = 0;
  spindle::Direction direction = spindle::Direction::none;
  bool g167 = false;               // override ignored for this speed
  std::uint32_t stage = 0;         // gear_change / load_gear_data
  double value = 0;                // percent (G130/G136)
  double tool_vb_min_rpm = 0, tool_vb_max_rpm = 0, tool_a_max_deg_s2 = 0;
  // synchronisation
  std::uint32_t sync_bits = 0;     // as configured (for events)
  SyncPoint sync = SyncPoint::none;
  bool output = false;             // output to the PLC (PLC_INFO or PLC spindle)
  SpindleWait wait = SpindleWait::none;  // internal acknowledgement waited for
  double ack_timeout_s = 0;        // *_prozess_zeit, 0 = none
  // for plc_out / plc_ack / wait events: "M3", "S", "M41", "M<n>", "H<n>"
  plc::TechKind fn = plc::TechKind::m;  // m, s or h
  std::int32_t fn_number = 0;
};

}  // namespace nck::kernel
