// Planning of G0/G1/G2/G3 blocks: target resolution, segment, limits.
#include <cmath>
#include <fmt/format.h>
#include <limits>

#include "planner.hpp"

namespace nck::kernel {
namespace {

constexpr double kInchMm = 25.4;

// Plane axis names per G17/G18/G19 (first, second) and the I/J/K index of each.
struct PlaneAxes {
  const char* first;
  const char* second;
  int first_ijk;
  int second_ijk;
};

PlaneAxes plane_axes(nc::Plane p) {
  switch (p) {
    case nc::Plane::g18: return {"Z", "X", 2, 0};
    case nc::Plane::g19: return {"Y", "Z", 1, 2};
    case nc::Plane::g17: default: return {"X", "Y", 0, 1};
  }
}

ErrorId arc_error_id(motion::ArcError e) {
  switch (e) {
    case motion::ArcError::radius_too_small: return ErrorId::KernelArcRadiusTooSmall;
    case motion::ArcError::full_circle_with_radius: return ErrorId::KernelArcFullCircleWithR;
    default: return ErrorId::KernelArcEndNotOnCircle;
  }
}

}  // namespace

Command Planner::plan_motion(const nc::Block& b, Command c, const std::string& file_name) {
  const double unit = b.modal.inch ? kInchMm : 1.0;
  motion::AxisVector start{}, target{};
  for (std::size_t j = 0; j < n_axes_; ++j) {
    start[j] = pos_[j];
    target[j] = pos_[j];
    if (!b.axes[j]) continue;
    const double v = *b.axes[j] * unit;
    target[j] = b.modal.absolute ? v : pos_[j] + v;
    if (target[j] < swe_neg_[j] - 1e-9 || target[j] > swe_pos_[j] + 1e-9)
      return error_command(
          ErrorId::KernelSoftwareLimit,
          fmt::format("{} {:.4f} is outside the software limits [{:.4f}, {:.4f}] ({}:{})",
                      channel_.axes[j].name, target[j], swe_neg_[j], swe_pos_[j], file_name, b.line),
          b.file_id, b.line);
  }

  const bool rapid = b.modal.motion == nc::Motion::rapid;
  const bool arc = b.modal.motion == nc::Motion::cw || b.modal.motion == nc::Motion::ccw;
  std::expected<motion::Segment, motion::ArcError> seg;
  if (arc) {
    const PlaneAxes pa = plane_axes(b.modal.plane);
    const int a = axis_named(pa.first), bb = axis_named(pa.second);
    if (a < 0 || bb < 0)
      return error_command(ErrorId::KernelAxisNotInPlane,
                           fmt::format("G{} needs axes {} and {}", static_cast<int>(b.modal.plane),
                                       pa.first, pa.second),
                           b.file_id, b.line);
    const bool ccw = b.modal.motion == nc::Motion::ccw;
    const auto& ci = b.ijk[static_cast<std::size_t>(pa.first_ijk)];
    const auto& cj = b.ijk[static_cast<std::size_t>(pa.second_ijk)];
    if (ci || cj) {
      const double ca = start[static_cast<std::size_t>(a)] + ci.value_or(0) * unit;
      const double cb = start[static_cast<std::size_t>(bb)] + cj.value_or(0) * unit;
      seg = motion::make_arc_center(start, target, n_axes_, static_cast<std::size_t>(a),
                                    static_cast<std::size_t>(bb), ca, cb, ccw);
    } else if (b.r) {
      seg = motion::make_arc_radius(start, target, n_axes_, static_cast<std::size_t>(a),
                                    static_cast<std::size_t>(bb), *b.r * unit, ccw);
    } else {
      return error_command(ErrorId::KernelArcNoCenter, "program I/J/K or R with G2/G3", b.file_id,
                           b.line);
    }
    if (!seg)
      return error_command(arc_error_id(seg.error()),
                           fmt::format("circle: {}", motion::describe(seg.error())), b.file_id, b.line);
  } else {
    seg = motion::make_line(start, target, n_axes_);
    if (!seg) return error_command(ErrorId::KernelArcEndNotOnCircle, "degenerate line", b.file_id, b.line);
  }

  double v_cmd = 0;  // rapid: the path limit (set below)
  if (!rapid) {
    const double f_mm_min = b.modal.feed_mm_min * unit;
    if (f_mm_min <= 0)
      return error_command(ErrorId::KernelNoFeed, "F is 0: program a feed in mm/min", b.file_id,
                           b.line);
    v_cmd = f_mm_min / 60.0;
  }
  pos_ = target;
  if (seg->length() <= 0) {
    c.kind = CommandKind::nop;
    return c;
  }
  c.kind = CommandKind::motion;
  c.segment = *seg;
  const auto& dyn = rapid ? rapid_dyn_ : feed_dyn_;
  c.limits = motion::path_limits(c.segment, std::span<const motion::AxisDynamics>(dyn.data(), n_axes_));
  if (!motion::valid(c.limits))
    return error_command(ErrorId::KernelBadDynamics, "the axes of this block cannot move", b.file_id,
                         b.line);
  c.v_cmd_mm_s = rapid ? c.limits.v_max_mm_s : v_cmd;
  return c;
}

}  // namespace nck::kernel
