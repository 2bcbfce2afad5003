#pragma once
// Events the kernel emits in the cyclic path: plain data, no strings, so
// producing one never allocates. The application turns them into JSON lines
// (the events file, docs/outputs.md), looking texts up by id.
#include <cstdint>

#include "nck/core/diagnostic.hpp"
#include "nck/distctrl/controller.hpp"
#include "nck/kernel/ax_link.hpp"
#include "nck/kernel/program_state.hpp"
#include "nck/nc/modal.hpp"
#include "nck/plc/hli.hpp"
#include "nck/spindle/spindle_status.hpp"

namespace nck::kernel {

enum class EventKind : std::uint8_t {
  block,      // a block starts executing
  plc_out,    // a function is output to the PLC
  plc_ack,    // the PLC acknowledged it
  wait,       // the channel starts waiting
  wait_end,   // ... and stops waiting
  spindle,    // a spindle changes mode
  speed_reached,
  gear,
  link,
  offset,
  stop,       // M0 / M1 programmed stop
  warning,
  error,
  end,        // program end of a channel
  dist_ctrl,  // 3D distance control changed state (dist_state)
  trc,        // tool radius compensation selected, deselected or its D changed (trc_*)
  state,      // the channel's program state changed (state_from / state_to / state_reason)
};

inline constexpr std::uint32_t kNoMessage = 0xFFFFFFFFu;

// hold: the run ended while a channel held and nothing could release it (nck run)
// stop_at: the run ended at its stop-at mark (nck run --stop-at)
enum class EndReason : std::uint8_t { m30, m2, error, reset, max_time, max_wall, interrupted, hold, stop_at,
                                      max_trace };  // max_trace: the Python trace's memory limit


enum class WaitReason : std::uint8_t {
  plc_ack, speed_reached, in_position, standstill, homing, gear_change, expl_syn, dwell, feedhold,
  coupling  // a spindle coupling holds the path (G95/G33/G63 with the spindle at rest); time by cause only
};

struct Event {
  double t_s = 0;             // cycle start
  std::uint8_t channel = 0;   // 1-based, 0 = not channel-specific
  EventKind kind = EventKind::block;
  // block / warning / error
  std::uint16_t file_id = 0;
  std::uint32_t line = 0;
  bool has_n = false;
  std::int64_t n = 0;
  // warning / error
  ErrorId id{};
  std::uint32_t message_index = 0;  // Kernel::message(), text prepared outside the cycle
                                    // (kNoMessage: the ID's table text); block: the
                                    // PlanStore::frames index of its map (kNoMessage: none)
  // plc_out / plc_ack / wait
  plc::TechKind fn = plc::TechKind::none;
  std::int32_t fn_number = 0;       // M3, T5 ...
  double value = 0;                 // S: rpm
  std::uint32_t sync = 0;           // synchronisation type bits
  std::int8_t spindle = -1;         // kernel spindle index (Kernel::spindle_name), -1 = none
  WaitReason wait_reason = WaitReason::plc_ack;
  // spindle / gear
  spindle::SpindleMode spindle_mode = spindle::SpindleMode::stop;
  std::uint32_t gear = 0;           // gear stage 1..6
  // end
  EndReason end_reason = EndReason::m30;
  // link: group, on/off, why (ax_link.hpp LinkReason); the pairs' names are
  // in the plan store at message_index
  std::int8_t link_group = -1;
  bool link_on = false;
  LinkReason link_reason = LinkReason::program;
  // dist_ctrl
  distctrl::State dist_state = distctrl::State::inactive;
  // trc: the mode, the D in force and its tool radius
  nc::RadiusComp trc_mode = nc::RadiusComp::g40;
  std::int32_t trc_d = 0;
  double trc_radius_mm = 0;
  // state: the program state left and entered, and why
  ProgramState state_from = ProgramState::idle, state_to = ProgramState::idle;
  StateReason state_reason = StateReason::start;
};

}  // namespace nck::kernel
