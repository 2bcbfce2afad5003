// The main spindle as C axis (#CAX, FCT-S1 §2.8.8): a channel whose main spindle
// may become a C axis (axis_mode 0x0204) has it as one more path axis from
// the start, so every layer (decoder words, planner, trace columns, final
// state) knows it; the planner and the channel let it move only in C-axis
// mode. The program addresses it by the name #CAX gives it, else by
// default_ax_name_of_spindle; the trace and the final state name it by the
// latter, or C (C1, C2 ... when C is taken) when the channel names none.
#include <algorithm>

#include <fmt/format.h>

#include "build.hpp"

namespace nck::config::detail {

// As the decoder reads it: main_spindle_ax_nr, else the first spindle.
const ChannelSpindle* main_spindle(const ChannelConfig& c) {
  for (const ChannelSpindle& s : c.spindles)
    if (c.main_spindle_ax_nr != 0 && s.log_axis_nr == c.main_spindle_ax_nr) return &s;
  return c.spindles.empty() ? nullptr : &c.spindles.front();
}

namespace {

bool axis_name_taken(const ChannelConfig& c, const std::string& name) {
  return std::any_of(c.axes.begin(), c.axes.end(), [&](const ChannelAxis& a) { return a.name == name; });
}

// The C axis's name in the trace and the final state.
std::string display_name(const ChannelConfig& c) {
  if (!c.default_ax_name_of_spindle.empty()) return c.default_ax_name_of_spindle;
  std::string name = "C";
  for (int k = 1; axis_name_taken(c, name); ++k) name = fmt::format("C{}", k);
  return name;
}

}  // namespace

void add_c_axes(Machine& m) {
  for (ChannelConfig& c : m.channels) {
    c.c_axis = -1;
    if (c.axes.size() >= kMaxAxes) continue;
    const ChannelSpindle* s = main_spindle(c);
    if (!s || s->axis_index < 0 || static_cast<std::size_t>(s->axis_index) >= m.axes.size() ||
        !m.axes[static_cast<std::size_t>(s->axis_index)].c_axis_capable())
      continue;
    c.c_axis = static_cast<int>(c.axes.size());
    c.axes.push_back(ChannelAxis{display_name(c), s->log_axis_nr, s->axis_index});
  }
}

}  // namespace nck::config::detail
