// Planning of G0/G1/G2/G3 blocks: program words through the offset chain to
// machine targets, the path segment and its dynamic limits.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "nck/prep/planner.hpp"

namespace nck::prep {
namespace {

ErrorId arc_error_id(motion::ArcError e) {
  switch (e) {
    case motion::ArcError::radius_too_small: return ErrorId::KernelArcRadiusTooSmall;
    case motion::ArcError::full_circle_with_radius: return ErrorId::KernelArcFullCircleWithR;
    default: return ErrorId::KernelArcEndNotOnCircle;
  }
}

frames::SuppressMask suppress_mask(const nc::Block& b) {
  const auto* s = b.hash ? std::get_if<nc::SuppressOffsets>(&*b.hash) : nullptr;
  if (!s) return frames::SuppressMask::none();
  if (s->all) return frames::SuppressMask::all();
  using M = frames::SuppressMask;
  std::uint8_t bits = 0;
  if (s->zero) bits |= M::kZero;
  if (s->add_zero) bits |= M::kAddZero;
  if (s->pset) bits |= M::kPset;
  if (s->clamp) bits |= M::kClamp;
  if (s->tool) bits |= M::kTool;
  if (s->measure) bits |= M::kMeasure;
  if (s->manual) bits |= M::kManual;
  return M{bits};
}

}  // namespace

// A circle in the working plane, built in program coordinates and mapped
// to the machine by the block's affine map (a pure shift in the usual case).
std::expected<motion::Segment, Command> Planner::arc_segment(const nc::Block& b,
                                                             const motion::AxisVector& start,
                                                             const motion::AxisVector& target,
                                                             const motion::AxisVector& origin) {
  const PlaneAxes pa = plane_axes(b.modal.plane);
  const char* first_name = kMainAxisNames[pa.first];
  const char* second_name = kMainAxisNames[pa.second];
  int a = axis_named(first_name), bb = axis_named(second_name);
  // #FACE / #CYL fix the plane to their own axes, centre words I and J.
  const bool trafo = trafo_plane(a, bb);
  const std::size_t ii = trafo ? 0 : static_cast<std::size_t>(pa.first);
  const std::size_t jj = trafo ? 1 : static_cast<std::size_t>(pa.second);
  if (a < 0 || bb < 0)
    return std::unexpected(error_command(
        ErrorId::KernelAxisNotInPlane,
        fmt::format("G{} needs axes {} and {}", static_cast<int>(b.modal.plane), first_name, second_name),
        b.file_id, b.line));
  const auto ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(bb);
  const bool ccw = b.modal.motion == nc::Motion::ccw;
  const auto& ci = b.ijk[ii];
  const auto& cj = b.ijk[jj];
  std::expected<motion::Segment, motion::ArcError> seg;
  if (ci || cj) {
    // G161: the centre is absolute (in the program's origin), G162: relative to the start.
    const bool abs = b.modal.circle_center_absolute;
    const double ca = (abs ? origin[ua] : start[ua]) + ci.value_or(0);
    const double cb = (abs ? origin[ub] : start[ub]) + cj.value_or(0);
    seg = motion::make_arc_center(start, target, n_axes_, ua, ub, ca, cb, ccw);
  } else if (b.r) {
    seg = motion::make_arc_radius(start, target, n_axes_, ua, ub, *b.r, ccw);
  } else {
    return std::unexpected(
        error_command(ErrorId::KernelArcNoCenter, "program I/J/K or R with G2/G3", b.file_id, b.line));
  }
  if (!seg)
    return std::unexpected(error_command(arc_error_id(seg.error()),
                                         fmt::format("circle: {}", motion::describe(seg.error())),
                                         b.file_id, b.line));
  return *seg;
}

// The handwheel offset is an offset like the others (seed 2.10, 2.2.6): a
// programmed axis leaves it out under #SUPPRESS OFFSETS (all kinds or
// MANUAL) and inside #MCS, and takes it back at its next absolute position.
std::uint32_t Planner::manual_axes_after(const nc::Block& b, frames::SuppressMask mask) const {
  const bool leave_out = mask.has(frames::SuppressMask::kManual) || frames_.mcs_active();
  std::uint32_t axes = manual_axes_;
  for (std::size_t j = 0; j < n_axes_; ++j) {
    if (!b.axes[j]) continue;
    if (leave_out) axes &= ~(1u << j);
    else if (b.modal.absolute) axes |= 1u << j;
  }
  return axes;
}

Command Planner::plan_motion(const nc::Block& b, Command c) {
  const frames::SuppressMask mask = suppress_mask(b);
  if (mask.bits != 0)
    if (auto r = frames::OffsetChain::check_suppress(!b.modal.absolute); !r)
      return error_command(r.error().id, "#SUPPRESS OFFSETS needs absolute dimensions (G90)",
                           b.file_id, b.line);
  for (std::size_t j = 0; j < n_axes_; ++j) {
    if (!b.axes[j]) continue;
    const double v = programmed_radius(b, j);
    if (b.modal.absolute) {
      pcs_[j] = v;
      frames_.commit_axis(j);  // G91 rule: new offsets act at the next absolute position
    } else {
      pcs_[j] += v;
    }
  }
  motion::AxisVector target = frames_.to_mcs(pcs_, mask);
  // #SUPPRESS OFFSETS acts on the programmed axes only; the others stay put.
  if (mask.bits != 0)
    for (std::size_t j = 0; j < n_axes_; ++j)
      if (!b.axes[j]) target[j] = mcs_[j];
  for (std::size_t j = 0; j < n_axes_; ++j)
    if (target[j] < swe_neg_[j] - 1e-9 || target[j] > swe_pos_[j] + 1e-9)
      return error_command(
          ErrorId::KernelSoftwareLimit,
          fmt::format("{} {:.4f} is outside the software limits [{:.4f}, {:.4f}]",  // the location is the event's
                      channel_.axes[j].name, target[j], swe_neg_[j], swe_pos_[j]),
          b.file_id, b.line);

  const bool rapid = b.modal.motion == nc::Motion::rapid;
  const bool arc = b.modal.motion == nc::Motion::cw || b.modal.motion == nc::Motion::ccw;
  auto dyn = rapid ? rapid_dyn_ : feed_dyn_;
  if (arc) {
    const AffineMap map = frames_.affine(mask);
    // Start and end in program coordinates of this block's map; the start is
    // where the axes are, so a changed offset never makes the path jump.
    const motion::AxisVector start_pcs = map.pure_translation ? mcs_ : frames_.to_pcs(mcs_, mask);
    const motion::AxisVector end_pcs = map.pure_translation ? target : pcs_;
    const motion::AxisVector origin = map.pure_translation ? map.shift : motion::AxisVector{};
    auto seg = arc_segment(b, start_pcs, end_pcs, origin);
    if (!seg) return seg.error();
    c.segment = *seg;
    if (!map.pure_translation) {
      c.mapped = true;
      c.map = map;
      // A rotated circle loads the main axes in turn: every main axis gets
      // the smallest main-axis limit.
      motion::AxisDynamics lo = dyn[0];
      for (int k : map.main)
        if (k >= 0) {
          const auto& d = dyn[static_cast<std::size_t>(k)];
          lo = {std::min(lo.v_max_mm_s, d.v_max_mm_s), std::min(lo.a_acc_mm_s2, d.a_acc_mm_s2),
                std::min(lo.a_dec_mm_s2, d.a_dec_mm_s2)};
        }
      for (int k : map.main)
        if (k >= 0) dyn[static_cast<std::size_t>(k)] = lo;
    }
  } else {
    auto seg = motion::make_line(mcs_, target, n_axes_, length_axes());
    if (!seg) return error_command(ErrorId::KernelBadDynamics, "degenerate line", b.file_id, b.line);
    c.segment = *seg;
  }

  double v_cmd = 0;  // rapid: the path limit (set below)
  if (rapid) c.feed_link = FeedLink{};
  else if (auto e = plan_feed(b, mcs_, target, c.segment.length(), c, v_cmd)) return *e;
  mcs_ = target;
  if (c.segment.length() <= 0) {
    c.kind = CommandKind::nop;
    return c;
  }
  c.kind = CommandKind::motion;
  manual_axes_ = manual_axes_after(b, mask);
  c.limits = motion::path_limits(c.segment, std::span<const motion::AxisDynamics>(dyn.data(), n_axes_));
  limit_transformed(c, dyn);
  if (!motion::valid(c.limits))
    return error_command(ErrorId::KernelBadDynamics, "the axes of this block cannot move", b.file_id,
                         b.line);
  // A coupling (v_cmd infinite) limits the speed each cycle in the channel.
  c.v_cmd_mm_s = rapid || std::isinf(v_cmd) ? c.limits.v_max_mm_s : v_cmd;
  if (v_cmd < 0) c.v_cmd_mm_s = -v_cmd * c.limits.v_max_mm_s;  // G194: a share of the maximum
  note_transition(b, c, rapid);
  return c;
}

}  // namespace nck::prep
