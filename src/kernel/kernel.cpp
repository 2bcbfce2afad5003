#include "nck/kernel/kernel.hpp"

#include <fmt/format.h>

#include "channel.hpp"
#include "nck/kernel/plan_store.hpp"

namespace nck::kernel {

Kernel::Kernel() = default;
Kernel::~Kernel() = default;
Kernel::Kernel(Kernel&&) noexcept = default;
Kernel& Kernel::operator=(Kernel&&) noexcept = default;

std::expected<void, Diagnostic> Kernel::configure(const config::Machine& machine,
                                                  const KernelOptions& options) {
  if (machine.cycle_time_us == 0)
    return std::unexpected(make_diagnostic(ErrorId::KernelNotYetSupported, {"startup.lis", 0, 0},
                                           "cycle_time_us must be greater than 0"));
  if (machine.channels.size() > config::kMaxChannels)
    return std::unexpected(make_diagnostic(
        ErrorId::KernelNotYetSupported, {"startup.lis", 0, 0},
        fmt::format("{} channels configured, at most {}", machine.channels.size(), config::kMaxChannels)));
  cycle_us_ = machine.cycle_time_us;
  cycle_s_ = machine.cycle_time_us * 1e-6;
  channels_.clear();
  machine_ = std::make_unique<const config::Machine>(machine);
  store_ = std::make_unique<PlanStore>();
  cycles_ = 0;
  const PlannerOptions planner_options{options.clamp_index};
  for (std::size_t i = 0; i < machine.channels.size(); ++i)
    channels_.push_back(std::make_unique<Channel>(*machine_, i, *store_, planner_options));
  return {};
}

std::size_t Kernel::channel_count() const { return channels_.size(); }

std::size_t Kernel::queue_space(std::size_t ch) const { return channels_.at(ch)->queue_space(); }

void Kernel::push_block(std::size_t ch, const nc::Block& block, const std::string& file_name) {
  Channel& c = *channels_.at(ch);
  c.push(c.planner().plan(block, file_name));
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
  for (std::size_t j = 0; j < c.planner().axis_count(); ++j) {
    s.axis_mcs[j] = c.position()[j];
    s.axis_pcs[j] = pcs[j];
  }
  for (const frames::OffsetEntry& e : f.active())
    s.offsets.emplace_back(std::string(frames::to_string(e.kind)), f.values_of(e.kind, false));
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
  for (std::size_t i = 0; i < channels_.size(); ++i)
    channels_[i]->tick(t_s, cycle_s_, in.channels[i], out.channels[i], out);
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
