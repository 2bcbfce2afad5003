#include "nck/prep/planner.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace nck::prep {
namespace {

bool is_fixed_m(int m) {
  switch (m) {
    case 0: case 1: case 2: case 17: case 29: case 30:
      return true;
    default:
      return false;
  }
}

// # commands this version executes: the offset chain's, #EXPL SYN and
// #MAIN SPINDLE (whose name mapping the decoder does).
bool is_executed_command(const nc::HashCommand& h) {
  if (std::holds_alternative<nc::ExplSyn>(h) || std::holds_alternative<nc::MainSpindle>(h) ||
      std::holds_alternative<nc::GetManualOffsets>(h) || std::holds_alternative<nc::DistCtrl>(h))
    return true;
  if (std::holds_alternative<nc::SetAxLink>(h) || std::holds_alternative<nc::EnableAxLink>(h) ||
      std::holds_alternative<nc::DisableAxLink>(h))
    return true;  // planner_axlink.cpp
  if (std::holds_alternative<nc::CAxis>(h) || std::holds_alternative<nc::Face>(h) ||
      std::holds_alternative<nc::Cylinder>(h))
    return true;  // planner_cax.cpp
  return std::holds_alternative<nc::CoordSystem>(h) || std::holds_alternative<nc::Ecs>(h) ||
         std::holds_alternative<nc::Mcs>(h) || std::holds_alternative<nc::Rotation>(h) ||
         std::holds_alternative<nc::PSet>(h) || std::holds_alternative<nc::PReset>(h) ||
         std::holds_alternative<nc::Tlc>(h) || std::holds_alternative<nc::SuppressOffsets>(h) ||
         std::holds_alternative<nc::ToolData>(h);
}

// The non-modal G functions this version executes.
constexpr nc::GCodeSet kExecutedNonModal{nc::GCode::g4,   nc::GCode::g60,  nc::GCode::g61,  nc::GCode::g74,  nc::GCode::g92,  nc::GCode::g100,
                                         nc::GCode::g101, nc::GCode::g102, nc::GCode::g112, nc::GCode::g130,
                                         nc::GCode::g135, nc::GCode::g136, nc::GCode::g137, nc::GCode::g167,
                                         nc::GCode::g196};

// With these the axis words are the function's values (homing order, G92
// offset, G101 factor, G102 selection), not a motion target.
constexpr nc::GCodeSet kAxisWordsAreValues{nc::GCode::g74, nc::GCode::g92, nc::GCode::g101, nc::GCode::g102};

}  // namespace

Planner::Planner(const config::Machine& machine, std::size_t channel_index, PlanStore& store,
                 const PlannerOptions& options, const std::vector<std::int8_t>& spindles)
    : machine_(&machine),
      channel_(machine.channels[channel_index]),
      store_(store),
      n_axes_(std::min(channel_.axes.size(), kMaxAxes)),
      frames_(channel_, channel_index < machine.channel_data.size() ? machine.channel_data[channel_index]
                                                                    : config::ChannelData{},
              n_axes_, options.clamp_index),
      spindles_(machine, channel_index, std::vector<int>(spindles.begin(), spindles.end())) {
  for (std::size_t j = 0; j < n_axes_; ++j) {
    static const config::AxisConfig kNoAxisList;  // defaults for an axis without a list
    const int idx = channel_.axes[j].axis_index;
    const config::AxisConfig& ax = idx >= 0 ? machine.axes[static_cast<std::size_t>(idx)] : kNoAxisList;
    const config::GearStage& g = ax.gear(ax.initial_gear_stage);
    // Feed moves: a_beschl up, a_brems down; rapid: a_grenz; all capped by a_max.
    feed_dyn_[j] = {g.vb_max, std::min(g.a_beschl, g.a_max), std::min(g.a_brems, g.a_max)};
    const double a_rapid = std::min(g.a_grenz, g.a_max);
    rapid_dyn_[j] = {std::min(g.vb_eilgang, g.vb_max), a_rapid, a_rapid};
    axis_a_max_[j] = g.a_max;
    swe_neg_[j] = ax.swe_neg;
    swe_pos_[j] = ax.swe_pos;
    ref_pos_[j] = g.pos_refpkt;
    if (!machine.sim.probe_axis.empty() && channel_.axes[j].name == machine.sim.probe_axis) {
      probe_axis_ = static_cast<std::int8_t>(j);
      probe_pos_mm_ = machine.sim.probe_position_mm;
    }
  }
  init_c_axis(machine, spindles);
  pcs_ = frames_.to_pcs(mcs_);  // the clamp / default zero offset act from the start
  setup_diameter_axes(machine);
  setup_corner_budgets(machine);
  find_main_spindle(spindles);
  init_ax_links(spindles);
}

Command Planner::error_command(ErrorId id, std::string message, std::uint16_t file_id,
                               std::uint32_t line) {
  Command c;
  c.kind = CommandKind::error;
  c.error_id = id;
  c.file_id = file_id;
  c.line = line;
  c.emit_block_event = false;
  c.message_index = store_.add_message(std::move(message));
  return c;
}

int Planner::axis_named(const char* name) const {
  for (std::size_t j = 0; j < n_axes_; ++j)
    if (channel_.axes[j].name == name) return static_cast<int>(j);
  return -1;
}

// Names what the block asks for that this version does not execute yet, or "".
std::string Planner::unsupported(const nc::Block& b) const {
  if (b.hash && !is_executed_command(*b.hash))
    return fmt::format("{} is not executed yet", nc::hash_command_name(*b.hash));
  for (nc::GCode g : b.g_nonmodal)
    if (!kExecutedNonModal.has(g)) return fmt::format("G{} is not executed yet", nc::g_number(g));
  for (const nc::VariableWrite& w : b.kernel_writes)
    if (w.name.rfind("V.G.NP[", 0) != 0) return fmt::format("writing {} is not executed yet", w.name);
  return {};
}

// A spindle commanded over the channel HLI (plc_control 1) knows only its
// speed and M3/M4/M5/M19 (FCT-S1 2.2.2.2).
std::string Planner::plc_control_violation(const nc::Block& b) const {
  for (const nc::SpindleCommand& s : b.spindles) {
    if (!s.spindle_index || *s.spindle_index >= channel_.spindles.size()) continue;
    const config::ChannelSpindle* sp = &channel_.spindles[*s.spindle_index];
    if (!sp->plc_control) continue;
    if (s.g74 || s.g167 || s.g130_pct || s.g135 || s.g137 || s.g136_pct || s.gear_stage || s.g112_stage ||
        s.get_dynamic_data || s.default_dynamic_data || !s.user_m.empty() || !s.user_h.empty())
      return fmt::format("{} is a PLC spindle over the channel interface: only its speed and "
                         "M3/M4/M5/M19 can be programmed",
                         sp->name);
  }
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
  // #TOOL PREP [basic, ...] is the T word's form (facts B16): the PLC gets the basic number.
  std::optional<std::int64_t> t = b.t;
  if (const auto* td = b.hash ? std::get_if<nc::ToolData>(&*b.hash) : nullptr; td && td->prep) t = td->fields[0];
  if (t && !c.outputs.push_back({FunctionKind::t, static_cast<std::int32_t>(*t), config::sync::MOS})) return false;
  return true;
}

// Runs the block's offset functions; on failure `error` holds the command.
bool Planner::apply_frames(const nc::Block& b, Command& c, Command& error) {
  auto changes = frames_.apply(b, mcs_);
  if (!changes) {
    error = error_command(changes.error().id, changes.error().message, b.file_id, b.line);
    return false;
  }
  add_warnings(c, changes->warnings, store_);
  for (frames::OffsetKind k : changes->kinds) {
    const std::string kind(frames::to_string(k));
    const bool seen = std::any_of(c.offset_events.begin(), c.offset_events.end(),
                                  [&](std::uint32_t i) { return store_.offsets[i].kind == kind; });
    if (!seen) (void)c.offset_events.push_back(store_.add_offset({kind, frames_.values_of(k, true)}));
  }
  // After a change of coordinate system the axes stay where they are: their
  // program position is read anew in the new system.
  if (changes->coordinate_system_changed) pcs_ = frames_.to_pcs(mcs_);
  return true;
}

Planner::Commands Planner::plan(const nc::Block& b) {
  Commands out;
  const bool homing = b.has_axis_words() && b.g_nonmodal.has(nc::GCode::g74);
  Command c = plan_one(b);
  if (homing && c.kind == CommandKind::nop) {
    plan_homing(b, c, out);
  } else if (c.kind == CommandKind::motion && c.trafo.kind == motion::CaxTrafoKind::face) {
    face_centre_commands(c, out);  // planner_cax.cpp: C turns at the face's centre
  } else {
    (void)out.push_back(c);
  }
  // Only motion commands change the handwheel share; the others carry it on.
  for (Command& cmd : out) cmd.manual_offset_axes = manual_axes_;
  follow_axis_links();
  return out;
}

// Homing path axes (G74 X<order> Y<order>..): the axes with the same order
// number move together at rapid to their reference position (pos_refpkt),
// group after group; the block's other functions go with the first group.
// Homing clears #PSET of the homed axes.
void Planner::plan_homing(const nc::Block& b, Command first, Commands& out) {
  AxisArray order{};
  std::vector<double> groups;
  for (std::size_t j = 0; j < n_axes_; ++j)
    if (b.axes[j]) {
      order[j] = *b.axes[j];
      if (std::find(groups.begin(), groups.end(), order[j]) == groups.end()) groups.push_back(order[j]);
    }
  std::sort(groups.begin(), groups.end());
  if (groups.size() > out.capacity()) {
    (void)out.push_back(error_command(ErrorId::KernelTooManyHomingGroups,
                                      fmt::format("G74 orders {} homing groups; at most {} per block",
                                                  groups.size(), out.capacity()),
                                      b.file_id, b.line));
    return;
  }
  Command c = first;
  for (double g : groups) {
    motion::AxisVector target = mcs_;
    for (std::size_t j = 0; j < n_axes_; ++j)
      if (b.axes[j] && order[j] == g) target[j] = ref_pos_[j];
    auto seg = motion::make_line(mcs_, target, n_axes_);
    if (seg && seg->length() > 0) {
      c.kind = CommandKind::motion;
      c.segment = *seg;
      c.mapped = false;
      c.limits = motion::path_limits(c.segment, std::span<const motion::AxisDynamics>(rapid_dyn_.data(), n_axes_));
      c.v_cmd_mm_s = c.limits.v_max_mm_s;
      c.exact_stop = true;  // each homing group ends at its reference point
    }
    mcs_ = target;
    (void)out.push_back(c);
    c = Command{};  // the following groups: motion only
    c.file_id = b.file_id;
    c.line = b.line;
    c.emit_block_event = false;
  }
  for (std::size_t j = 0; j < n_axes_; ++j)
    if (b.axes[j]) frames_.preset_axis(j);
  pcs_ = frames_.to_pcs(mcs_);
}

Command Planner::plan_one(const nc::Block& b) {
  modal_ = b.modal;
  if (std::string why = unsupported(b); !why.empty())
    return error_command(ErrorId::KernelNotYetSupported, why + " in this version of nck",
                         b.file_id, b.line);
  if (std::string why = spindle_out_of_scope(b); !why.empty())
    return error_command(ErrorId::SpindleFunctionOutOfScope, why, b.file_id, b.line);
  Command c;
  c.file_id = b.file_id;
  c.line = b.line;
  c.has_n = b.n.has_value();
  c.n = b.n.value_or(0);
  if (!add_outputs(b, c))
    return error_command(ErrorId::KernelQueueOverflow, "more than 8 PLC outputs in one block",
                         b.file_id, b.line);
  Command error;
  if (!check_diameter(b, c, error)) return error;
  if (!apply_frames(b, c, error)) return error;
  modal_.zero_offset = frames_.zero_index();  // what is in force, for --final
  if (!apply_measure_offset(b, c, error)) return error;
  if (std::string why = plc_control_violation(b); !why.empty())
    return error_command(ErrorId::KernelPlcSpindleFunction, why, b.file_id, b.line);
  ErrorId cax_id{};
  if (std::string why = cax_violation(b, cax_id); !why.empty())
    return error_command(cax_id, why, b.file_id, b.line);
  if (!plan_cax(b, c, error)) return error;
  if (auto e = plan_ax_link(b, c)) return *e;
  if (!plan_dist(b, c, error)) return error;
  nc::Block with_slaves_scratch;
  auto actions = spindles_.plan(with_slaves(b, with_slaves_scratch));
  if (!actions) return error_command(actions.error().id, actions.error().message, b.file_id, b.line);
  c.spindle_actions = *actions;
  note_spindle_words(b);
  end_ax_links(b);
  if (auto e = plan_links(b, c)) return *e;
  c.expl_syn = b.hash && std::holds_alternative<nc::ExplSyn>(*b.hash);
  c.get_manual_offsets = b.hash && std::holds_alternative<nc::GetManualOffsets>(*b.hash);
  if (b.manual_g) {
    std::uint32_t mask = 0;
    for (std::size_t j = 0; j < n_axes_; ++j)
      if (b.axes[j]) mask |= 1u << j;
    if (*b.manual_g == nc::GCode::g201) c.manual_on = mask;
    else c.manual_off = mask != 0 ? mask : ~0u;  // G202 without axes: all
  }
  if (b.program_end) {
    c.kind = CommandKind::end;
    c.end_reason = std::find(b.m.begin(), b.m.end(), 2) != b.m.end() ? EndReason::m2 : EndReason::m30;
    return c;
  }
  if (b.stop || b.optional_stop) {
    c.kind = CommandKind::stop;
    c.optional_stop = !b.stop;  // M0 and M1 together: M0 wins
    return c;
  }
  if (b.dwell_s) {
    c.kind = CommandKind::dwell;
    c.dwell_s = std::max(0.0, *b.dwell_s);
    return c;
  }
  if (b.dwell_revs) {
    if (main_spindle_ < 0)
      return error_command(ErrorId::KernelLinkNoSpindle, "G4 S.. counts main-spindle revolutions: the channel has none",
                           b.file_id, b.line);
    c.kind = CommandKind::dwell;
    c.dwell_revs = std::max(0.0, *b.dwell_revs);
    c.dwell_spindle = main_spindle_;
    return c;
  }
  if (b.g_nonmodal.has(nc::GCode::g100)) return plan_measuring_run(b, c);
  // With G201/G202 the axis words select the axes.
  const bool words_are_motion = !b.manual_g && !b.g_nonmodal.has_any(kAxisWordsAreValues);
  const bool circle = b.modal.motion == nc::Motion::cw || b.modal.motion == nc::Motion::ccw;
  if (words_are_motion && (b.has_axis_words() || (circle && (b.ijk[0] || b.ijk[1] || b.ijk[2])))) {
    c.feed_motion = b.modal.motion != nc::Motion::rapid;
    return plan_motion(b, c);
  }
  // P-CHAN-00100 move_tool_offsets_directly 1: a new tool offset is moved
  // with the D word itself (DIN 66025), at rapid.
  if (channel_.move_tool_offsets_directly && (b.d || (b.hash && std::holds_alternative<nc::ToolData>(*b.hash)))) {
    nc::Block move = b;
    move.modal.motion = nc::Motion::rapid;
    move.axes = {};
    return plan_motion(move, c);
  }
  c.kind = CommandKind::nop;
  return c;
}

}  // namespace nck::prep
