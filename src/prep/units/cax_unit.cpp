// C-axis machining in block preparation (FCT-S1 §2.8.8): #CAX / #CAX OFF,
// #FACE / #FACE OFF, #CYL / #CYL OFF, the rules around them, and the path
// limits of a transformed motion. The math is in motion/cax_transform.
#include "nck/prep/units/cax_unit.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

namespace nck::prep {
namespace {

bool iequals(std::string_view a, std::string_view b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                    [](char x, char y) { return std::toupper(static_cast<unsigned char>(x)) ==
                                                std::toupper(static_cast<unsigned char>(y)); });
}

bool has_trafo_id(const config::ChannelConfig& c, std::uint32_t id) {
  return std::find(c.trafo_ids.begin(), c.trafo_ids.end(), id) != c.trafo_ids.end();
}

}  // namespace

CaxUnit::CaxUnit(const config::Machine& machine, const config::ChannelConfig& channel, std::size_t n_axes,
                 const std::vector<std::int8_t>& spindles) {
  if (channel.c_axis < 0 || static_cast<std::size_t>(channel.c_axis) >= n_axes) return;
  const auto jc = static_cast<std::size_t>(channel.c_axis);
  const int list = channel.axes[jc].axis_index;
  for (std::size_t k = 0; k < channel.spindles.size() && k < spindles.size(); ++k)
    if (channel.spindles[k].axis_index == list) {
      c_axis_ = channel.c_axis;
      c_spindle_ = spindles[k];
      c_spindle_channel_ = static_cast<int>(k);
    }
  if (c_axis_ < 0) return;
  c_list_ = &machine.axes[static_cast<std::size_t>(list)];
  if (machine.cycle_time_us > 0) c_cycle_limit_deg_s_ = 45.0 / (machine.cycle_time_us * 1e-6);
}

void CaxUnit::take_c_axis_position(double c_deg, PlanContext& ctx) {
  if (c_axis_ < 0) return;
  ctx.planned.mcs[static_cast<std::size_t>(c_axis_)] = c_deg;
  machine_c_deg_ = c_deg;
  ctx.planned.reread(ctx.frames);
}

motion::AxisVector CaxUnit::cartesian(const motion::AxisVector& m, std::size_t n_axes) const {
  motion::AxisVector cart = m;
  if (trafo_.kind != motion::CaxTrafoKind::none) motion::cax_to_cartesian(trafo_, m, cart, n_axes);
  return cart;
}

// Path length: C (degrees) counts only when nothing else moves, as for any
// rotary axis; under #FACE / #CYL C is in mm and counts.
motion::AxisMask CaxUnit::length_axes() const {
  if (c_axis_ < 0 || trafo_.kind != motion::CaxTrafoKind::none) return motion::kAllAxes;
  return motion::kAllAxes & ~(motion::AxisMask{1} << static_cast<unsigned>(c_axis_));
}

// The C axis's name in the program: as the last #CAX gave it, else the list's.
const std::string& CaxUnit::c_axis_name(const PlanContext& ctx) const {
  return name_.empty() ? ctx.channel.axes[static_cast<std::size_t>(c_axis_)].name : name_;
}

// What a block may not do around C-axis mode.
PlanResult CaxUnit::check(const nc::Block& b, const PlanContext& ctx) const {
  if (c_axis_ < 0) return {};
  const auto jc = static_cast<std::size_t>(c_axis_);
  const bool cax_block = b.hash && std::holds_alternative<nc::CAxis>(*b.hash);
  if (!on_ && b.axes[jc] && !cax_block)
    return block_error(ErrorId::KernelCaxAxisNotInMode, b,
                       fmt::format("{} is the main spindle and not in C-axis mode: program #CAX first",
                                   c_axis_name(ctx)));
  if (on_)
    for (const nc::SpindleCommand& s : b.spindles) {
      if (!s.spindle_index || static_cast<int>(*s.spindle_index) != c_spindle_channel_) continue;
      if (s.m != nc::SpindleM::none || s.rev_rpm || s.pos_deg || s.g74 || s.gear_stage || s.g112_stage)
        return block_error(ErrorId::KernelCaxSpindleFunction, b,
                           fmt::format("{} is the C axis {}: spindle functions need #CAX OFF first",
                                       ctx.channel.spindles[static_cast<std::size_t>(c_spindle_channel_)].name,
                                       c_axis_name(ctx)));
    }
  if (trafo_.kind != motion::CaxTrafoKind::none && b.modal.plane != plane_)
    return block_error(ErrorId::KernelTrafoActive, b, "the plane cannot change under #FACE / #CYL");
  return {};
}

// The block's #CAX / #FACE / #CYL.
PlanResult CaxUnit::plan(const nc::Block& b, PlannedCommand& c, PlanContext& ctx) {
  if (!b.hash) return {};
  if (const auto* a = std::get_if<nc::CAxis>(&*b.hash)) {
    if (a->on) return plan_cax_on(b, *a, c, ctx);
    if (trafo_.kind != motion::CaxTrafoKind::none)
      return block_error(ErrorId::KernelCaxOffWithTrafo, b, "#CAX OFF while #FACE or #CYL is active");
    name_.clear();  // the program names it by the list's name again
    if (!on_) return {};
    on_ = false;
    c.attach(kernel::CaxChange{false, c_spindle_, static_cast<std::int8_t>(c_axis_)});
    return {};
  }
  if (std::holds_alternative<nc::Face>(*b.hash) || std::holds_alternative<nc::Cylinder>(*b.hash))
    return plan_trafo(b, ctx);
  return {};
}

PlanResult CaxUnit::plan_cax_on(const nc::Block& b, const nc::CAxis& a, PlannedCommand& c, const PlanContext& ctx) {
  const config::ChannelConfig& channel = ctx.channel;
  if (c_axis_ < 0)
    return block_error(ErrorId::KernelCaxWrongAxisMode, b,
                       "#CAX: the main spindle's axis list needs kenngr.achs_mode 0x0204");
  const config::ChannelSpindle& sp = channel.spindles[static_cast<std::size_t>(c_spindle_channel_)];
  if (!a.spindle.empty() && !iequals(a.spindle, sp.name) && !iequals(a.spindle, channel.main_spindle_name))
    return block_error(ErrorId::KernelCaxWrongAxisMode, b, fmt::format("#CAX: only {} can become the C axis", sp.name));
  // The name is the decoder's (it addresses the axis words); without one the
  // channel's default_ax_name_of_spindle (P-CHAN-00010) must give it.
  const std::string& name = a.axis.empty() ? channel.default_ax_name_of_spindle : a.axis;
  if (name.empty())
    return block_error(ErrorId::KernelCaxWrongAxisMode, b,
                       "#CAX: the channel list names no default_ax_name_of_spindle; name the C axis: #CAX [S, C]");
  name_ = name;
  on_ = true;
  // Also when C-axis mode is on already: the channel answers with C's
  // position, which preparation waits for after every #CAX.
  c.attach(kernel::CaxChange{true, c_spindle_, static_cast<std::int8_t>(c_axis_)});
  return {};
}

PlanResult CaxUnit::plan_trafo(const nc::Block& b, PlanContext& ctx) {
  const config::ChannelConfig& channel = ctx.channel;
  const auto* face = std::get_if<nc::Face>(&*b.hash);
  const auto* cyl = std::get_if<nc::Cylinder>(&*b.hash);
  const motion::CaxTrafoKind kind = face ? motion::CaxTrafoKind::face : motion::CaxTrafoKind::cylinder;
  if (!(face ? face->on : cyl->on)) {
    if (trafo_.kind == kind) set_trafo(motion::CaxTrafo{}, ctx);
    return {};
  }
  const char* name = face ? "#FACE" : "#CYL";
  if (!on_)
    return block_error(ErrorId::KernelCaxNotActive, b, fmt::format("{} needs the C axis: program #CAX first", name));
  if (trafo_.kind != motion::CaxTrafoKind::none)
    return block_error(ErrorId::KernelTrafoActive, b, fmt::format("{}: switch the active #FACE / #CYL off first", name));
  const std::string& c_name = c_axis_name(ctx);
  motion::CaxTrafo t;
  t.kind = kind;
  t.c = static_cast<std::int8_t>(c_axis_);
  int first = -1;
  if (face) {
    first = ctx.axis_named(face->axis1);
    t.radial = static_cast<std::int8_t>(first);
    if (first < 0 || first == c_axis_ || !iequals(face->axis2, c_name))
      return block_error(ErrorId::KernelCaxBadAxes, b,
                         fmt::format("#FACE [<radial axis>, {}]: {} and {} do not fit", c_name, face->axis1,
                                     face->axis2));
    const std::uint32_t id = channel.cax_face_id == 1 ? 13u : channel.cax_face_id == 2 ? 14u : 0u;
    if (id == 0 || !has_trafo_id(channel, id))
      return block_error(ErrorId::KernelTrafoNotConfigured, b,
                         fmt::format("#FACE needs cax_face_id 1 with trafo[i].id 13 or 2 with 14 (cax_face_id is {})",
                                     channel.cax_face_id));
  } else {
    first = ctx.axis_named(cyl->axis1);
    const int radial = ctx.axis_named(cyl->axis3);
    t.radial = static_cast<std::int8_t>(radial);
    t.radius_mm = cyl->radius_mm;
    if (first < 0 || radial < 0 || first == c_axis_ || radial == c_axis_ || first == radial ||
        !iequals(cyl->axis2, c_name))
      return block_error(ErrorId::KernelCaxBadAxes, b,
                         fmt::format("#CYL [<axis>, {}, <radial axis><radius>]: {}, {}, {} do not fit", c_name,
                                     cyl->axis1, cyl->axis2, cyl->axis3));
    if (!has_trafo_id(channel, 15))
      return block_error(ErrorId::KernelTrafoNotConfigured, b, "#CYL needs a trafo[i].id 15 in the channel list");
  }
  plane_ = b.modal.plane;
  plane_first_ = first;
  set_trafo(t, ctx);
  return {};
}

// Switches the transformation: the planned position is carried over between
// machine and Cartesian values, so nothing moves.
void CaxUnit::set_trafo(const motion::CaxTrafo& t, PlanContext& ctx) {
  motion::AxisVector& mcs = ctx.planned.mcs;
  const motion::CaxTrafo old = trafo_;
  if (old.kind == motion::CaxTrafoKind::face) {
    const auto jx = static_cast<std::size_t>(old.radial), jc = static_cast<std::size_t>(old.c);
    const motion::FaceMachine m = motion::face_to_machine(mcs[jx], mcs[jc], machine_c_deg_);
    mcs[jx] = m.x_mm;
    mcs[jc] = m.c_deg;
  } else if (old.kind == motion::CaxTrafoKind::cylinder) {
    const auto jc = static_cast<std::size_t>(old.c);
    mcs[jc] = motion::cyl_to_machine_c_deg(mcs[jc], old.radius_mm);
  }
  if (old.kind != motion::CaxTrafoKind::none) machine_c_deg_ = mcs[static_cast<std::size_t>(old.c)];
  trafo_ = t;
  if (t.kind != motion::CaxTrafoKind::none) {
    machine_c_deg_ = mcs[static_cast<std::size_t>(t.c)];
    motion::AxisVector cart{};
    motion::cax_to_cartesian(t, mcs, cart, ctx.n_axes);
    mcs = cart;
  }
  ctx.planned.reread(ctx.frames);
}

// The transformation's plane (#FACE: radial and C, #CYL: 1st axis and C);
// false without a transformation.
bool CaxUnit::trafo_plane(int& a, int& b) const {
  if (trafo_.kind == motion::CaxTrafoKind::none) return false;
  a = plane_first_;
  b = c_axis_;
  return true;
}

// Limits of a motion under #FACE / #CYL (docs/decisions.md, "C axis"): the Cartesian
// C has the radial axis's dynamics (face) or C's scaled to the reference
// radius (cylinder); on the face the path speed is further limited so that
// C's angular speed, growing near the centre, stays within C's own.
void CaxUnit::limit_transformed(PlannedCommand& c, const AxisDynamicsArray& axes_dyn, std::size_t n_axes) {
  if (trafo_.kind == motion::CaxTrafoKind::none || c.kind != CommandKind::motion) return;
  AxisDynamicsArray dyn = axes_dyn;  // C's entry becomes the Cartesian axis's
  c.trafo = trafo_;
  const auto jc = static_cast<std::size_t>(c_axis_);
  const motion::AxisDynamics c_dyn = dyn[jc];
  if (trafo_.kind == motion::CaxTrafoKind::cylinder) {
    const double mm_per_deg = std::numbers::pi * trafo_.radius_mm / 180.0;
    dyn[jc] = {c_dyn.v_max_mm_s * mm_per_deg, c_dyn.a_acc_mm_s2 * mm_per_deg, c_dyn.a_dec_mm_s2 * mm_per_deg};
    c.limits = motion::path_limits(c.segment, std::span<const motion::AxisDynamics>(dyn.data(), n_axes));
    return;
  }
  dyn[jc] = dyn[static_cast<std::size_t>(trafo_.radial)];
  c.limits = motion::path_limits(c.segment, std::span<const motion::AxisDynamics>(dyn.data(), n_axes));
  const double rate_deg_mm = motion::face_max_c_rate_deg_mm(trafo_, c.segment);
  if (rate_deg_mm > 0) {
    const double c_v_deg_s = std::min(c_dyn.v_max_mm_s, c_cycle_limit_deg_s_);
    c.limits.v_max_mm_s = std::min(c.limits.v_max_mm_s, c_v_deg_s / rate_deg_mm);
    c.limits.a_acc_mm_s2 = std::min(c.limits.a_acc_mm_s2, c_dyn.a_acc_mm_s2 / rate_deg_mm);
    c.limits.a_dec_mm_s2 = std::min(c.limits.a_dec_mm_s2, c_dyn.a_dec_mm_s2 / rate_deg_mm);
  }
  c_before_deg_ = machine_c_deg_;
  machine_c_deg_ = motion::face_end_c_deg(trafo_, c.segment, machine_c_deg_);
}

namespace {

// The motion part of `piece` as a command of `block`: the first carries the
// block's functions and events, the following ones only their motion.
PlannedCommand as_part_of(const PlannedCommand& block, const PlannedCommand& piece, bool first) {
  PlannedCommand c = block;
  if (!first) {
    c = PlannedCommand{};
    c.head.file_id = block.head.file_id;
    c.head.line = block.head.line;
    c.head.emit_block_event = false;
    c.head.feed_motion = block.head.feed_motion;
  }
  c.kind = piece.kind;
  c.segment = piece.segment;
  c.limits = piece.limits;
  c.v_cmd_mm_s = piece.v_cmd_mm_s;
  c.trafo = piece.trafo;
  c.detach<kernel::ProgramMap>();
  if (const auto* map = piece.find<kernel::ProgramMap>()) c.attach(*map);
  return c;
}

}  // namespace

// A face line that leaves the centre needs C turned to its direction first
// (the tool stands at the centre, so only C moves); on a lathe
// (cax_face_id 1), where X stays >= 0, a line through the centre is split
// there and C turns half a turn between the halves. The mill lets X pass
// through 0 instead (docs/decisions.md, "C axis"). At most three commands: line to
// the centre, turn, line from it; the first carries the block's functions.
void CaxUnit::face_centre_commands(const PlannedCommand& c, PlannedBlock& out, const PlanContext& ctx) {
  const motion::CaxTrafo& t = c.trafo;
  const auto jx = static_cast<std::size_t>(t.radial), jc = static_cast<std::size_t>(t.c);
  const bool lathe = ctx.channel.cax_face_id == 1;
  if (c.has<kernel::ProgramMap>() || c.segment.kind() != motion::SegmentKind::line) {
    // An arc never starts at the centre; a rotated contour's points are not
    // machine-Cartesian here: both run as planned.
    (void)out.push_back(c);
    return;
  }
  const motion::AxisVector& p0 = c.segment.start_point();
  const motion::AxisVector& p1 = c.segment.end_point();
  std::vector<std::pair<motion::AxisVector, motion::AxisVector>> lines{{p0, p1}};
  const double dx = p1[jx] - p0[jx], dy = p1[jc] - p0[jc], lp = std::hypot(dx, dy);
  if (lathe && lp > 0) {
    const double foot = -(p0[jx] * dx + p0[jc] * dy) / lp;  // along the plane, from p0
    const double d = std::abs(p0[jx] * dy - p0[jc] * dx) / lp;
    if (d < motion::kFaceCentre_mm && foot > motion::kFaceCentre_mm && foot < lp - motion::kFaceCentre_mm) {
      motion::AxisVector mid{};
      c.segment.point_at(foot / lp * c.segment.length(), mid);
      mid[jx] = mid[jc] = 0;
      lines = {{p0, mid}, {mid, p1}};
    }
  }
  double c_deg = c_before_deg_;
  for (const auto& [a, b] : lines) {
    if (std::hypot(a[jx], a[jc]) < motion::kFaceCentre_mm) {
      const double to = motion::face_leave_centre_c_deg(b[jx] - a[jx], b[jc] - a[jc], c_deg, lathe);
      if (std::abs(to - c_deg) > 1e-9) (void)out.push_back(as_part_of(c, face_turn(c, a, c_deg, to, ctx), out.empty()));
      c_deg = to;
    }
    PlannedCommand piece = c;
    if (lines.size() > 1)
      if (auto s = motion::make_line(a, b, ctx.n_axes)) piece.segment = *s;  // same direction: same limits
    c_deg = motion::face_end_c_deg(t, piece.segment, c_deg);
    (void)out.push_back(as_part_of(c, piece, out.empty()));
  }
  machine_c_deg_ = c_deg;
}

// C alone turning from_deg -> to_deg with the tool at the face's centre (a
// machine move, no transformation), at C's own limits.
PlannedCommand CaxUnit::face_turn(const PlannedCommand& like, const motion::AxisVector& centre_cart, double from_deg,
                           double to_deg, const PlanContext& ctx) const {
  const auto jx = static_cast<std::size_t>(like.trafo.radial), jc = static_cast<std::size_t>(like.trafo.c);
  motion::AxisVector a = centre_cart, b = centre_cart;
  a[jx] = b[jx] = 0;
  a[jc] = from_deg;
  b[jc] = to_deg;
  PlannedCommand turn = like;
  turn.kind = CommandKind::motion;
  turn.trafo = motion::CaxTrafo{};
  turn.detach<kernel::ProgramMap>();
  if (auto s = motion::make_line(a, b, ctx.n_axes)) turn.segment = *s;
  const AxisDynamicsArray& dyn = ctx.axes.dynamics(!like.head.feed_motion);
  turn.limits = motion::path_limits(turn.segment, std::span<const motion::AxisDynamics>(dyn.data(), ctx.n_axes));
  turn.v_cmd_mm_s = turn.limits.v_max_mm_s;
  return turn;
}

}  // namespace nck::prep
