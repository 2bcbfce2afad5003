// Spindle planning, the per-command part: which main function a spindle
// command carries (M19 > M3/M4/M5 > S), what it does in the planned state,
// and in which order its actions execute. Synchronisation mapping, gear
// selection and tool dynamics are in spindle_planner_rules.cpp.
#include "nck/prep/spindle_planner.hpp"

#include <cmath>
#include <utility>

#include <fmt/format.h>

namespace nck::prep {
namespace {

using nc::SpindleM;

Diagnostic diag(const nc::Block& b, const nc::SpindleCommand& c, ErrorId id, std::string msg) {
  return make_diagnostic(id, {"", b.line, c.column}, std::move(msg));
}

std::uint32_t bits_for(const config::ChannelSpindle& sp, SpindleM m) {
  switch (m) {
    case SpindleM::m3: return sp.m3_sync;
    case SpindleM::m4: return sp.m4_sync;
    case SpindleM::m5: return sp.m5_sync;
    case SpindleM::m19: return sp.m19_sync;
    default: return sp.s_sync;
  }
}

double timeout_for(const config::ChannelSpindle& sp, SpindleM m) {
  switch (m) {
    case SpindleM::m3: return sp.m3_ack_timeout_s;
    case SpindleM::m4: return sp.m4_ack_timeout_s;
    case SpindleM::m5: return sp.m5_ack_timeout_s;
    case SpindleM::m19: return sp.m19_ack_timeout_s;
    default: return sp.s_ack_timeout_s;
  }
}

spindle::Direction direction_of(SpindleM m) {
  if (m == SpindleM::m3) return spindle::Direction::positive;
  if (m == SpindleM::m4) return spindle::Direction::negative;
  return spindle::Direction::none;
}

// Output and wait as the deciding function's sync bits say. A PLC spindle
// outputs everything and the PLC acknowledgement is its only wait; without a
// synchronisation point nothing waits at all.
void synchronise(SpindleAction& a, std::uint32_t bits, SyncPoint point, SpindleWait wait,
                 double timeout_s, bool plc) {
  a.sync_bits = bits;
  a.sync = point;
  a.output = plc || (bits & config::sync::PLC_INFO) != 0;
  a.wait = (plc || point == SyncPoint::none) ? SpindleWait::none : wait;
  a.ack_timeout_s = timeout_s;
}

// An action that is neither output nor waited for (G74, G130, G135...).
SpindleAction plain(std::int8_t spindle, SpindleOp op) {
  SpindleAction a;
  a.spindle = spindle;
  a.op = op;
  a.fn = TechKind::s;
  return a;
}

bool finite_or_absent(const std::optional<double>& v) { return !v || std::isfinite(*v); }

std::expected<void, Diagnostic> check_values(const nc::Block& b, const nc::SpindleCommand& c) {
  if (finite_or_absent(c.rev_rpm) && finite_or_absent(c.pos_deg) &&
      finite_or_absent(c.pos_shift_deg) && finite_or_absent(c.g130_pct) &&
      finite_or_absent(c.g136_pct))
    return {};
  return std::unexpected(diag(b, c, ErrorId::SpindleBadValue,
                              fmt::format("{}: a speed, position or percentage is not a finite "
                                          "number; program a finite value",
                                          c.name)));
}

}  // namespace

SpindlePlanner::SpindlePlanner(const config::Machine& m, std::size_t channel_index,
                               std::vector<int> kernel_index)
    : machine_(m), kernel_index_(std::move(kernel_index)) {
  if (channel_index < m.channels.size()) channel_ = &m.channels[channel_index];
  if (channel_index < m.channel_data.size()) data_ = &m.channel_data[channel_index];
  reset();
}

void SpindlePlanner::reset() {
  state_.clear();
  if (!channel_) return;
  for (const auto& sp : channel_->spindles) {
    PlannedSpindle p;
    if (sp.axis_index >= 0 && static_cast<std::size_t>(sp.axis_index) < machine_.axes.size()) {
      const std::uint32_t g = machine_.axes[static_cast<std::size_t>(sp.axis_index)].initial_gear_stage;
      p.gear_stage = (g >= 1 && g <= config::kMaxGearStages) ? g : 1;
    }
    state_.push_back(p);
  }
}

std::expected<SpindleActions, Diagnostic> SpindlePlanner::plan(const nc::Block& b) {
  SpindleActions out;
  // The block is all or nothing: plan on a copy, keep it only on success.
  std::vector<PlannedSpindle> st = state_;
  if (auto r = plan_tool(b, out); !r) return std::unexpected(r.error());
  for (const auto& c : b.spindles)
    if (auto r = plan_command(b, c, st, out); !r) return std::unexpected(r.error());
  state_ = std::move(st);
  return out;
}

namespace {

// S alone. Whether it changes the running speed or only stores it depends
// on what the spindle is really doing when the block executes, which
// preparation cannot know (a PLC command, another channel, a PLC reset may
// come first): the kernel decides (speed_change_rpm). G167 without a speed
// only suspends the override.
std::optional<SpindleAction> speed_only(const nc::SpindleCommand& c, const config::ChannelSpindle& sp,
                                        std::int8_t kidx, bool plc, const PlannedSpindle& st) {
  if (!c.rev_rpm) {
    if (!c.g167) return std::nullopt;
    SpindleAction g = plain(kidx, SpindleOp::suppress_override);
    g.g167 = true;
    return g;
  }
  SpindleAction a = plain(kidx, SpindleOp::speed);
  a.g167 = c.g167;
  a.rpm = *st.speed_rpm;
  const std::optional<SyncPoint> s_point = sync_point(sp.s_sync);
  synchronise(a, sp.s_sync, s_point.value_or(SyncPoint::none), SpindleWait::speed_reached,
              sp.s_ack_timeout_s, plc);
  if (!s_point) a.output = false;
  return a;
}

// The function that decides this command (M19 > M3/M4/M5 > S) and what it
// does in the planned state. Empty when the command moves nothing (POS alone,
// M3 with NO_SYNCH and no S, ...). Updates the planned state.
std::expected<std::optional<SpindleAction>, Diagnostic> main_action(const nc::Block& b,
                                                                   const nc::SpindleCommand& c,
                                                                   const config::ChannelSpindle& sp,
                                                                   std::int8_t kidx, bool plc,
                                                                   PlannedSpindle& st) {
  SpindleM m = c.m;
  std::optional<SyncPoint> point;
  if (m != SpindleM::none) {
    point = sync_point(bits_for(sp, m));
    if (!point) m = SpindleM::none;  // NO_SYNCH: the M function is not executed (docs/parameters.md)
  }
  // S / REV, POS and POS_SHIFT are modal whatever the function does (S with M5 is kept).
  if (c.rev_rpm) {
    st.speed_rpm = std::fabs(*c.rev_rpm);
    st.signed_speed_rpm = *c.rev_rpm;
  }
  if (c.pos_deg) st.pos_deg = *c.pos_deg;
  if (c.pos_shift_deg) st.pos_shift_deg = *c.pos_shift_deg;

  SpindleAction a;
  a.spindle = kidx;
  a.g167 = c.g167;
  a.fn = TechKind::m;
  a.fn_number = static_cast<std::int32_t>(m);
  const std::uint32_t bits = bits_for(sp, m);
  const double timeout_s = timeout_for(sp, m);
  switch (m) {
    case SpindleM::m19:
      if (!st.speed_rpm || *st.speed_rpm <= 0)
        return std::unexpected(diag(b, c, ErrorId::KernelSpindleM19NoSpeed,
                                    fmt::format("{}: M19 without speed; program a positioning "
                                                "speed with or before M19 (e.g. {})",
                                                c.name,
                                                c.din ? fmt::format("M19 {}200", c.name)
                                                      : fmt::format("{}[M19 REV200]", c.name))));
      a.op = SpindleOp::position;
      a.pos_deg = st.pos_deg.value_or(0) + st.pos_shift_deg;
      a.rpm = *st.speed_rpm;
      a.direction = direction_of(c.direction);
      synchronise(a, bits, *point, SpindleWait::in_position, timeout_s, plc);
      return a;
    case SpindleM::m3:
    case SpindleM::m4: {
      // TF5200 M03/M04: a rotation starts only with a valid speed. Without one
      // the direction is selected at 0 rpm, so that a later S turns the
      // spindle that way (seed FCT-S1 2.5.2, second synchronisation example).
      const double rpm = st.speed_rpm.value_or(0.0);
      a.op = SpindleOp::rotate;
      a.direction = direction_of(m);
      a.rpm = m == SpindleM::m3 ? rpm : -rpm;
      synchronise(a, bits, *point, SpindleWait::speed_reached, timeout_s, plc);
      return a;
    }
    case SpindleM::m5:
      a.op = SpindleOp::stop;
      synchronise(a, bits, *point, SpindleWait::standstill, timeout_s, plc);
      return a;
    default: break;
  }
  return speed_only(c, sp, kidx, plc, st);
}

}  // namespace

std::expected<void, Diagnostic> SpindlePlanner::plan_command(const nc::Block& b,
                                                            const nc::SpindleCommand& c,
                                                            std::vector<PlannedSpindle>& st,
                                                            SpindleActions& out) const {
  const auto idx = find_spindle(c);
  const int kidx = idx && *idx < kernel_index_.size() ? kernel_index_[*idx] : -1;
  if (!idx || kidx < 0 || kidx > 127 || *idx >= st.size())
    return std::unexpected(diag(b, c, ErrorId::KernelSpindleUnknown,
                                fmt::format("spindle '{}' is not a spindle of this channel; program "
                                            "one of the channel list's spindel[i].bezeichnung",
                                            c.target.empty() ? c.name : c.target)));
  if (auto r = check_values(b, c); !r) return r;
  const config::ChannelSpindle& sp = channel_->spindles[*idx];
  Step s{b, c, sp, static_cast<std::int8_t>(kidx), config::is_plc_spindle(machine_, sp), st[*idx], out};
  // The main action is decided first (the gear change before it needs its speed).
  auto main = main_action(b, c, sp, s.kernel_spindle, s.plc, s.st);
  if (!main) return std::unexpected(main.error());
  const bool moves = *main && ((*main)->op == SpindleOp::rotate || (*main)->op == SpindleOp::position ||
                               (*main)->op == SpindleOp::speed);
  auto push = [&](const SpindleAction& a) -> std::expected<void, Diagnostic> {
    if (out.push_back(a)) return {};
    return std::unexpected(diag(b, c, ErrorId::KernelSpindleTooManyActions,
                                fmt::format("more than {} spindle actions in one block; split the "
                                            "spindle commands over several blocks",
                                            PlannedCommand::kMaxSpindleActions)));
  };
  std::expected<void, Diagnostic> r;
  if (c.default_dynamic_data) r = push(plain(s.kernel_spindle, SpindleOp::default_dynamic_data));
  if (r && c.get_dynamic_data) r = push(plain(s.kernel_spindle, SpindleOp::get_dynamic_data));
  if (r && c.g112_stage) {
    if (*c.g112_stage < 1 || *c.g112_stage > static_cast<int>(config::kMaxGearStages))
      return std::unexpected(diag(b, c, ErrorId::SpindleGearStageInvalid,
                                  fmt::format("G112 {}{}: the gear stage must be 1..6", c.name,
                                              *c.g112_stage)));
    SpindleAction a = plain(s.kernel_spindle, SpindleOp::load_gear_data);
    a.stage = static_cast<std::uint32_t>(*c.g112_stage);
    s.st.gear_stage = a.stage;  // the data record in force is what gear selection starts from
    r = push(a);
  }
  if (r) r = plan_gear(s, moves ? std::optional<double>(std::fabs((*main)->rpm)) : std::nullopt);
  if (r && c.g130_pct) {
    SpindleAction a = plain(s.kernel_spindle, SpindleOp::accel_weight);
    a.value = *c.g130_pct;
    r = push(a);
  }
  if (r && c.g135) r = push(plain(s.kernel_spindle, SpindleOp::feedforward_on));
  if (r && c.g137) r = push(plain(s.kernel_spindle, SpindleOp::feedforward_off));
  if (r && c.g136_pct) {
    SpindleAction a = plain(s.kernel_spindle, SpindleOp::feedforward_weight);
    a.value = *c.g136_pct;
    r = push(a);
  }
  if (r && c.g74) r = push(plain(s.kernel_spindle, SpindleOp::home));
  if (r && *main) r = push(**main);
  auto user = [&](TechKind fn, int n) {
    SpindleAction a = plain(s.kernel_spindle, SpindleOp::user_function);
    a.fn = fn;
    a.fn_number = n;
    synchronise(a, config::sync::MOS, SyncPoint::none, SpindleWait::none, 0, true);
    return push(a);
  };
  for (int n : c.user_m)
    if (r) r = user(TechKind::m, n);
  for (int n : c.user_h)
    if (r) r = user(TechKind::h, n);
  return r;
}

}  // namespace nck::prep
