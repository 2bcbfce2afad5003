#include "nck/kernel/kernel.hpp"

#include <algorithm>
#include <fmt/format.h>

#include "channel.hpp"
#include "kernel_plc.hpp"
#include "nck/kernel/plan_store.hpp"
#include "spindle_planner.hpp"
#include "spindle_unit.hpp"

namespace nck::kernel {

Kernel::Kernel() = default;
Kernel::~Kernel() = default;
Kernel::Kernel(Kernel&&) noexcept = default;
Kernel& Kernel::operator=(Kernel&&) noexcept = default;

std::expected<void, Diagnostic> Kernel::configure(const config::Machine& machine,
                                                  const KernelOptions& options) {
  auto bad = [](std::string msg) {
    return std::unexpected(make_diagnostic(ErrorId::KernelBadMachine, {"startup.lis", 0, 0}, std::move(msg)));
  };
  if (machine.cycle_time_us == 0) return bad("cycle_time_us must be greater than 0");
  if (machine.channels.size() > config::kMaxChannels)
    return bad(fmt::format("{} channels configured, at most {}", machine.channels.size(), config::kMaxChannels));
  cycle_us_ = machine.cycle_time_us;
  cycle_s_ = machine.cycle_time_us * 1e-6;
  cycles_ = 0;
  machine_ = std::make_unique<const config::Machine>(machine);
  store_ = std::make_unique<PlanStore>();
  plc_ = std::make_unique<KernelPlc>(*machine_);
  if (plc_->map.count > kMaxMachineSpindles)
    return bad(fmt::format("{} spindles configured, at most {}", plc_->map.count, kMaxMachineSpindles));

  // One unit per machine spindle, in the HLI map's order.
  spindles_ = std::vector<SpindleUnit>(plc_->map.count);
  spindle_names_.assign(plc_->map.count, std::string());
  std::vector<std::vector<std::int8_t>> per_channel(machine_->channels.size());
  for (std::size_t c = 0; c < machine_->channels.size(); ++c) {
    const config::ChannelConfig& ch = machine_->channels[c];
    for (std::size_t i = 0; i < ch.spindles.size(); ++i) {
      const std::int8_t k = plc_->map.at(c + 1, static_cast<std::int32_t>(i));
      per_channel[c].push_back(k);
      if (k < 0 || !spindle_names_[static_cast<std::size_t>(k)].empty()) continue;
      const config::ChannelSpindle& sp = ch.spindles[i];
      const config::AxisConfig* ax =
          sp.axis_index >= 0 ? &machine_->axes[static_cast<std::size_t>(sp.axis_index)] : nullptr;
      SpindleUnit& u = spindles_[static_cast<std::size_t>(k)];
      if (auto ok = u.axis.configure(ax, sp, machine_->sim, cycle_s_); !ok) return std::unexpected(ok.error());
      u.plc_spindle = detail::is_plc_spindle(*machine_, sp);
      u.channel = static_cast<std::uint8_t>(c + 1);
      u.channel_index = static_cast<std::int8_t>(i);
      u.last_gear = u.axis.status().gear_stage;
      spindle_names_[static_cast<std::size_t>(k)] = sp.name;
    }
  }
  channels_.clear();
  const PlannerOptions planner_options{options.clamp_index};
  for (std::size_t i = 0; i < machine_->channels.size(); ++i)
    channels_.push_back(std::make_unique<Channel>(*machine_, i, *store_, planner_options, per_channel[i]));
  return {};
}

std::size_t Kernel::channel_count() const { return channels_.size(); }
std::size_t Kernel::spindle_count() const { return spindles_.size(); }
const std::string& Kernel::spindle_name(std::size_t index) const { return spindle_names_.at(index); }
const spindle::SpindleStatus& Kernel::spindle_status(std::size_t index) const {
  return spindles_.at(index).axis.status();
}

const plc::HliImage& Kernel::hli() const { return plc_->hli; }

void Kernel::load_scenario(const plc::Scenario& scenario) {
  plc_->player = plc::ScenarioPlayer(scenario);
}

std::size_t Kernel::queue_space(std::size_t ch) const { return channels_.at(ch)->queue_space(); }

void Kernel::push_block(std::size_t ch, const nc::Block& block, const std::string& file_name) {
  Channel& c = *channels_.at(ch);
  for (const Command& cmd : c.planner().plan(block, file_name)) c.push(cmd);
}

void Kernel::push_error(std::size_t ch, const Diagnostic& d, std::uint16_t file_id) {
  Channel& c = *channels_.at(ch);
  c.push(c.planner().error_command(d.id, d.message, file_id, d.loc.line));
}

void Kernel::push_end_without_m30(std::size_t ch, std::uint16_t file_id, std::uint32_t line) {
  Channel& c = *channels_.at(ch);
  c.push(c.planner().error_command(ErrorId::KernelMissingProgramEnd,
                                   "the program has no M30 (or M2) at its end", file_id, line));
}

bool Kernel::needs_sync(const nc::Block& b) {
  return b.g_nonmodal.has(nc::GCode::g100) ||
         (b.hash && std::holds_alternative<nc::GetManualOffsets>(*b.hash));
}

std::uint64_t Kernel::sync_count(std::size_t ch) const { return channels_.at(ch)->sync_count(); }

std::vector<std::pair<std::string, double>> Kernel::take_sync_values(std::size_t ch) {
  Channel& c = *channels_.at(ch);
  if (c.last_sync_was_measure()) return c.planner().take_measurement();
  std::vector<std::pair<std::string, double>> vars;
  for (std::size_t j = 0; j < c.planner().axis_count(); ++j)
    vars.emplace_back("V.A.MANUAL_OFFSETS." + c.planner().frames().axis_name(j), c.manual_offsets()[j]);
  return vars;
}

const std::string& Kernel::message(std::uint32_t index) const {
  static const std::string none;
  return store_ && index < store_->messages.size() ? store_->messages[index] : none;
}

const OffsetPayload& Kernel::offset(std::uint32_t index) const {
  static const OffsetPayload none;
  return store_ && index < store_->offsets.size() ? store_->offsets[index] : none;
}

ChannelSnapshot Kernel::snapshot(std::size_t ch) const {
  const Channel& c = *channels_.at(ch);
  ChannelSnapshot s;
  const ChannelFrames& f = c.planner().frames();
  const motion::AxisVector pcs = f.to_pcs(c.position());
  const motion::AxisVector mcs = c.machine_position();
  std::vector<std::pair<std::string, double>> manual;
  bool any_manual = false;
  for (std::size_t j = 0; j < c.planner().axis_count(); ++j) {
    s.axis_mcs[j] = mcs[j];
    s.axis_pcs[j] = pcs[j];
    manual.emplace_back(f.axis_name(j), c.manual_offsets()[j]);
    any_manual = any_manual || c.manual_offsets()[j] != 0;
  }
  for (const frames::OffsetEntry& e : f.active())
    s.offsets.emplace_back(std::string(frames::to_string(e.kind)), f.values_of(e.kind, false));
  if (any_manual) s.offsets.emplace_back("manual", std::move(manual));
  s.modal = c.planner().modal();
  s.status = c.status();
  return s;
}

void Kernel::tick(const TickInput& in, TickOutput& out) noexcept {
  // From integer microseconds, so times print as the decimals they are.
  const double t_s = static_cast<double>(cycles_ * cycle_us_) / 1e6;
  out.t_s = t_s;
  out.events.clear();
  out.events_dropped = 0;
  tick_plc(t_s, out);
  tick_external_commands(t_s, out);
  ChannelContext ctx{spindles_.data(), spindles_.size(), &plc_->sim, &plc_->hli};
  for (std::size_t i = 0; i < channels_.size(); ++i) {
    // The integrator's inputs and the HLI's act together.
    plc::ChannelControl& hc = plc_->hli.channel[i];
    ChannelInput ci = in.channels[i];
    ci.feed_override_pct = ci.feed_override_pct * hc.feed_override_percent / 100.0;
    ci.feedhold = ci.feedhold || hc.feedhold;
    ci.reset = ci.reset || hc.reset;
    hc.reset = false;
    channels_[i]->tick(t_s, cycle_s_, ci, out.channels[i], out, ctx);
  }
  tick_spindles(t_s, out);
  ++cycles_;
}

bool Kernel::channel_done(std::size_t ch) const noexcept {
  return ch < channels_.size() && channels_[ch]->done();
}

bool Kernel::all_channels_done() const noexcept {
  for (const auto& c : channels_)
    if (!c->done()) return false;
  return true;
}

}  // namespace nck::kernel
