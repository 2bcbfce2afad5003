#pragma once
// The events of a machine spindle: it changes mode or commanded speed, it
// reaches its speed, a gear change is done. The spindle is the kernel's
// index (Kernel::spindle_name). Each payload's JSON writer is beside it
// (docs/outputs.md lists the fields).
#include <cstdint>

#include "nck/core/event_head.hpp"
#include "nck/core/shown_number.hpp"
#include "nck/spindle/spindle_status.hpp"

namespace nck::spindle {

struct ModeEvent {
  std::int8_t spindle = 0;
  SpindleMode mode = SpindleMode::stop;
  double cmd_rpm = 0;  // the speed it runs towards, signed
  std::uint32_t gear = 1;
};

struct SpeedReachedEvent {
  std::int8_t spindle = 0;
  double act_rpm = 0;
};

// The gear change to `stage` (by M`m`) is done.
struct GearEvent {
  std::int8_t spindle = 0;
  std::uint32_t stage = 1;
  std::int32_t m = 0;
};

template <class Json, class Names>
void write_json(Json& j, const ModeEvent& e, const EventHead&, const Names& names) {
  j["spindle"] = names.spindle(e.spindle);
  j["mode"] = mode_name(e.mode);
  j["rpm"] = written(e.cmd_rpm);
  j["gear"] = e.gear;
}

template <class Json, class Names>
void write_json(Json& j, const SpeedReachedEvent& e, const EventHead&, const Names& names) {
  j["spindle"] = names.spindle(e.spindle);
  j["rpm"] = written(e.act_rpm);
}

template <class Json, class Names>
void write_json(Json& j, const GearEvent& e, const EventHead&, const Names& names) {
  j["spindle"] = names.spindle(e.spindle);
  j["stage"] = e.stage;
  j["fn"] = "M" + std::to_string(e.m);
}

}  // namespace nck::spindle
