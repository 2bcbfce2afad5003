// See spindle_limit_check.hpp. The rules mirror SpindleAxis::rotate and
// the spindle unit: a rotation (M3/M4, or S while rotating) is checked, an
// S on a standing spindle only stores the speed (its M3 is checked).
#include "spindle_limit_check.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "nck/config/drive_feedback.hpp"

namespace nck::prep {

SpindleLimitCheck::SpindleLimitCheck(const config::Machine& m, std::size_t ch,
                                     const std::vector<std::int8_t>& kernel_spindles) {
  const config::ChannelConfig& channel = m.channels[ch];
  for (std::size_t i = 0; i < channel.spindles.size() && i < kernel_spindles.size(); ++i) {
    Tracked t;
    t.kernel = kernel_spindles[i];
    t.channel = &channel.spindles[i];
    const int ax = channel.spindles[i].axis_index;
    if (ax >= 0 && static_cast<std::size_t>(ax) < m.axes.size() && !channel.spindles[i].plc_control) {
      t.axis = &m.axes[static_cast<std::size_t>(ax)];
      t.stage = t.axis->initial_gear_stage;
    }
    spindles_.push_back(t);
  }
}

SpindleLimitCheck::Tracked* SpindleLimitCheck::find(std::int8_t kernel) {
  for (Tracked& t : spindles_)
    if (t.kernel == kernel) return &t;
  return nullptr;
}

void SpindleLimitCheck::check(const PlannedCommand& c, std::vector<Diagnostic>& out) {
  using kernel::SpindleOp;
  for (const kernel::Attachment& attached : c.attachments) {
    const auto* action = std::get_if<kernel::SpindleAction>(&attached);
    if (!action) continue;
    const kernel::SpindleAction& a = *action;
    Tracked* s = find(a.spindle);
    if (!s) continue;
    switch (a.op) {
      case SpindleOp::gear_change:
      case SpindleOp::load_gear_data: s->stage = a.stage; break;
      case SpindleOp::tool_dynamics: s->pending_tool_max_rpm = a.tool_vb_max_rpm; break;
      case SpindleOp::get_dynamic_data:  // GET_DYNAMIC_DATA: the tool's limits at once
        if (s->pending_tool_max_rpm) s->tool_max_rpm = *std::exchange(s->pending_tool_max_rpm, {});
        break;
      case SpindleOp::default_dynamic_data:  // DEFAULT_DYNAMIC_DATA: no tool limits
        s->tool_max_rpm = 0;
        s->pending_tool_max_rpm.reset();
        break;
      case SpindleOp::rotate:
        // Tool limits take effect on the way from standstill into motion (FCT-S1 2.8.5).
        if (!s->rotating && s->pending_tool_max_rpm) s->tool_max_rpm = *std::exchange(s->pending_tool_max_rpm, {});
        s->rotating = a.rpm != 0;
        if (auto d = speed_check(*s, a.rpm, c.head.line)) out.push_back(*d);
        break;
      case SpindleOp::speed:
        if (s->rotating)
          if (auto d = speed_check(*s, a.rpm, c.head.line)) out.push_back(*d);
        break;
      case SpindleOp::stop: s->rotating = false; break;
      case SpindleOp::position:  // M19, S.POS, G331's start
      case SpindleOp::home:      // G74
        s->rotating = false;
        if (auto d = position_check(*s, a.op, c.head.line)) out.push_back(*d);
        break;
      default: break;
    }
  }
}

// SpindleAxis::position / home refuse a spindle that does not know its position.
std::optional<Diagnostic> SpindleLimitCheck::position_check(const Tracked& s, kernel::SpindleOp op,
                                                            std::uint32_t line) const {
  if (!s.axis || config::knows_position(*s.axis)) return std::nullopt;
  return make_diagnostic(ErrorId::SpindleSensorlessPositioning, {"", line, 0},
                         fmt::format("{} cannot {}: it is speed-controlled without position feedback", s.channel->name,
                                     op == kernel::SpindleOp::home ? "home (G74)" : "position (M19)"));
}

std::optional<Diagnostic> SpindleLimitCheck::speed_check(const Tracked& s, double rpm, std::uint32_t line) const {
  if (!s.axis) return std::nullopt;
  // In deg/s, as the spindle compares (SpindleAxis::max_speed_deg_s).
  const double gear_deg_s = s.axis->gear(s.stage).max_speed_mm_s;
  double max_deg_s = gear_deg_s > 0 ? gear_deg_s : 1e12;
  const bool tool = s.tool_max_rpm > 0 && s.tool_max_rpm * 6.0 < max_deg_s;
  if (tool) max_deg_s = s.tool_max_rpm * 6.0;
  if (!(std::fabs(rpm * 6.0) > max_deg_s)) return std::nullopt;
  const double max_rpm = max_deg_s / 6.0;
  return make_diagnostic(
      ErrorId::SpindleSpeedLimited, {"", line, 0},
      fmt::format("{} {:g} rpm is above the maximum of {:g} rpm ({}); it turns at {:g} rpm", s.channel->name,
                  std::fabs(rpm), max_rpm, tool ? "the active tool's wz[i].vb_max" : fmt::format("gear stage {}", s.stage),
                  max_rpm));
}

}  // namespace nck::prep
