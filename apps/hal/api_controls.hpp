#pragma once
// The operator's actions that came through nck-hal's API (POST
// /api/v1/command), merged in nck.cycle with what the channel's pins say,
// as a second operator's panel wired beside the first:
//   - a button (cycle start, reset, NC stop) is one press, beside the pin's
//     rising edge;
//   - a switch (feedhold, single step, optional stop) is on while the pin
//     or the API has it on;
//   - an override and the skip levels are the value changed last, by the
//     pin or by the API.
// Real-time safe: plain data, no allocation.
#include <cstdint>
#include <optional>

#include "nck/kernel/tick_io.hpp"
#include "nck/plc/hli.hpp"
#include "nck/sim/scenario_action.hpp"

namespace nck::hal {

// The value changed last, by the pin or by the API: the API's until the
// pin changes (the pin's first value is no change).
template <class T>
struct LastChanged {
  std::optional<T> api, pin_was;
  T operator()(T pin) noexcept {
    if (pin_was && pin != *pin_was) api.reset();
    pin_was = pin;
    return api ? *api : pin;
  }
};

struct ApiChannelControls {
  bool cycle_start = false, reset = false, stop = false;  // presses for the next cycle
  bool feedhold = false, single_step = false, optional_stop = false;
  LastChanged<double> feed_override_pct, rapid_override_pct;
  LastChanged<std::uint32_t> skip_mask;  // for preparation (nck-hal), not the kernel

  // Takes one action; kinds the API does not pass on are left.
  void take(const sim::ScenarioAction& a) noexcept {
    if (a.get<sim::act::CycleStart>()) cycle_start = true;
    if (a.get<sim::act::Reset>()) reset = true;
    if (a.get<sim::act::Stop>()) stop = true;
    if (const auto* f = a.get<sim::act::Feedhold>()) feedhold = f->on;
    if (const auto* s = a.get<sim::act::SingleStep>()) single_step = s->on;
    if (const auto* o = a.get<sim::act::OptionalStop>()) optional_stop = o->on;
    if (const auto* f = a.get<sim::act::FeedOverride>()) feed_override_pct.api = f->percent;
    if (const auto* r = a.get<sim::act::RapidOverride>()) rapid_override_pct.api = r->percent;
    if (const auto* m = a.get<sim::act::SkipMask>()) skip_mask.api = m->mask;
  }

  // `in` holds what the pins say; afterwards what the kernel is given. The presses are used up.
  void merge_into(kernel::ChannelInput& in) noexcept {
    in.cycle_start = in.cycle_start || cycle_start;
    in.reset = in.reset || reset;
    in.stop = in.stop || stop;
    cycle_start = reset = stop = false;
    in.feedhold = in.feedhold || feedhold;
    in.single_step = in.single_step || single_step;
    in.optional_stop = in.optional_stop || optional_stop;
    in.feed_override_pct = feed_override_pct(in.feed_override_pct);
    in.rapid_override_pct = rapid_override_pct(in.rapid_override_pct);
  }
};

// A spindle's controls from the API (spindle_override, spindle_feedhold),
// beside its pins the same way.
struct ApiSpindleControls {
  LastChanged<double> override_pct;
  bool feedhold = false;

  void take(const sim::ScenarioAction& a) noexcept {
    if (const auto* o = a.get<sim::act::SpindleOverride>()) override_pct.api = o->percent;
    if (const auto* f = a.get<sim::act::SpindleFeedhold>()) feedhold = f->on;
  }
  // `in` holds what the pins say; afterwards what the kernel is given.
  void merge_into(plc::SpindleControl& in) noexcept {
    in.override_percent = override_pct(in.override_percent);
    in.override_valid = true;
    in.feedhold = in.feedhold || feedhold;
  }
};

// The operator's controls as the state document shows them (its `hli`).
inline plc::ChannelControl shown_controls(const kernel::ChannelInput& in, std::uint32_t skip_mask) noexcept {
  plc::ChannelControl c;
  c.feed_override_percent = in.feed_override_pct;
  c.rapid_override_percent = in.rapid_override_pct;
  c.feedhold = in.feedhold;
  c.single_step = in.single_step;
  c.optional_stop = in.optional_stop;
  c.manual_mode = in.manual_mode;
  c.skip_mask = skip_mask;
  return c;
}

}  // namespace nck::hal
