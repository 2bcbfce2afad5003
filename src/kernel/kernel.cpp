#include "nck/kernel/kernel.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "channel.hpp"
#include "drive_units.hpp"
#include "plc_outputs.hpp"
#include "spindle_unit.hpp"

namespace nck::kernel {

// An embedder keeps one of each outside the real-time thread's stack
// (docs/embedding.md gives these sizes).
static_assert(sizeof(TickInput) == 24640, "docs/embedding.md gives TickInput's size");
static_assert(sizeof(TickOutput) == 38888, "docs/embedding.md gives TickOutput's size");

namespace {

// A path axis's manual-mode settings: the jog speeds and acceleration its
// list gives (capped by the axis's own a_max and top speed), its software
// limits (none for a modulo axis, which turns endlessly).
JogAxisSettings jog_settings(const config::Machine& m, const config::ChannelAxis& axis) {
  JogAxisSettings s;
  if (axis.axis_index < 0 || static_cast<std::size_t>(axis.axis_index) >= m.axes.size()) return s;
  const config::AxisConfig& ax = m.axes[static_cast<std::size_t>(axis.axis_index)];
  const config::GearStage& g = ax.gear(ax.initial_gear_stage);
  s.speed_mm_s = ax.jog_speed_mm_s;
  s.increment_speed_mm_s = ax.jog_increment_speed_mm_s;
  s.max_speed_mm_s = std::min(ax.manual_max_speed_mm_s, g.max_speed_mm_s);
  s.a_max_mm_s2 = std::min(ax.manual_a_max_mm_s2, g.a_max);
  if (!ax.is_modulo()) {
    s.sw_limit_neg_mm = ax.sw_limit_neg;
    s.sw_limit_pos_mm = ax.sw_limit_pos;
  }
  return s;
}

// G74 of a path axis on a real drive (config::HomingMethod): the cam
// search's directions, speeds (at most vb_max) and acceleration, the
// reference at the cam's edge, and its time.
HomingSearchSettings homing_search_settings(const config::AxisConfig& ax, double cycle_s) {
  const config::GearStage& g = ax.gear(ax.initial_gear_stage);
  HomingSearchSettings s;
  s.method = ax.homing_method();
  s.to_cam = ax.homing_positive ? 1 : -1;
  s.off_cam = static_cast<std::int8_t>(ax.homing_without_reversal ? s.to_cam : -s.to_cam);
  s.fast_mm_s = std::min(g.homing_fast_mm_s, g.max_speed_mm_s);
  s.off_cam_mm_s = std::min(ax.fast_from_cam ? g.homing_fast_mm_s : g.homing_slow_mm_s, g.max_speed_mm_s);
  s.a_mm_s2 = g.homing_accel();
  s.reference_mm = g.reference_pos;
  s.timeout_cycles = static_cast<std::uint32_t>(std::ceil(ax.drive_homing_timeout_s / cycle_s));
  return s;
}

// The path's deceleration under E-stop: the smallest of its axes'
// emergency decelerations (P-AXIS-00003 of the stage in force at start; 0:
// a_max), so that no axis brakes harder than its own whatever the path's
// direction (docs/decisions.md, "E-stop and machine on").
double emergency_decel(const config::Machine& m, const config::ChannelConfig& ch) {
  double a = 0;
  for (const config::ChannelAxis& axis : ch.axes) {
    if (axis.axis_index < 0 || static_cast<std::size_t>(axis.axis_index) >= m.axes.size()) continue;
    const config::AxisConfig& ax = m.axes[static_cast<std::size_t>(axis.axis_index)];
    const config::GearStage& g = ax.gear(ax.initial_gear_stage);
    const double e = g.a_emergency > 0 ? g.a_emergency : g.a_max;
    if (e > 0 && (a == 0 || e < a)) a = e;
  }
  return a;
}

}  // namespace

Kernel::Kernel() = default;
Kernel::~Kernel() = default;
Kernel::Kernel(Kernel&&) noexcept = default;
Kernel& Kernel::operator=(Kernel&&) noexcept = default;

std::expected<void, Diagnostic> Kernel::configure(const config::Machine& machine) {
  auto bad = [](std::string msg) {
    return std::unexpected(make_diagnostic(ErrorId::KernelBadMachine, {"startup.lis", 0, 0}, std::move(msg)));
  };
  if (machine.cycle_time_us == 0) return bad("cycle_time_us must be greater than 0");
  if (machine.channels.size() > config::kMaxChannels)
    return bad(fmt::format("{} channels configured, at most {}", machine.channels.size(), config::kMaxChannels));
  cycle_us_ = machine.cycle_time_us;
  cycle_s_ = machine.cycle_time_us * 1e-6;
  cycles_ = 0;
  time_s_ = 0;
  machine_out_ = MachineOutput{};
  machine_ = std::make_unique<const config::Machine>(machine);
  plc_outputs_ = std::make_unique<PlcOutputs>();
  drive_units_ = std::make_unique<DriveUnits>();
  drive_units_->configure(*machine_, cycle_s_);
  ext_commands_ = plc::ExtCommandQueue{};
  spindle_map_ = plc::build_spindle_map(*machine_);
  if (spindle_map_.count > kMaxMachineSpindles)
    return bad(fmt::format("{} spindles configured, at most {}", spindle_map_.count, kMaxMachineSpindles));

  // One unit per machine spindle, in the HLI map's order.
  spindles_ = std::vector<SpindleUnit>(spindle_map_.count);
  spindle_names_.assign(spindle_map_.count, std::string());
  std::vector<std::vector<std::int8_t>> per_channel(machine_->channels.size());
  for (std::size_t c = 0; c < machine_->channels.size(); ++c) {
    const config::ChannelConfig& ch = machine_->channels[c];
    for (std::size_t i = 0; i < ch.spindles.size(); ++i) {
      const std::int8_t k = spindle_map_.at(c + 1, static_cast<std::int32_t>(i));
      per_channel[c].push_back(k);
      const plc::ChannelSpindleRef here{static_cast<std::uint8_t>(c + 1), static_cast<std::int8_t>(i)};
      if (k < 0 || spindle_map_.first[static_cast<std::size_t>(k)] != here) continue;  // set up by its first listing
      const config::ChannelSpindle& sp = ch.spindles[i];
      const config::AxisConfig* ax =
          sp.axis_index >= 0 ? &machine_->axes[static_cast<std::size_t>(sp.axis_index)] : nullptr;
      SpindleUnit& u = spindles_[static_cast<std::size_t>(k)];
      if (auto ok = u.axis.configure(ax, sp, cycle_s_); !ok) return std::unexpected(ok.error());
      u.plc_spindle = config::is_plc_spindle(*machine_, sp);
      u.channel = static_cast<std::uint8_t>(c + 1);
      u.channel_index = static_cast<std::int8_t>(i);
      if (ax != nullptr && static_cast<std::size_t>(sp.axis_index) < drives::kMaxDrives) {
        u.axis_list = static_cast<std::int16_t>(sp.axis_index);
        if (ax->is_cia402()) u.cia402_axis = u.axis_list;
        if (ax->is_conventional()) u.conventional_axis = u.axis_list;
      }
      u.last_gear = u.axis.status().gear_stage;
      spindle_names_[static_cast<std::size_t>(k)] = sp.name;
    }
  }
  channels_.clear();
  command_queues_.clear();
  feedback_queues_.clear();
  for (std::size_t i = 0; i < machine_->channels.size(); ++i) {
    command_queues_.push_back(std::make_unique<CommandQueue>());
    feedback_queues_.push_back(std::make_unique<FeedbackQueue>());
    channels_.push_back(std::make_unique<Channel>(i, machine_->channels[i].axes.size(), per_channel[i],
                                                  *command_queues_.back(), *feedback_queues_.back()));
    // The C axis (config/c_axis.cpp) is the spindle with the same axis list.
    const config::ChannelConfig& ch = machine_->channels[i];
    channels_.back()->set_preserve_links(ch.preserve_coupling_after_prog_end);
    channels_.back()->set_single_step_mode(ch.single_step_mode);
    channels_.back()->set_rapid_override_mode(ch.rapid_override_mode);
    channels_.back()->setup_technologies(ch, cycle_s_);
    channels_.back()->set_emergency_decel(emergency_decel(*machine_, ch));
    for (std::size_t j = 0; j < ch.axes.size() && j < kMaxAxes; ++j) {
      channels_.back()->set_jog_axis(j, jog_settings(*machine_, ch.axes[j]));
      const int a = ch.axes[j].axis_index;
      if (a >= 0 && machine_->axes[static_cast<std::size_t>(a)].prog_move_requires_homing)
        channels_.back()->homing().require(j, std::nullopt);
      if (a >= 0 && static_cast<std::size_t>(a) < drives::kMaxDrives) {
        channels_.back()->set_machine_axis(j, static_cast<std::int8_t>(a));
        channels_.back()->set_homing_search(j, homing_search_settings(machine_->axes[static_cast<std::size_t>(a)], cycle_s_));
      }
    }
    if (ch.c_axis >= 0)
      for (std::size_t k = 0; k < ch.spindles.size(); ++k)
        if (ch.spindles[k].axis_index == ch.axes[static_cast<std::size_t>(ch.c_axis)].axis_index)
          channels_.back()->set_c_axis(static_cast<std::int8_t>(ch.c_axis), per_channel[i][k]);
  }
  channel_done_.assign(channels_.size(), 0);
  for (std::size_t i = 0; i < channels_.size(); ++i) channel_done_[i] = channels_[i]->done();
  return {};
}

std::size_t Kernel::channel_count() const { return channels_.size(); }
std::size_t Kernel::spindle_count() const { return spindles_.size(); }
const std::string& Kernel::spindle_name(std::size_t index) const { return spindle_names_.at(index); }
int Kernel::spindle_axis_list(std::size_t index) const { return spindles_.at(index).axis_list; }
plc::SpindleStatus Kernel::hli_spindle_status(std::size_t index) const {
  plc::SpindleStatus h;
  fill_hli_status(spindles_.at(index), h);
  return h;
}

const spindle::SpindleStatus& Kernel::spindle_status(std::size_t index) const {
  return spindles_.at(index).axis.status();
}
const plc::SpindleMap& Kernel::spindle_map() const { return spindle_map_; }
const std::string& Kernel::axis_name(std::size_t index) const {
  static const std::string none;
  return machine_ ? config::axis_list_name(*machine_, index) : none;
}

std::vector<std::uint32_t> Kernel::active_links(std::size_t ch) const {
  std::vector<std::uint32_t> out;
  channels_.at(ch)->for_each_link([&](std::uint32_t payload) { out.push_back(payload); });
  return out;
}


void Kernel::start_channel_at(std::size_t ch, const motion::AxisVector& path_mcs) {
  channels_.at(ch)->start_at(path_mcs);
}

void Kernel::set_homed_axes(std::size_t ch, std::uint32_t mask) noexcept {
  if (ch < channels_.size()) channels_[ch]->homing().set_homed(mask);
}

std::uint32_t Kernel::homed_axes(std::size_t ch) const noexcept {
  return ch < channels_.size() ? channels_[ch]->homing().homed() : 0u;
}

void Kernel::name_unhomed_axis(std::size_t ch, std::size_t j, std::uint32_t message) {
  HomingUnit& h = channels_.at(ch)->homing();
  if (j < kMaxAxes && (h.required() >> j & 1u)) h.require(j, message);
}

ChannelState Kernel::channel_state(std::size_t ch) const {
  const Channel& c = *channels_.at(ch);
  const DistUnit& dist = c.technologies().get<DistUnit>();
  return ChannelState{c.position(),      c.manual_offsets(),
                      c.machine_position(), c.status(),
                      c.program_state(), c.at(),
                      dist.state(), dist.offset_mm(),
                      c.homing().homed(), c.homing().required()};
}

void Kernel::tick(const TickInput& in, TickOutput& out) noexcept {
  const double t_s = time_s_;
  out.t_s = t_s;
  out.events.clear();
  out.events_dropped = 0;
  out.tech_outputs.clear();
  take_acknowledgements(in, t_s, out);
  take_spindle_controls(in);
  take_spindle_measured(in);
  take_external_commands(in, t_s, out);
  run_external_commands(t_s, out);
  ChannelContext ctx{spindles_.data(), spindles_.size(), plc_outputs_.get(), &in.spindles};
  ctx.estop = in.machine.estop;
  ctx.machine_off = !in.machine.machine_on;
  ctx.drives_enabled = machine_out_.drives_enabled;
  ctx.axes = &in.axes;
  ctx.drive_feedback = &in.drives;
  if (drive_units_ && !drive_units_->empty()) {
    for (const ChannelInput& c : in.channels)
      if (c.reset) drive_units_->on_reset();
    ctx.drives = drive_units_->step(in, out, machine_out_.drives_enabled);
    take_drive_homing(in);
  }
  for (std::size_t i = 0; i < channels_.size(); ++i) {
    channels_[i]->tick(t_s, cycle_s_, in.channels[i], out.channels[i], out, ctx);
    channel_done_[i] = channels_[i]->done();  // only a tick changes it
  }
  tick_spindles(t_s, out);
  follow_machine(in, t_s, out);
  if (drive_units_ && !drive_units_->empty()) write_drive_set_points(in, out);
  ++cycles_;
  time_s_ = static_cast<double>(cycles_ * cycle_us_) / 1e6;
}

ProgramState Kernel::program_state(std::size_t ch) const noexcept {
  return ch < channels_.size() ? channels_[ch]->program_state() : ProgramState::idle;
}

bool Kernel::channel_jogging(std::size_t ch) const noexcept {
  return ch < channels_.size() && channels_[ch]->jogging();
}

bool Kernel::all_channels_done() const noexcept {
  for (const auto& c : channels_)
    if (!c->done()) return false;
  return true;
}

}  // namespace nck::kernel
