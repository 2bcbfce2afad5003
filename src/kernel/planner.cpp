#include "planner.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace nck::kernel {
namespace {

constexpr double kInchMm = 25.4;

bool is_fixed_m(int m) {
  switch (m) {
    case 0: case 1: case 2: case 17: case 29: case 30:
      return true;
    default:
      return false;
  }
}

// The spindle M functions belong to the spindle work (issue 3).
bool is_spindle_m(int m) { return m == 3 || m == 4 || m == 5 || m == 19 || (m >= 40 && m <= 45); }

}  // namespace

Planner::Planner(const config::Machine& machine, std::size_t channel_index,
                 std::vector<std::string>& messages)
    : machine_(machine), channel_(machine.channels[channel_index]), messages_(messages) {
  n_axes_ = std::min(channel_.axes.size(), config::kMaxPathAxes);
  for (std::size_t j = 0; j < n_axes_; ++j) {
    const int idx = channel_.axes[j].axis_index;
    config::AxisConfig fallback;
    const config::AxisConfig& ax = idx >= 0 ? machine.axes[static_cast<std::size_t>(idx)] : fallback;
    const config::GearStage& g = ax.gear(ax.initial_gear_stage);
    // Feed moves: a_beschl up, a_brems down; rapid: a_grenz; all capped by a_max.
    feed_dyn_[j] = {g.vb_max, std::min(g.a_beschl, g.a_max), std::min(g.a_brems, g.a_max)};
    const double a_rapid = std::min(g.a_grenz, g.a_max);
    rapid_dyn_[j] = {std::min(g.vb_eilgang, g.vb_max), a_rapid, a_rapid};
    swe_neg_[j] = ax.swe_neg;
    swe_pos_[j] = ax.swe_pos;
  }
}

Command Planner::error_command(ErrorId id, std::string message, std::uint16_t file_id,
                               std::uint32_t line) {
  Command c;
  c.kind = CommandKind::error;
  c.error_id = id;
  c.file_id = file_id;
  c.line = line;
  c.emit_block_event = false;
  c.message_index = static_cast<std::uint32_t>(messages_.size());
  messages_.push_back(std::move(message));
  return c;
}

int Planner::axis_named(const char* name) const {
  for (std::size_t j = 0; j < n_axes_; ++j)
    if (channel_.axes[j].name == name) return static_cast<int>(j);
  return -1;
}

// Names what the block asks for that this version does not execute yet, or "".
std::string Planner::unsupported(const nc::Block& b) const {
  if (b.hash) return fmt::format("{} is not executed yet", nc::hash_command_name(*b.hash));
  if (!b.spindles.empty())
    return fmt::format("spindle function of {} is not executed yet", b.spindles.front().name);
  for (int m : b.m)
    if (is_spindle_m(m)) return fmt::format("M{} is not executed yet", m);
  for (int g : b.g_nonmodal)
    if (g != 4) return fmt::format("G{} is not executed yet", g);
  if (b.d && *b.d != 0) return fmt::format("tool offset D{} is not applied yet", *b.d);
  if (!b.kernel_writes.empty())
    return fmt::format("writing {} is not executed yet", b.kernel_writes.front().name);
  if (b.dwell_revs) return "a dwell in spindle revolutions (G4 S..) is not executed yet";
  const nc::ModalState& m = b.modal;
  using nc::Motion;
  if (m.motion != Motion::rapid && m.motion != Motion::linear && m.motion != Motion::cw &&
      m.motion != Motion::ccw)
    return "thread cutting and tapping (G33/G63/G331/G332) are not executed yet";
  if (m.feed_mode != nc::FeedMode::g94) return "feed modes G93/G95 are not executed yet";
  if (m.speed_mode != nc::SpeedMode::g97) return "constant cutting speed G96 is not executed yet";
  if (m.radius_comp != nc::RadiusComp::g40) return "tool radius compensation G41/G42 is not executed yet";
  if (m.diameter) return "diameter programming G51 is not executed yet";
  if (m.zero_offset != 0) return "zero offsets G54..G59/G159 are not applied yet";
  return {};
}

bool Planner::add_outputs(const nc::Block& b, Command& c) {
  for (int m : b.m) {
    if (is_fixed_m(m)) continue;
    const std::uint32_t sync = m >= 0 && static_cast<std::size_t>(m) < channel_.m_synch.size()
                                   ? channel_.m_synch[static_cast<std::size_t>(m)]
                                   : config::sync::MOS;
    // A channel M function with NO_SYNCH is not output (FCT-S1 2.5).
    if (sync == config::sync::NO_SYNCH) continue;
    if (!c.outputs.push_back({FunctionKind::m, m, sync})) return false;
  }
  for (int h : b.h)
    if (!c.outputs.push_back({FunctionKind::h, h, config::sync::MOS})) return false;
  if (b.t && !c.outputs.push_back({FunctionKind::t, static_cast<std::int32_t>(*b.t), config::sync::MOS}))
    return false;
  return true;
}

Command Planner::plan(const nc::Block& b, const std::string& file_name) {
  modal_ = b.modal;
  if (std::string why = unsupported(b); !why.empty())
    return error_command(ErrorId::KernelNotYetSupported, why + " in this version of nck",
                         b.file_id, b.line);
  Command c;
  c.file_id = b.file_id;
  c.line = b.line;
  c.has_n = b.n.has_value();
  c.n = b.n.value_or(0);
  if (!add_outputs(b, c))
    return error_command(ErrorId::KernelQueueOverflow, "more than 8 PLC outputs in one block",
                         b.file_id, b.line);
  if (b.program_end) {
    c.kind = CommandKind::end;
    c.end_reason = std::find(b.m.begin(), b.m.end(), 2) != b.m.end() ? EndReason::m2 : EndReason::m30;
    return c;
  }
  if (b.stop) {
    c.kind = CommandKind::stop;
    return c;
  }
  if (b.dwell_s) {
    c.kind = CommandKind::dwell;
    c.dwell_s = std::max(0.0, *b.dwell_s);
    return c;
  }
  if (b.has_axis_words() || b.modal.motion == nc::Motion::cw || b.modal.motion == nc::Motion::ccw)
    if (b.has_axis_words() || b.ijk[0] || b.ijk[1] || b.ijk[2])
      return plan_motion(b, c, file_name);
  c.kind = CommandKind::nop;
  return c;
}

}  // namespace nck::kernel
