#pragma once
// The events of a channel's program: a block starts, a programmed stop, a
// warning or an error, the program state changes, the program ends. Each
// payload's JSON writer is beside it (docs/outputs.md lists the fields).
#include <cstdint>
#include <optional>
#include <string_view>

#include "nck/core/diagnostic.hpp"
#include "nck/core/event_head.hpp"
#include "nck/kernel/program_state.hpp"

namespace nck::kernel {

// hold: the run ended while a channel held and nothing could release it (nck run)
// stop_at: the run ended at its stop-at mark (nck run --stop-at)
// max_trace, max_events: the Python trace's / events' memory limit
enum class EndReason : std::uint8_t { m30, m2, error, reset, max_time, max_wall, interrupted, hold, stop_at,
                                      max_trace, max_events };

constexpr const char* end_name(EndReason r) noexcept {
  switch (r) {
    case EndReason::m30: return "M30";
    case EndReason::m2: return "M2";
    case EndReason::error: return "error";
    case EndReason::reset: return "reset";
    case EndReason::max_time: return "max_time";
    case EndReason::max_wall: return "max_wall";
    case EndReason::interrupted: return "interrupted";
    case EndReason::hold: return "hold";
    case EndReason::stop_at: return "stop_at";
    case EndReason::max_trace: return "max_trace";
    case EndReason::max_events: return "max_events";
  }
  return "error";
}

// A Kernel::message() index that names no message (the ID's table text).
inline constexpr std::uint32_t kNoMessage = 0xFFFFFFFFu;

namespace ev {

// A block starts executing (the event's head names it).
struct Block {
  std::optional<std::uint32_t> frame_index;  // PlanStore::frames index of its program -> machine map
};

// M0 / M1: the program stops at the block.
struct Stop {};

// A warning or an error at the block (or of the machine, channel 0).
struct Diagnosis {
  ErrorId id{};
  std::optional<std::uint32_t> message;  // Kernel::message() index; none: the ID's table text
  std::optional<std::int8_t> spindle;    // the spindle (kernel index) it concerns
  std::optional<std::int8_t> axis{};     // the drive (machine axis list index) it concerns
};
struct Warning : Diagnosis {};
struct Error : Diagnosis {};

// The channel's program ends.
struct End {
  EndReason reason = EndReason::m30;
};

// The channel's program state changed.
struct State {
  ProgramState from = ProgramState::idle, to = ProgramState::idle;
  StateReason reason = StateReason::start;
};

template <class Json, class Names>
void write_block_ref(Json& j, const EventHead& h, const Names& names) {
  j["line"] = h.at.line;
  j["n"] = h.at.n ? Json(*h.at.n) : Json(nullptr);
  j["file"] = names.file(h.channel_index(), h.at.file_id);
}

template <class Json, class Names>
void write_json(Json& j, const Block&, const EventHead& h, const Names& names) {
  write_block_ref(j, h, names);
}

template <class Json, class Names>
void write_json(Json& j, const Stop&, const EventHead& h, const Names& names) {
  write_block_ref(j, h, names);
}

template <class Json, class Names>
void write_json(Json& j, const Diagnosis& e, const EventHead& h, const Names& names) {
  j["id"] = number(e.id);
  j["line"] = h.at.line;
  j["file"] = names.file(h.channel_index(), h.at.file_id);
  j["msg"] = names.text(e.id, e.message);
  if (e.spindle) j["spindle"] = names.spindle(e.spindle);
}

template <class Json, class Names>
void write_json(Json& j, const End& e, const EventHead&, const Names&) {
  j["reason"] = end_name(e.reason);
}

template <class Json, class Names>
void write_json(Json& j, const State& e, const EventHead& h, const Names& names) {
  j["from"] = state_name(e.from);
  j["to"] = state_name(e.to);
  j["reason"] = state_reason_name(e.reason);
  write_block_ref(j, h, names);
}

}  // namespace ev
}  // namespace nck::kernel
