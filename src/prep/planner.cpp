// The Planner sequences the technology units of preparation: the order of
// the calls below is the order in which a block's rules are checked and its
// functions planned (the first failure is the block's error).
#include "nck/prep/planner.hpp"

#include <algorithm>
#include <cmath>

#include "nck/prep/block_rules.hpp"
#include "nck/prep/error_command.hpp"
#include "nck/prep/state_variables.hpp"
#include "nck/prep/units/path_geometry.hpp"

namespace nck::prep {
namespace {

const config::ChannelData& channel_data(const config::Machine& m, std::size_t channel_index) {
  static const config::ChannelData kNone;
  return channel_index < m.channel_data.size() ? m.channel_data[channel_index] : kNone;
}

}  // namespace

Planner::Planner(const config::Machine& machine, std::size_t channel_index, PlanStore& store,
                 const PlannerOptions& options, const std::vector<std::int8_t>& spindles)
    : machine_(&machine),
      channel_(machine.channels[channel_index]),
      store_(store),
      n_axes_(std::min(channel_.axes.size(), kMaxAxes)),
      frames_(channel_, channel_data(machine, channel_index), n_axes_, options.clamp_index),
      cax_(machine, channel_, n_axes_, spindles),
      axes_(machine, channel_, n_axes_, cax_.c_axis(), cax_.c_axis_list()),
      corner_(axes_, machine.cycle_time_us),
      weights_(axes_),
      spindles_(machine, channel_index, std::vector<int>(spindles.begin(), spindles.end())),
      feed_(channel_, spindles),
      diameter_(machine, channel_, n_axes_),
      couplings_(channel_, spindles) {
  planned_.reread(frames_);  // the clamp / default zero offset act from the start
}

PlanContext Planner::context() { return {*machine_, channel_, store_, n_axes_, axes_, frames_, planned_}; }

const PlannedSpindle& Planner::main_planned() const {
  static const PlannedSpindle kNone;
  const std::size_t i = feed_.main_spindle().list_index;
  return i < spindles_.spindle_count() ? spindles_.planned(i) : kNone;
}

Planner::Commands Planner::plan(const nc::Block& b) {
  PlanContext ctx = context();
  // Every error of the block is located at the block (the one place that
  // makes error commands: error_command.hpp).
  auto fail = [&](Diagnostic d) {
    d.loc.line = b.line;
    Commands out;
    (void)out.push_back(error_command(d, b.file_id, store_));
    return out;
  };
  Commands out;
  const bool homing = b.has_axis_words() && b.g_nonmodal.has(nc::GCode::g74);
  // A block that fails moves nothing: the position stays where the last
  // good block left it (a run stops at the error; `nck check` goes on from
  // there without a wrong start for the next block).
  const PlannedPosition before = planned_;
  PlannedCommand& c = *out.emplace_back();
  const PlanResult r = plan_one(b, c, ctx);
  if (!r) {
    planned_ = before;
    out = fail(r.error());
  } else if (homing && c.kind == CommandKind::nop) {
    auto groups = plan_homing(b, c, ctx);
    out = groups ? *groups : fail(groups.error());
  } else if (c.kind == CommandKind::motion && c.trafo.kind == motion::CaxTrafoKind::face) {
    const PlannedCommand first = c;  // out is refilled
    out.clear();
    cax_.face_centre_commands(first, out, ctx);  // C turns at the face's centre
  }
  manual_.stamp(out);
  couplings_.follow(ctx);
  return out;
}

PlanResult Planner::plan_one(const nc::Block& b, PlannedCommand& c, PlanContext& ctx) {
  modal_ = b.modal;
  if (auto r = check_supported(b); !r) return std::unexpected(r.error());
  if (auto r = check_spindle_scope(b); !r) return std::unexpected(r.error());
  c.head.file_id = b.file_id;
  c.head.line = b.line;
  c.head.n = b.n;
  if (auto r = add_outputs(b, c, channel_); !r) return std::unexpected(r.error());
  if (auto r = plan_technologies(b, c, ctx); !r) return std::unexpected(r.error());
  return plan_execution(b, c, ctx);
}

// The block's functions, unit after unit.
PlanResult Planner::plan_technologies(const nc::Block& b, PlannedCommand& c, PlanContext& ctx) {
  if (auto r = diameter_.check(b, c, ctx); !r) return r;
  apply_weights(b, c);
  if (auto r = apply_frames(b, c); !r) return r;
  modal_.zero_offset = frames_.zero_index();  // what is in force, for --final
  if (auto r = measure_.apply_offset(b, c, ctx); !r) return r;
  if (auto r = check_plc_spindles(b, channel_); !r) return r;
  if (auto r = cax_.check(b, ctx); !r) return r;
  if (auto r = cax_.plan(b, c, ctx); !r) return r;
  if (auto r = couplings_.plan(b, c, ctx); !r) return r;
  if (auto r = technologies_.plan(b, c, ctx); !r) return r;
  auto actions = spindles_.plan(couplings_.with_slaves(b, with_slaves_scratch_, channel_));
  if (!actions) return std::unexpected(actions.error());
  for (const kernel::SpindleAction& a : *actions) c.attach(a);
  couplings_.end_program(b);
  const PlannedSpindle& main = main_planned();
  if (auto r = feed_.plan_block(b, c, ctx, main); !r) return r;
  const MainSpindle& ms = feed_.main_spindle();
  if (auto r = css_.plan(b, c, ctx, ms, ms.vb_max_rpm(*machine_, channel_, main.gear_stage)); !r) return r;
  c.head.expl_syn = b.hash && std::holds_alternative<nc::ExplSyn>(*b.hash);
  manual_.plan(b, c, n_axes_);
  return {};
}

// G130...G134, G233 and #SLOPE DEFAULT: the weightings in force (the
// values they limit warned at c), and the corner rule's kink budgets with
// the weighted accelerations.
void Planner::apply_weights(const nc::Block& b, PlannedCommand& c) {
  constexpr nc::GCodeSet kWeighting{nc::GCode::g130, nc::GCode::g131, nc::GCode::g132,
                                    nc::GCode::g133, nc::GCode::g134, nc::GCode::g233};
  if (!b.slope_default && !b.g_nonmodal.has_any(kWeighting)) return;
  add_warnings(c, weights_.apply(b, axes_, channel_), store_);
  AxisDynamicsArray feed = axes_.dynamics(false);
  weights_.weigh(feed, false);
  corner_.set_feed_dynamics(axes_, feed);
}

// Runs the block's offset functions.
PlanResult Planner::apply_frames(const nc::Block& b, PlannedCommand& c) {
  auto changes = frames_.apply(b, planned_.mcs);
  if (!changes) return std::unexpected(changes.error());
  add_warnings(c, changes->warnings, store_);
  for (frames::OffsetKind k : changes->kinds) {
    const std::string kind(frames::to_string(k));
    bool seen = false;
    c.each<frames::OffsetEvent>([&](const frames::OffsetEvent& e) { seen = seen || store_.offsets[e.index].kind == kind; });
    if (!seen) c.attach(frames::OffsetEvent{store_.add_offset({kind, frames_.values_of(k, true)})});
  }
  // After a change of coordinate system the axes stay where they are: their
  // program position is read anew in the new system.
  if (changes->coordinate_system_changed) planned_.reread(frames_);
  return {};
}

// What the block executes: program end, stop, dwell, motion or nothing.
PlanResult Planner::plan_execution(const nc::Block& b, PlannedCommand& c, PlanContext& ctx) {
  if (b.program_end) {
    c.kind = CommandKind::end;
    c.step = kernel::End{std::find(b.m.begin(), b.m.end(), 2) != b.m.end() ? EndReason::m2 : EndReason::m30};
    return {};
  }
  if (b.stop || b.optional_stop) {
    c.kind = CommandKind::stop;
    c.step = kernel::Hold{!b.stop};  // M0 and M1 together: M0 wins
    return {};
  }
  if (b.dwell_s) {
    c.kind = CommandKind::dwell;
    c.step = kernel::Dwell{std::max(0.0, *b.dwell_s), std::nullopt};
    return {};
  }
  if (b.dwell_revs) {
    if (!feed_.main_spindle().exists())
      return block_error(ErrorId::KernelLinkNoSpindle, b, "G4 S.. counts main-spindle revolutions: the channel has none");
    c.kind = CommandKind::dwell;
    c.step = kernel::Dwell{0, kernel::Dwell::Revolutions{std::max(0.0, *b.dwell_revs), feed_.main_spindle().kernel}};
    return {};
  }
  if (b.g_nonmodal.has(nc::GCode::g100)) {
    // G100: a linear move at F that stops where the probe switches.
    nc::Block run = b;
    run.modal.motion = nc::Motion::linear;
    const PlanResult m = plan_motion(run, c, ctx);
    if (m && c.kind == CommandKind::motion) measure_.start_run(c, ctx);
    return m;
  }
  // With G201/G202 the axis words select the axes.
  const bool words_are_motion = !b.manual_g && !b.g_nonmodal.has_any(kAxisWordsAreValues);
  const bool circle = b.modal.motion == nc::Motion::cw || b.modal.motion == nc::Motion::ccw;
  if (words_are_motion && (b.has_axis_words() || (circle && (b.ijk[0] || b.ijk[1] || b.ijk[2])))) {
    c.head.feed_motion = b.modal.motion != nc::Motion::rapid;
    return plan_motion(b, c, ctx);
  }
  // P-CHAN-00100 move_tool_offsets_directly 1: a new tool offset is moved
  // with the D word itself (DIN 66025), at rapid.
  if (channel_.move_tool_offsets_directly && (b.d || (b.hash && std::holds_alternative<nc::ToolData>(*b.hash)))) {
    nc::Block move = b;
    move.modal.motion = nc::Motion::rapid;
    move.axes = {};
    return plan_motion(move, c, ctx);
  }
  c.kind = CommandKind::nop;
  return {};
}

// G0/G1/G2/G3: the target through the offsets, the path segment, its feed
// and dynamic limits, and the transition from the motion before it.
PlanResult Planner::plan_motion(const nc::Block& b, PlannedCommand& c, PlanContext& ctx) {
  const frames::SuppressMask mask = suppress_mask(b);
  AxisArray radius_mm{};
  for (std::size_t j = 0; j < n_axes_; ++j)
    if (b.axes[j]) radius_mm[j] = diameter_.programmed_radius(b, j);
  auto target = machine_target(b, radius_mm, mask, ctx);
  if (!target) return std::unexpected(target.error());
  const bool rapid = b.modal.motion == nc::Motion::rapid;
  const bool arc = b.modal.motion == nc::Motion::cw || b.modal.motion == nc::Motion::ccw;
  // The axes' dynamics (2 KB) are copied only for a block that changes them.
  std::optional<AxisDynamicsArray> own;
  const auto changed = [&]() -> AxisDynamicsArray& { return own ? *own : own.emplace(axes_.dynamics(rapid)); };
  if (weights_.active()) {
    weights_.weigh(changed(), rapid);
    if (!rapid) c.weights = weights_.scale();
  }
  if (arc) {
    if (auto r = plan_arc(b, c, *target, mask, changed(), ctx); !r) return std::unexpected(r.error());
  } else {
    auto seg = motion::make_line(planned_.mcs, *target, n_axes_, cax_.length_axes());
    if (!seg) return block_error(ErrorId::KernelBadDynamics, b, "degenerate line");
    c.segment = *seg;
  }
  PathSpeed speed{PathSpeed::Kind::axes_max, 0};  // rapid: the path limit
  if (rapid) {
    c.feed_link = FeedLink{};
  } else {
    auto v = feed_.plan_feed(b, planned_.mcs, *target, c.segment.length(), c, ctx, main_planned());
    if (!v) return std::unexpected(v.error());
    speed = *v;
  }
  planned_.mcs = *target;
  if (c.segment.length() <= 0) {
    c.kind = CommandKind::nop;
    return {};
  }
  c.kind = CommandKind::motion;
  manual_.moved(b, mask, ctx);
  const AxisDynamicsArray& dyn = own ? *own : axes_.dynamics(rapid);
  c.limits = motion::path_limits(c.segment, std::span<const motion::AxisDynamics>(dyn.data(), n_axes_), b.modal.slope);
  cax_.limit_transformed(c, dyn, n_axes_);
  if (!motion::valid(c.limits)) return block_error(ErrorId::KernelBadDynamics, b, "the axes of this block cannot move");
  switch (speed.kind) {
    case PathSpeed::Kind::programmed: c.v_cmd_mm_s = speed.value; break;
    case PathSpeed::Kind::axes_max: c.v_cmd_mm_s = c.limits.v_max_mm_s; break;
    case PathSpeed::Kind::share_of_max: c.v_cmd_mm_s = speed.value * c.limits.v_max_mm_s; break;
  }
  corner_.note_transition(b, c, rapid, ctx);
  return {};
}

PlannedCommand Planner::return_motion(const motion::AxisVector& from_mcs, const motion::AxisVector& to_mcs) const {
  PlannedCommand c;
  c.kind = CommandKind::nop;
  const auto seg = motion::make_line(from_mcs, to_mcs, n_axes_, cax_.length_axes());
  if (!seg || !(seg->length() > 0)) return c;
  const AxisDynamicsArray dyn = axes_.dynamics(true);
  c.segment = *seg;
  c.limits = motion::path_limits(c.segment, std::span<const motion::AxisDynamics>(dyn.data(), n_axes_));
  if (!motion::valid(c.limits)) return c;
  c.kind = CommandKind::motion;
  c.v_cmd_mm_s = c.limits.v_max_mm_s;
  c.exact_stop = true;
  return c;
}

// A circle: start and end in program coordinates of this block's map; the
// start is where the axes are, so a changed offset never makes the path jump.
PlanResult Planner::plan_arc(const nc::Block& b, PlannedCommand& c, const motion::AxisVector& target,
                             frames::SuppressMask mask, AxisDynamicsArray& dyn, PlanContext& ctx) {
  const AffineMap map = frames_.affine(mask);
  const motion::AxisVector start_pcs = map.pure_translation ? planned_.mcs : frames_.to_pcs(planned_.mcs, mask);
  const motion::AxisVector end_pcs = map.pure_translation ? target : planned_.pcs;
  const motion::AxisVector origin = map.pure_translation ? map.shift : motion::AxisVector{};
  ArcPlane plane = arc_plane(b, ctx);
  plane.trafo = cax_.trafo_plane(plane.first, plane.second);
  auto seg = arc_segment(b, plane, start_pcs, end_pcs, origin, n_axes_);
  if (!seg) return std::unexpected(seg.error());
  c.segment = *seg;
  if (map.pure_translation) return {};
  c.attach(kernel::ProgramMap{map});
  // A rotated circle loads the main axes in turn: every main axis gets the
  // smallest main-axis limit.
  motion::AxisDynamics lo = dyn[0];
  for (int k : map.main)
    if (k >= 0) {
      const auto& d = dyn[static_cast<std::size_t>(k)];
      lo = {std::min(lo.v_max_mm_s, d.v_max_mm_s), std::min(lo.a_acc_mm_s2, d.a_acc_mm_s2),
            std::min(lo.a_dec_mm_s2, d.a_dec_mm_s2), motion::longest(lo.tr, d.tr),
            std::max(lo.tr_geom_s, d.tr_geom_s)};
    }
  for (int k : map.main)
    if (k >= 0) dyn[static_cast<std::size_t>(k)] = lo;
  return {};
}

std::vector<std::pair<std::string, double>> Planner::take_measurement(const kernel::MeasureResult& r) {
  PlanContext ctx = context();
  return measure_.take_measurement(r, ctx);
}

void Planner::take_stopped_position(const motion::AxisVector& path_mcs) {
  planned_.mcs = path_mcs;
  planned_.reread(frames_);
}

void Planner::take_c_axis_position(double c_deg) {
  PlanContext ctx = context();
  cax_.take_c_axis_position(c_deg, ctx);
}

std::optional<double> Planner::read(std::string_view key) const {
  return read_state_variable(key, frames_, channel_, planned_.pcs, n_axes_, modal_.plane);
}

}  // namespace nck::prep
