#include "hal/cycle.hpp"

#include <fmt/format.h>

#include "nck/config/load.hpp"
#include "nck/core/diagnostic.hpp"
#include "nck/drives/cia402.hpp"

namespace nck::hal {

bool Cycle::build(Link& link, std::string& error) {
  if (link.magic != kLinkMagic || link.version != kLinkVersion || link.pack_bytes.load() == 0) {
    error = fmt::format("{}: no machine in shared memory; load nck-hal first (loadusr -W nck-hal MACHINE PROGRAM)",
                        static_cast<std::uint32_t>(ErrorId::HalNoMachinePack));
    return false;
  }
  link_ = &link;
  auto pack = std::make_shared<const ListPack>(read_pack(link));
  config::LoadOptions options;
  // The pack's paths are the folder's as nck-hal read them; nothing is read from disk here.
  options.read_text = [pack](const std::filesystem::path& p) -> std::optional<std::string> {
    auto it = pack->find(p.string());
    if (it == pack->end()) return std::nullopt;
    return it->second;
  };
  const auto folder_it = pack->find("");
  const std::filesystem::path folder = folder_it == pack->end() ? std::filesystem::path() : std::filesystem::path(folder_it->second);
  auto loaded = config::load_machine(folder, options);
  if (!loaded.ok()) {
    std::string first;
    for (const Diagnostic& d : loaded.diagnostics.items())
      if (d.severity == Severity::error) {
        first = fmt::format(": {} {}", static_cast<std::uint32_t>(d.id), d.message);
        break;
      }
    error = fmt::format("{}: the packed machine does not load{}", static_cast<std::uint32_t>(ErrorId::HalMachineInvalid), first);
    return false;
  }
  machine_ = std::make_unique<config::Machine>(std::move(*loaded.machine));
  if (auto ok = kernel_.configure(*machine_); !ok) {
    error = fmt::format("{}: {}", static_cast<std::uint32_t>(ErrorId::HalMachineInvalid), ok.error().message);
    return false;
  }
  // A machine switched on is not homed (P-AXIS-00277; G74 homes its axes).
  for (std::size_t ch = 0; ch < machine_->channels.size(); ++ch) kernel_.set_homed_axes(ch, 0u);
  in_ = std::make_unique<kernel::TickInput>();
  out_ = std::make_unique<kernel::TickOutput>();
  for (std::size_t ch = 0; ch < machine_->channels.size(); ++ch) {
    const auto& axes = machine_->channels[ch].axes;
    for (std::size_t j = 0; j < axes.size() && j < kMaxAxes; ++j) {
      const int index = axes[j].axis_index;
      const bool listed = index >= 0 && static_cast<std::size_t>(index) < drives::kMaxDrives;
      const config::AxisConfig* ax = listed ? &machine_->axes[static_cast<std::size_t>(index)] : nullptr;
      const bool talks = ax != nullptr && (ax->is_cia402() || ax->is_conventional());
      axes_.push_back({ch, j, axes[j].name, talks ? index : -1, ax != nullptr && ax->is_cia402(), listed ? index : -1});
    }
  }
  for (auto& s : plc_slots_) s.handle = plc::kNoHandle;
  link.rt_state.store(static_cast<std::uint32_t>(RtState::configured));
  return true;
}

void Cycle::fail(std::uint32_t id) noexcept {
  failed_ = true;
  **machine_pins.error = true;
  **machine_pins.error_id = id;
  for (const auto& a : axis_pins) **a.enable = false;
  link_->rt_error_id.store(id);
  link_->rt_state.store(static_cast<std::uint32_t>(RtState::error));
}

void Cycle::run(long period_ns) noexcept {
  watchdog_ = !watchdog_;
  **machine_pins.watchdog = watchdog_;
  if (failed_) return;
  // The kernel's time advances by the machine's cycle per tick: a thread of
  // another period would run it faster or slower than the machine.
  if (period_ns != static_cast<long>(machine_->cycle_time_us) * 1000) {
    fail(static_cast<std::uint32_t>(ErrorId::HalPeriodMismatch));
    return;
  }
  link_->rt_state.store(static_cast<std::uint32_t>(RtState::running), std::memory_order_relaxed);
  read_pins();
  read_drives();
  relay_commands();
  out_->tech_outputs.clear();
  out_->events.clear();
  out_->events_dropped = 0;
  tick_timed();
  write_pins();
  publish_state();
  show_nc_error();
  hand_to_plc();
  for (const auto& e : out_->events) {
    if (e.channel > 0 && e.at.line > 0 && e.channel <= channel_pins.size())
      **channel_pins[e.channel - 1u].block_line = static_cast<std::int32_t>(e.at.line);
    ask_for_index(e);
    note_plc_spindle_done(e);
    if (!link_->events.push(e)) link_->events_dropped.fetch_add(1, std::memory_order_relaxed);
  }
  if (out_->events_dropped) link_->events_dropped.fetch_add(out_->events_dropped, std::memory_order_relaxed);
  for (std::size_t ch = 0; ch < channel_count(); ++ch) {
    auto& fb = kernel_.feedback(ch);
    while (!fb.empty() && link_->feedback[ch].push(fb.front())) fb.pop();
    link_->channel_done[ch].store(kernel_.channel_done(ch) ? 1 : 0, std::memory_order_release);
  }
  link_->cycles.store(kernel_.cycles(), std::memory_order_release);
  **machine_pins.cycles = static_cast<std::uint32_t>(kernel_.cycles());
}

// One Kernel::tick(), timed when the clocks are there: the tick's own
// clocks, and the clock rate from the first timed cycle to this one.
void Cycle::tick_timed() noexcept {
  if (!clocks.clocks || !clocks.ns || !machine_pins.tick_time) {
    kernel_.tick(*in_, *out_);
    return;
  }
  const long long before = clocks.clocks();
  kernel_.tick(*in_, *out_);
  const long long after = clocks.clocks();
  **machine_pins.tick_time = static_cast<std::int32_t>(after - before);
  const long long now_ns = clocks.ns();
  if (first_ns_ == 0) {
    first_ns_ = now_ns;
    first_clocks_ = after;
  } else if (now_ns > first_ns_) {
    **machine_pins.clocks_per_us = static_cast<double>(after - first_clocks_) * 1e3 / static_cast<double>(now_ns - first_ns_);
  }
}

// The CiA 402 drives' statuswords and actual values, as the drive sent
// them after the last cycle.
namespace {

// A CiA 402 drive's words and actual velocity, in and out (its positions
// are the caller's: an axis's pos-* pins, a spindle's drive-pos-*).
void read_words(const CiaPins& c, drives::DriveFeedback& fb) noexcept {
  fb.statusword = static_cast<std::uint16_t>(**c.statusword);
  fb.mode_display = static_cast<std::int8_t>(**c.opmode_display);
  fb.fault = (fb.statusword & drives::cia402::sw::fault) != 0;
  fb.actual_vel = **c.vel_fb;
}
void write_words(const drives::DriveCommand& d, const CiaPins& c) noexcept {
  **c.controlword = d.controlword;
  **c.opmode = d.mode_of_operation;
  **c.vel_cmd = d.target_vel;
}

}  // namespace

void Cycle::read_drives() noexcept {
  for (std::size_t i = 0; i < axes_.size() && i < cia_pins.size(); ++i) {
    if (axes_[i].drive < 0) continue;
    const CiaPins& c = cia_pins[i];
    drives::DriveFeedback& fb = in_->drives[static_cast<std::size_t>(axes_[i].drive)];
    fb.actual_pos = **axis_pins[i].pos_fb;
    if (!axes_[i].cia402) continue;  // a conventional drive reports its position only
    read_words(c, fb);
    fb.following_error = **axis_pins[i].following_error;
  }
  for (const SpindleDrivePins& p : spindle_drive_pins) {
    if (!p.cia402) continue;  // a conventional spindle measures through speed-in / revs
    drives::DriveFeedback& fb = in_->drives[static_cast<std::size_t>(p.drive)];
    read_words(p.words, fb);
    fb.actual_pos = **p.pos_fb;
  }
}

void Cycle::read_pins() noexcept {
  // The kernel brakes, refuses starts and disables the drives itself
  // (TickInput::machine); a reset after the E-stop's release is the
  // channel's reset pin.
  in_->machine.estop = **machine_pins.estop;
  in_->machine.machine_on = **machine_pins.machine_on;
  in_->acks.clear();
  in_->ext_commands.clear();
  in_->ext_commands_lost = 0;
  // The kernel brakes on an amplifier fault or a limit switch itself, and
  // G74 searches the home switch (TickInput::axes).
  for (std::size_t i = 0; i < axes_.size() && i < axis_pins.size(); ++i) {
    if (axes_[i].machine < 0) continue;
    const AxisPins& p = axis_pins[i];
    kernel::AxisSwitches& s = in_->axes[static_cast<std::size_t>(axes_[i].machine)];
    s.amp_fault = **p.amp_fault;
    s.pos_limit = **p.limit_pos;
    s.neg_limit = **p.limit_neg;
    s.home_cam = **p.home_sw;
  }
  take_api_actions();
  for (std::size_t ch = 0; ch < channel_count(); ++ch) {
    const ChannelPins& p = channel_pins[ch];
    kernel::ChannelInput& c = in_->channels[ch];
    // Buttons act on their rising edge (a held cycle start is one press).
    const bool start = **p.cycle_start, reset = **p.reset;
    c.cycle_start = start && !cycle_start_was_[ch];
    c.reset = reset && !reset_was_[ch];
    cycle_start_was_[ch] = start;
    reset_was_[ch] = reset;
    c.feedhold = **p.feedhold;
    c.single_step = **p.single_step;
    c.optional_stop = **p.optional_stop;
    c.feed_override_pct = **p.feed_override;
    c.rapid_override_pct = **p.rapid_override;
    c.stop = false;  // the API's NC stop only
    api_[ch].merge_into(c);
    link_->skip_mask[ch].store(api_[ch].skip_mask(**p.skip_mask), std::memory_order_relaxed);
  }
  for (std::size_t s = 0; s < spindle_pins.size(); ++s) {
    const SpindlePins& p = spindle_pins[s];
    spindle::DriveFeedback& f = in_->spindle_measured[s];
    f.valid = **p.feedback_valid;
    f.actual_speed_deg_s = **p.speed_in_rpm * 6.0;  // rpm -> deg/s
    f.actual_pos_deg = **p.revolutions * 360.0;
    f.index_reset_pending = p.index_wired() && **p.index_enable;
    if (p.axis_list >= 0) in_->axes[static_cast<std::size_t>(p.axis_list)].amp_fault = **p.amp_fault;
    plc::SpindleControl& c = in_->spindles[s];
    if (p.override_pct) {  // a test's cells may leave them out
      c.override_percent = **p.override_pct;
      c.feedhold = **p.feedhold;
      c.stop_at_program_end = **p.stop_at_end;
      const bool reset = **p.reset;  // a button: one request per press
      c.reset = reset && !spindle_reset_was_[s];
      spindle_reset_was_[s] = reset;
    }
    api_spindles_[s].merge_into(c);
  }
  take_plc_spindle_commands();
  for (std::size_t k = 0; k < kPlcSlots; ++k) {
    const PlcPins& p = plc_pins[k];
    kernel::TechRequest& slot = plc_slots_[k];
    // The rising edge acknowledges: an ack still high from the slot's last
    // function does not acknowledge the next one.
    const bool ack = **p.ack, rose = ack && !ack_was_[k];
    ack_was_[k] = ack;
    if (slot.handle == plc::kNoHandle || !rose) continue;
    (void)in_->acks.push_back(plc::PlcAck{slot.handle, slot.output, kernel_.time_s()});
    slot.handle = plc::kNoHandle;
    **p.request = false;
  }
}

// The operator's actions from nck-hal's API (only with --serve: the queue
// stays empty otherwise), each to its channel's controls.
void Cycle::take_api_actions() noexcept {
  for (auto& q = link_->api_actions; !q.empty(); q.pop()) {
    const sim::ScenarioAction& a = q.front();
    if (a.channel >= 1 && a.channel <= channel_count()) api_[a.channel - 1u].take(a);
    const sim::act::SpindleRef* s = nullptr;
    if (const auto* o = a.get<sim::act::SpindleOverride>()) s = &o->spindle;
    if (const auto* f = a.get<sim::act::SpindleFeedhold>()) s = &f->spindle;
    if (s && s->hli >= 0 && static_cast<std::size_t>(s->hli) < api_spindles_.size())
      api_spindles_[static_cast<std::size_t>(s->hli)].take(a);
  }
}

// With nck-hal --serve: the state after this cycle, for its API's state
// document (a copy into the triple buffer's free slot).
void Cycle::publish_state() noexcept {
  if (link_->serving.load(std::memory_order_relaxed) == 0) return;
  app::LiveSnapshot& s = link_->state.back();
  app::fill_kernel_snapshot(kernel_, *out_, s);
  for (std::size_t ch = 0; ch < s.channel_count && ch < s.channels.size(); ++ch)
    s.channels[ch].hli = shown_controls(in_->channels[ch], link_->skip_mask[ch].load(std::memory_order_relaxed));
  for (std::size_t i = 0; i < s.spindle_count && i < s.spindle_override_pct.size(); ++i)
    s.spindle_override_pct[i] = in_->spindles[i].effective_override_percent();
  s.speed = 1;
  link_->state.publish();
}

// Moves what nck-hal queued into the kernel's queues while they have room:
// the kernel's look-ahead sees what it holds, the shared queue is the buffer.
void Cycle::relay_commands() noexcept {
  for (std::size_t ch = 0; ch < channel_count(); ++ch) {
    kernel::CommandQueue& from = link_->commands[ch];
    kernel::CommandQueue& to = kernel_.commands(ch);
    while (!from.empty() && to.free_slots() > 0) {
      const kernel::Command& c = from.front();
      if (to.free_attachment_slots() < c.attachments || c.attachments > attachments_.size()) break;
      for (std::size_t i = 0; i < c.attachments; ++i) attachments_[i] = from.attachment(i);
      (void)to.push(c, std::span<const kernel::Attachment>(attachments_.data(), c.attachments));
      from.pop();
    }
  }
}

// The PLC's spindle commands (FCT-S1 2.9): a rising request hands the
// command over to the spindle's channel (the one that lists it first);
// an M function other than 3, 4, 5, 19 is no command.
void Cycle::take_plc_spindle_commands() noexcept {
  const plc::SpindleMap& map = kernel_.spindle_map();
  for (std::size_t s = 0; s < plc_command_pins.size() && s < plc_request_was_.size(); ++s) {
    const PlcSpindleCommandPins& p = plc_command_pins[s];
    const bool request = **p.request, rose = request && !plc_request_was_[s];
    plc_request_was_[s] = request;
    const std::int32_t m = **p.m;
    if (!rose || (m != 3 && m != 4 && m != 5 && m != 19)) continue;
    if (s >= map.count) continue;
    plc::ExtSpindleCommand c;  // to the first channel that lists the spindle
    c.channel = map.first[s].channel;
    c.spindle = map.first[s].index;
    c.fn = static_cast<plc::ExtFunction>(m);
    c.has_rev = **p.rpm > 0;
    c.rev_rpm = c.has_rev ? **p.rpm : 0.0;
    c.has_pos = m == 19;
    c.pos_deg = **p.pos_deg;
    **p.done = false;
    plc_command_pending_[s] = true;
    if (!in_->ext_commands.push_back(c)) ++in_->ext_commands_lost;
  }
}

// The kernel acknowledges a PLC spindle command as done (speed reached,
// standstill, in position) with a plc_ack event naming the spindle.
void Cycle::note_plc_spindle_done(const kernel::Event& e) noexcept {
  const auto* a = e.get<kernel::ev::PlcAck>();
  if (!a || !a->spindle || *a->spindle < 0 || static_cast<std::size_t>(*a->spindle) >= plc_command_pins.size()) return;
  const auto s = static_cast<std::size_t>(*a->spindle);
  if (!plc_command_pending_[s]) return;  // the PLC's acknowledgement of a program's M function
  plc_command_pending_[s] = false;
  **plc_command_pins[s].done = true;
}

// G33 waits for a spindle's zero mark: its encoder (index-enable netted)
// resets its count at the next index pulse, which is the zero mark.
void Cycle::ask_for_index(const kernel::Event& e) noexcept {
  const auto* w = e.get<kernel::ev::Wait>();
  if (!w || w->reason != kernel::WaitReason::zero_mark || !w->spindle || *w->spindle < 0) return;
  const auto s = static_cast<std::size_t>(*w->spindle);
  if (s < spindle_pins.size() && spindle_pins[s].index_wired()) **spindle_pins[s].index_enable = true;
}

// nck.error / nck.error-id while nck.cycle runs: on with the last NC error
// (an amplifier fault, a limit switch, a drive's fault ...) as long as a
// channel is in error, off again after its reset. A stop of nck.cycle
// itself (fail) keeps its own ID for good.
void Cycle::show_nc_error() noexcept {
  for (const kernel::Event& e : out_->events)
    if (const auto* x = e.get<kernel::ev::Error>()) nc_error_id_ = static_cast<std::uint32_t>(x->id);
  bool in_error = false;
  for (std::size_t ch = 0; ch < channel_count(); ++ch)
    in_error = in_error || out_->channels[ch].program_state == kernel::ProgramState::error;
  if (!in_error) nc_error_id_ = 0;
  **machine_pins.error = nc_error_id_ != 0;
  **machine_pins.error_id = nc_error_id_;
}

void Cycle::write_pins() noexcept {
  const bool on = out_->machine.drives_enabled;
  for (std::size_t i = 0; i < axes_.size(); ++i) {
    const AxisRef& a = axes_[i];
    const AxisPins& p = axis_pins[i];
    const double cmd = out_->channels[a.channel].drive_pos(a.axis);  // what homing set included
    **p.pos_cmd = cmd;
    **p.following_error = cmd - **p.pos_fb;
    **p.enable = on;
    **p.homed = (out_->channels[a.channel].homed_axes >> a.axis & 1u) != 0;
    if (a.drive < 0 || i >= cia_pins.size()) continue;
    const drives::DriveCommand& d = out_->drives[static_cast<std::size_t>(a.drive)];
    const CiaPins& c = cia_pins[i];
    **p.enable = on && d.enable;
    if (a.cia402) write_words(d, c);
    else **c.vel_cmd = d.target_vel;  // a conventional drive: the velocity set point only
  }
  for (std::size_t ch = 0; ch < channel_count(); ++ch) {
    const kernel::ChannelOutput& o = out_->channels[ch];
    const ChannelPins& p = channel_pins[ch];
    **p.program_state = static_cast<std::int32_t>(o.program_state);
    **p.status = static_cast<std::int32_t>(o.status);
    **p.path_velocity = o.path_velocity_mm_s;
    **p.done = kernel_.channel_done(ch);
  }
  for (std::size_t s = 0; s < spindle_pins.size(); ++s) {
    const SpindlePins& p = spindle_pins[s];
    **p.speed_cmd_rpm = out_->spindles[s].set_rpm;
    **p.pos_cmd_deg = out_->spindles[s].set_pos_deg;
    **p.at_speed = out_->hli_spindles[s].speed_reached;
    **p.homed = kernel_.spindle_status(s).homed;
    **p.orient = kernel_.spindle_status(s).mode == spindle::SpindleMode::position;
  }
  for (const SpindleDrivePins& p : spindle_drive_pins) {
    if (p.drive < 0) continue;
    const drives::DriveCommand& d = out_->drives[static_cast<std::size_t>(p.drive)];
    if (!p.cia402) {
      **p.words.vel_cmd = d.target_vel;  // a conventional drive: the velocity set point only
      continue;
    }
    write_words(d, p.words);
    **p.pos_cmd = d.target_pos;
  }
}

// Each technology function the kernel hands out takes a free slot until the
// PLC acknowledges it; with no slot free it is an error (never a hang).
void Cycle::hand_to_plc() noexcept {
  for (const kernel::TechRequest& r : out_->tech_outputs) {
    std::size_t k = 0;
    while (k < kPlcSlots && plc_slots_[k].handle != plc::kNoHandle) ++k;
    if (k == kPlcSlots) {
      fail(static_cast<std::uint32_t>(ErrorId::HalPlcSlotsFull));
      return;
    }
    plc_slots_[k] = r;
    const PlcPins& p = plc_pins[k];
    **p.kind = static_cast<std::int32_t>(r.output.kind);
    **p.number = r.output.number;
    **p.channel = r.output.channel;
    **p.value = r.output.value;
    **p.request = true;
  }
}

}  // namespace nck::hal
