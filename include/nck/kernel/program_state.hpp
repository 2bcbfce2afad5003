#pragma once
// A channel's program state as the operator sees it (docs/operating.md): every
// change is a `state` event with the state left, the state entered and why.
#include <cstdint>
#include <string_view>

namespace nck::kernel {

enum class ProgramState : std::uint8_t {
  idle,       // no program started (or reset)
  running,    // the program runs (moving, dwelling or waiting for a synchronisation)
  hold,       // waits for cycle start: M0, M1 with the optional-stop switch, single step, a stop-at mark
  searching,  // block search: decoding without motion up to the restart mark
  returning,  // back to the contour after a block search
  error,      // aborted by an error; a reset leaves it
  ended,      // program end (M30 / M2) or a limit of the run
};

enum class StateReason : std::uint8_t {
  start,        // the channel took its first block
  m0,           // programmed stop
  m1,           // optional stop (the switch is on)
  cycle_start,  // the hold was released
  m30,
  m2,
  error,
  reset,
  max_time,
  max_wall,
  interrupted,
  hold,  // the run ended in a hold nothing could release (nck run)
  single_step,  // single step: the block ended
  stop_at,      // the stop-at mark's block ended
  block_search,  // a block search began, returned to the contour, or ended its return
  mdi,           // MDI text began or was done
  stop,          // NC stop: the operator stopped the program
  max_trace,     // the Python module's trace reached its memory limit (max_trace_mb)
  max_events,    // the Python module's events reached their memory limit (max_events_mb)
};

constexpr std::string_view state_name(ProgramState s) noexcept {
  switch (s) {
    case ProgramState::idle: return "idle";
    case ProgramState::running: return "running";
    case ProgramState::hold: return "hold";
    case ProgramState::searching: return "searching";
    case ProgramState::returning: return "returning";
    case ProgramState::error: return "error";
    case ProgramState::ended: return "ended";
  }
  return "idle";
}

constexpr std::string_view state_reason_name(StateReason r) noexcept {
  switch (r) {
    case StateReason::start: return "start";
    case StateReason::m0: return "M0";
    case StateReason::m1: return "M1";
    case StateReason::cycle_start: return "cycle_start";
    case StateReason::m30: return "M30";
    case StateReason::m2: return "M2";
    case StateReason::error: return "error";
    case StateReason::reset: return "reset";
    case StateReason::max_time: return "max_time";
    case StateReason::max_wall: return "max_wall";
    case StateReason::interrupted: return "interrupted";
    case StateReason::hold: return "hold";
    case StateReason::single_step: return "single_step";
    case StateReason::stop_at: return "stop_at";
    case StateReason::block_search: return "block_search";
    case StateReason::mdi: return "mdi";
    case StateReason::stop: return "stop";
    case StateReason::max_trace: return "max_trace";
    case StateReason::max_events: return "max_events";
  }
  return "start";
}

}  // namespace nck::kernel
