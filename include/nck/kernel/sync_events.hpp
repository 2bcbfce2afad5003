#pragma once
// The events of the PLC handshake (SyncUnit, the spindles' gear changes and
// the PLC's external spindle commands): a function output to the PLC, its
// acknowledgement, and the channel's waits. Each payload's JSON writer is
// beside it (docs/outputs.md lists the fields).
#include <climits>
#include <cstdint>
#include <optional>
#include <string_view>

#include "nck/core/event_head.hpp"
#include "nck/core/shown_number.hpp"
#include "nck/plc/function_text.hpp"
#include "nck/plc/hli.hpp"

namespace nck::kernel {

enum class WaitReason : std::uint8_t {
  plc_ack, speed_reached, in_position, standstill, homing, gear_change, expl_syn, dwell, feedhold,
  coupling,  // a spindle coupling holds the path (G95/G33/G63 with the spindle at rest); time by cause only
  zero_mark,  // G33 waits for the spindle's zero mark (+ OFFSET) before it cuts
  drive_enable  // CiA 402 drives power up to operation enabled before the program moves
};

constexpr const char* wait_reason_name(WaitReason r) noexcept {
  switch (r) {
    case WaitReason::plc_ack: return "plc_ack";
    case WaitReason::speed_reached: return "speed_reached";
    case WaitReason::in_position: return "in_position";
    case WaitReason::standstill: return "standstill";
    case WaitReason::homing: return "homing";
    case WaitReason::gear_change: return "gear_change";
    case WaitReason::expl_syn: return "expl_syn";
    case WaitReason::dwell: return "dwell";
    case WaitReason::feedhold: return "feedhold";
    case WaitReason::coupling: return "coupling";
    case WaitReason::zero_mark: return "zero_mark";
    case WaitReason::drive_enable: return "drive_enable";
  }
  return "plc_ack";
}

namespace ev {

// A kernel spindle index, or none for a negative one. rt
constexpr std::optional<std::int8_t> spindle_or_none(std::int8_t s) noexcept {
  return s >= 0 ? std::optional<std::int8_t>(s) : std::nullopt;
}

// A function output to the PLC (M, H, T, S).
// No additional value (an int32 the decoder never yields: |value| < 2^31;
// a sentinel, not std::optional, keeps the event at its size).
inline constexpr std::int32_t kNoAddValue = INT32_MIN;

struct PlcOut {
  plc::TechKind fn = plc::TechKind::m;
  std::int32_t number = 0;             // M3 -> 3; S: 0
  std::optional<std::int8_t> spindle;  // kernel spindle index
  double s_rpm = 0;                    // S: the programmed speed
  std::uint32_t sync = 0;              // synchronisation bits (config::sync)
  std::int32_t add_value = kNoAddValue;  // M/H: the additional value (M52=-345)
};

// The PLC acknowledged a function.
struct PlcAck {
  plc::TechKind fn = plc::TechKind::m;
  std::int32_t number = 0;
  std::optional<std::int8_t> spindle;
};

// The channel starts waiting (for the function of `fn`/`number`, or for spindle `spindle`).
struct Wait {
  WaitReason reason = WaitReason::plc_ack;
  std::optional<std::int8_t> spindle;
  plc::TechKind fn = plc::TechKind::none;
  std::int32_t number = 0;
};

// ... and stops waiting (the same fields as the wait it ends).
struct WaitEnd : Wait {};

template <class Json, class Names>
void write_json(Json& j, const PlcOut& e, const EventHead&, const Names& names) {
  j["fn"] = plc::function_name(e.fn, e.number);
  j["spindle"] = names.spindle(e.spindle);
  j["value"] = e.fn == plc::TechKind::s ? Json(written(e.s_rpm)) : e.add_value != kNoAddValue ? Json(e.add_value) : Json(nullptr);
  j["sync"] = plc::sync_name(e.sync);
}

template <class Json, class Names>
void write_json(Json& j, const PlcAck& e, const EventHead&, const Names& names) {
  j["fn"] = plc::function_name(e.fn, e.number);
  j["spindle"] = names.spindle(e.spindle);
  j["value"] = e.fn == plc::TechKind::s ? Json(0.0) : Json(nullptr);  // an acknowledgement carries no speed
}

template <class Json, class Names>
void write_json(Json& j, const Wait& e, const EventHead& h, const Names& names) {
  j["reason"] = wait_reason_name(e.reason);
  j["spindle"] = names.spindle(e.spindle);
  j["fn"] = plc::function_name(e.fn, e.number);
  j["line"] = h.at.line;
}

}  // namespace ev
}  // namespace nck::kernel
