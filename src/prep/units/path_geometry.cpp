// The geometry of a motion block; see path_geometry.hpp.
#include "nck/prep/units/path_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <vector>

#include "nck/prep/units/axis_table.hpp"

namespace nck::prep {
namespace {

ErrorId arc_error_id(motion::ArcError e) {
  switch (e) {
    case motion::ArcError::radius_too_small: return ErrorId::KernelArcRadiusTooSmall;
    case motion::ArcError::full_circle_with_radius: return ErrorId::KernelArcFullCircleWithR;
    default: return ErrorId::KernelArcEndNotOnCircle;
  }
}

// The numbers behind an impossible circle, so that the programmer sees how
// far off it is: both radii of a centre-programmed circle and their
// difference, or R against half the chord.
std::string centre_arc_values(double sa, double sb, double ea, double eb) {
  const double r_start = std::hypot(sa, sb), r_end = std::hypot(ea, eb);
  return fmt::format(" (start radius {:.4f} mm, end radius {:.4f} mm, difference {:.4f} mm)", r_start, r_end,
                     std::fabs(r_end - r_start));
}

std::string radius_arc_values(double r, double chord) {
  return fmt::format(" (R {:.4f} mm, half the chord {:.4f} mm, difference {:.4f} mm)", std::fabs(r), 0.5 * chord,
                     0.5 * chord - std::fabs(r));
}

// Which axis, where, and by how much it would pass its software limit.
std::string outside_limits(const std::string& axis, double pos, double lo, double hi) {
  const bool below = pos < lo;
  return fmt::format("{} {:.4f} is outside the software limits [{:.4f}, {:.4f}]: {:.4f} mm {} the {} limit", axis,
                     pos, lo, hi, below ? lo - pos : pos - hi, below ? "below" : "beyond",
                     below ? "negative" : "positive");
}

}  // namespace

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

std::expected<motion::AxisVector, Diagnostic> machine_target(const nc::Block& b, const AxisArray& radius_mm,
                                                             frames::SuppressMask mask, PlanContext& ctx) {
  if (mask.bits != 0)
    if (auto r = frames::OffsetChain::check_suppress(!b.modal.absolute); !r)
      return block_error(r.error().id, b, "#SUPPRESS OFFSETS needs absolute dimensions (G90)");
  motion::AxisVector& pcs = ctx.planned.pcs;
  for (std::size_t j = 0; j < ctx.n_axes; ++j) {
    if (!b.axes[j]) continue;
    if (b.modal.absolute) {
      pcs[j] = radius_mm[j];
      ctx.frames.commit_axis(j);  // G91 rule: new offsets act at the next absolute position
    } else {
      pcs[j] += radius_mm[j];
    }
  }
  motion::AxisVector target = ctx.frames.to_mcs(pcs, mask);
  // #SUPPRESS OFFSETS acts on the programmed axes only; the others stay put.
  if (mask.bits != 0)
    for (std::size_t j = 0; j < ctx.n_axes; ++j)
      if (!b.axes[j]) target[j] = ctx.planned.mcs[j];
  for (std::size_t j = 0; j < ctx.n_axes; ++j) {
    const double lo = ctx.axes.sw_limit_neg_mm(j), hi = ctx.axes.sw_limit_pos_mm(j);
    if (target[j] < lo - 1e-9 || target[j] > hi + 1e-9)
      return block_error(ErrorId::KernelSoftwareLimit, b,  // the location is the event's
                         outside_limits(ctx.channel.axes[j].name, target[j], lo, hi));
  }
  return target;
}

ArcPlane arc_plane(const nc::Block& b, const PlanContext& ctx) {
  const PlaneAxes pa = plane_axes(b.modal.plane);
  return {ctx.axis_named(kMainAxisNames[pa.first]), ctx.axis_named(kMainAxisNames[pa.second]), false};
}

// A circle in the working plane, built in program coordinates and mapped
// to the machine by the block's affine map (a pure shift in the usual case).
std::expected<motion::Segment, Diagnostic> arc_segment(const nc::Block& b, const ArcPlane& p,
                                                       const motion::AxisVector& start,
                                                       const motion::AxisVector& target,
                                                       const motion::AxisVector& origin, std::size_t n_axes) {
  const PlaneAxes pa = plane_axes(b.modal.plane);
  // #FACE / #CYL fix the plane to their own axes, centre words I and J.
  const std::size_t ii = p.trafo ? 0 : static_cast<std::size_t>(pa.first);
  const std::size_t jj = p.trafo ? 1 : static_cast<std::size_t>(pa.second);
  if (p.first < 0 || p.second < 0)
    return block_error(ErrorId::KernelAxisNotInPlane, b,
                       fmt::format("G{} needs axes {} and {}", static_cast<int>(b.modal.plane),
                                   kMainAxisNames[pa.first], kMainAxisNames[pa.second]));
  const auto ua = static_cast<std::size_t>(p.first), ub = static_cast<std::size_t>(p.second);
  const bool ccw = b.modal.motion == nc::Motion::ccw;
  const auto& ci = b.ijk[ii];
  const auto& cj = b.ijk[jj];
  std::expected<motion::Segment, motion::ArcError> seg;
  std::string values;  // for the message, should the circle be impossible
  if (ci || cj) {
    // G161: the centre is absolute (in the program's origin), G162: relative to the start.
    const bool abs = b.modal.circle_center_absolute;
    const double ca = (abs ? origin[ua] : start[ua]) + ci.value_or(0);
    const double cb = (abs ? origin[ub] : start[ub]) + cj.value_or(0);
    seg = motion::make_arc_center(start, target, n_axes, ua, ub, ca, cb, ccw);
    if (!seg && seg.error() == motion::ArcError::end_point_not_on_circle)
      values = centre_arc_values(start[ua] - ca, start[ub] - cb, target[ua] - ca, target[ub] - cb);
  } else if (b.r) {
    seg = motion::make_arc_radius(start, target, n_axes, ua, ub, *b.r, ccw);
    if (!seg && seg.error() == motion::ArcError::radius_too_small)
      values = radius_arc_values(*b.r, std::hypot(target[ua] - start[ua], target[ub] - start[ub]));
  } else {
    return block_error(ErrorId::KernelArcNoCenter, b, "program I/J/K or R with G2/G3");
  }
  if (!seg)
    return block_error(arc_error_id(seg.error()), b, fmt::format("circle: {}{}", motion::describe(seg.error()), values));
  return *seg;
}

std::expected<PlannedBlock, Diagnostic> plan_homing(const nc::Block& b, const PlannedCommand& first, PlanContext& ctx) {
  PlannedBlock out;
  AxisArray order{};
  std::vector<double> groups;
  for (std::size_t j = 0; j < ctx.n_axes; ++j)
    if (b.axes[j]) {
      order[j] = *b.axes[j];
      if (std::find(groups.begin(), groups.end(), order[j]) == groups.end()) groups.push_back(order[j]);
    }
  std::sort(groups.begin(), groups.end());
  if (groups.size() > out.capacity())
    return block_error(ErrorId::KernelTooManyHomingGroups, b,
                       fmt::format("G74 orders {} homing groups; at most {} per block", groups.size(),
                                   out.capacity()));
  motion::AxisVector& mcs = ctx.planned.mcs;
  const AxisDynamicsArray& rapid = ctx.axes.dynamics(true);
  PlannedCommand c = first;
  for (double g : groups) {
    motion::AxisVector target = mcs;
    kernel::HomeAxes homes;  // the kernel marks these homed at the group's end
    for (std::size_t j = 0; j < ctx.n_axes; ++j)
      if (b.axes[j] && order[j] == g) {
        target[j] = ctx.axes.home_pos_mm(j);
        homes.mask |= 1u << j;
      }
    c.attach(homes);
    auto seg = motion::make_line(mcs, target, ctx.n_axes);
    // An axis that searches its reference on a real drive (the kernel's
    // HomingSearch) starts this motion wherever the search left it: the
    // motion is always there, and its limits hold in every direction.
    const bool searches = (homes.mask & ctx.axes.searching_home()) != 0;
    if (seg && (seg->length() > 0 || searches)) {
      const std::span<const motion::AxisDynamics> dyn(rapid.data(), ctx.n_axes);
      c.kind = CommandKind::motion;
      c.segment = *seg;
      c.detach<kernel::ProgramMap>();
      c.limits = searches ? motion::any_direction_limits(dyn) : motion::path_limits(c.segment, dyn);
      c.v_cmd_mm_s = c.limits.v_max_mm_s;
      c.exact_stop = true;  // each homing group ends at its home position
    }
    mcs = target;
    (void)out.push_back(c);
    c = PlannedCommand{};  // the following groups: motion only
    c.head.file_id = b.file_id;
    c.head.line = b.line;
    c.head.emit_block_event = false;
  }
  for (std::size_t j = 0; j < ctx.n_axes; ++j)
    if (b.axes[j]) ctx.frames.preset_axis(j);
  ctx.planned.reread(ctx.frames);
  return out;
}

}  // namespace nck::prep
