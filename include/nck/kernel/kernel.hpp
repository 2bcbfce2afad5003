#pragma once
// The kernel: configured once (may allocate, may fail), then run cycle by
// cycle through tick(), which never allocates, throws, locks, does I/O or
// reads a clock: time comes in with the cycle count.
//
// Blocks reach a channel through push_block() outside the cycle (the
// decoder's work is not real-time); the channel consumes them from a
// fixed-size queue in tick().
#include <cstdint>
#include <expected>
#include <memory>
#include <string>
#include <vector>

#include "nck/config/machine.hpp"
#include "nck/core/diagnostic.hpp"
#include "nck/kernel/tick_io.hpp"
#include "nck/nc/block.hpp"
#include "nck/plc/hli.hpp"
#include "nck/plc/scenario.hpp"
#include "nck/spindle/spindle_status.hpp"

namespace nck::kernel {

class Channel;
struct SpindleUnit;
struct KernelPlc;
struct PlanStore;
struct OffsetPayload;

struct KernelOptions {
  std::uint32_t clamp_index = 0;  // clamp-offset group at program start (pzv_grp[i])
};

// What a channel knows about its programmed state, for --final.
struct ChannelSnapshot {
  AxisArray axis_mcs{};
  AxisArray axis_pcs{};
  // every active offset: kind -> per-axis values
  std::vector<std::pair<std::string, std::vector<std::pair<std::string, double>>>> offsets;
  nc::ModalState modal;
  ChannelStatus status = ChannelStatus::idle;
};

class Kernel {
 public:
  Kernel();
  ~Kernel();
  Kernel(Kernel&&) noexcept;
  Kernel& operator=(Kernel&&) noexcept;

  // setup: builds channels, limits and queues from the machine.
  std::expected<void, Diagnostic> configure(const config::Machine& machine,
                                            const KernelOptions& options = {});

  std::size_t channel_count() const;
  // The machine's spindles (a spindle shared by channels is one), in the
  // order of plc::build_spindle_map.
  std::size_t spindle_count() const;
  const std::string& spindle_name(std::size_t index) const;
  const spindle::SpindleStatus& spindle_status(std::size_t index) const;
  // The HLI image as the PLC sees it (status written every cycle).
  const plc::HliImage& hli() const;
  // setup: a PLC scenario (--plc); it must stay alive while the kernel runs.
  void load_scenario(const plc::Scenario& scenario);
  double cycle_time_s() const { return cycle_s_; }

  // setup side (not real-time) -------------------------------------------
  // Free places in channel ch's block queue (ch 0-based).
  std::size_t queue_space(std::size_t ch) const;
  // Plans a decoded block for channel ch. Planning errors (e.g. a circle
  // whose end point is not on it) become an error the channel raises when it
  // reaches that block. file_name names the block's file for messages.
  void push_block(std::size_t ch, const nc::Block& block, const std::string& file_name);
  // The decoder stopped with an error: the channel raises it after the blocks
  // already queued.
  void push_error(std::size_t ch, const Diagnostic& d, std::uint16_t file_id);
  // The decoder reached the end of the program without M2/M30.
  void push_end_without_m30(std::size_t ch, std::uint16_t file_id, std::uint32_t line);
  // Blocks after which the decoder needs values from execution: a G100
  // measuring run and #GET MANUAL OFFSETS. The caller holds the channel's
  // later blocks back until sync_count(ch) has grown, then takes the values.
  static bool needs_sync(const nc::Block& b);
  std::uint64_t sync_count(std::size_t ch) const;
  // The decoder variables (V.A.MESS/MERF/MOFFS.<axis> after G100 — planning
  // then goes on from where the axes stopped —, V.A.MANUAL_OFFSETS.<axis>).
  std::vector<std::pair<std::string, double>> take_sync_values(std::size_t ch);
  // Text of an event's message_index (error, warning).
  const std::string& message(std::uint32_t index) const;
  // Kind and per-axis values of an offset event's message_index.
  const OffsetPayload& offset(std::uint32_t index) const;
  ChannelSnapshot snapshot(std::size_t ch) const;

  // real-time side -------------------------------------------------------
  void tick(const TickInput& in, TickOutput& out) noexcept;

  bool all_channels_done() const noexcept;
  bool channel_done(std::size_t ch) const noexcept;
  std::uint64_t cycles() const noexcept { return cycles_; }
  // Simulated time at the start of the next cycle.
  double time_s() const noexcept { return static_cast<double>(cycles_ * cycle_us_) / 1e6; }

 private:
  void tick_plc(double t_s, TickOutput& out) noexcept;
  void tick_external_commands(double t_s, TickOutput& out) noexcept;
  void tick_spindles(double t_s, TickOutput& out) noexcept;

  std::unique_ptr<const config::Machine> machine_;  // own copy: channels refer into it
  std::vector<SpindleUnit> spindles_;
  std::vector<std::string> spindle_names_;
  std::unique_ptr<KernelPlc> plc_;
  std::vector<std::unique_ptr<Channel>> channels_;
  std::unique_ptr<PlanStore> store_;
  double cycle_s_ = 0.001;
  std::uint64_t cycle_us_ = 1000;
  std::uint64_t cycles_ = 0;
};

}  // namespace nck::kernel
