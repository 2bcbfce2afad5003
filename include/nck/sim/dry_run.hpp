#pragma once
// A whole dry run, as `nck run`, the tests and the benchmarks drive it: per
// channel a block preparation (nck/prep) feeding the kernel through its
// queues, the kernel, and the simulated machine around it (MachineSim).
//
//   run.prepare();        // setup side: decode and plan what fits (allocates)
//   run.cycle(out);       // rt: sim.read -> kernel.tick -> sim.write
//
// With DryRunOptions::prep_thread, preparation runs in a thread of its own
// (PrepThread) and prepare() only waits until it has caught up, so the
// outputs stay those of the single thread; the two share only the kernel's
// SPSC queues, the plan store's append-only logs and a few atomics.
#include <atomic>
#include <cstdint>
#include <expected>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "nck/config/machine.hpp"
#include "nck/core/axes.hpp"
#include "nck/core/diagnostic.hpp"
#include "nck/kernel/kernel.hpp"
#include "nck/nc/modal.hpp"
#include "nck/prep/run_records.hpp"
#include "nck/sim/scenario.hpp"
#include "nck/prep/channel_prep.hpp"
#include "nck/prep/plan_store.hpp"
#include "nck/sim/machine_sim.hpp"
#include "nck/sim/operator_action.hpp"
#include "nck/sim/prep_thread.hpp"

namespace nck::sim {

struct DryRunOptions {
  std::uint32_t clamp_index = 0;  // clamp-offset group at program start (--clamp-index)
  bool record_frames = false;     // blocks carry their program -> machine map (--report)
  bool prep_thread = false;       // preparation in a thread of its own (--prep-thread)
  const std::atomic<bool>* stop = nullptr;  // stops decoding at once when set (prep::PrepOptions::stop)
  // Block search (nck run --start-at, a scenario's block_search line): the
  // program of channel `search_channel` (0-based) runs without motion up to
  // the mark, then returns to the contour.
  std::optional<prep::SearchMark> search;
  std::size_t search_channel = 0;
  // nck serve: the folders every file a program opens must lie in (empty: any).
  std::vector<std::filesystem::path> allowed_roots;
  bool record_modal = false;  // with record_frames: the modal state of each block (nck serve)
  // Block-skip levels per channel at program start (the HLI's; nck serve keeps the operator's).
  std::array<std::uint32_t, config::kMaxChannels> skip_masks{};
  // Where each channel's axes stand at program start (nck serve: where the
  // last run, a jog or MDI left them); none: the machine's start position.
  std::array<std::optional<motion::AxisVector>, config::kMaxChannels> start_mcs{};
  // Which path axes of each channel are homed at program start (bit j =
  // axis j); none: all, the operator homed the machine (nck run without
  // --unhomed). nck serve starts with none homed and keeps what G74 homed.
  std::array<std::optional<std::uint32_t>, config::kMaxChannels> homed_axes{};
};

// What a channel knows about its programmed state, for --final.
struct ChannelSnapshot {
  AxisArray axis_mcs{};
  AxisArray axis_pcs{};
  // every active offset: kind -> per-axis values
  std::vector<std::pair<std::string, std::vector<std::pair<std::string, double>>>> offsets;
  nc::ModalState modal;
  kernel::ChannelStatus status = kernel::ChannelStatus::idle;
};

class DryRun final : public prep::RunRecords {
 public:
  // setup: programs[i] runs in channel i; channels without one stay idle.
  static std::expected<DryRun, Diagnostic> create(const config::Machine& m,
                                                  const std::vector<std::filesystem::path>& programs,
                                                  const DryRunOptions& options = {});
  ~DryRun();
  DryRun(DryRun&&) noexcept;
  DryRun& operator=(DryRun&&) noexcept;

  // setup: the --plc scenario; it must stay alive while the run goes on.
  void load_scenario(const sim::Scenario& scenario) { sim_->load_scenario(scenario); }

  // setup side: every channel's preparation decodes and plans what fits
  // (with prep_thread: waits until the preparation thread has caught up).
  // Inline up to the test that nothing changed: most cycles end there.
  void prepare() {
    if (!threaded_ && quiet()) return;
    prepare_now();
  }
  // rt: one cycle of the simulated machine and the kernel.
  void cycle(kernel::TickOutput& out) noexcept;
  // A live kernel's preparation (nck serve): as prepare(), but never waits
  // for the preparation thread (the kernel's braking reserve covers a late
  // one). Does nothing until start_preparation_thread() (setup side, once
  // this object stays where it is) has started it.
  void prepare_live();
  void start_preparation_thread();
  // Both, as a dry run does them every cycle.
  void step(kernel::TickOutput& out) {
    prepare();
    cycle(out);
  }

  // Ends the preparation thread (if any): call before reading prep(ch),
  // snapshot() or anything else preparation owns. The destructor does it.
  void stop_preparation();

  // Channel ch holds at this mark for the caller (nck run --stop-at).
  void set_stop_at(std::size_t ch, const kernel::StopMark& mark) noexcept { sim_->set_stop_at(ch, mark); }
  // Every channel that has a program has ended, and (when the scenario
  // types MDI) no MDI text is still to come or to run.
  bool done() const noexcept;
  // MDI lines the scenario typed while their channel could not take them
  // (930710) or that a reset discarded (930712), since the last call; the
  // caller reports them.
  struct Refusal {
    std::uint8_t channel = 1;
    Diagnostic diagnostic;
  };
  bool has_refusals() const noexcept { return !refusals_.empty(); }
  std::vector<Refusal> take_refusals() { return std::exchange(refusals_, {}); }
  // Any thread (nck serve's, while this run runs): channel ch's zero-offset
  // list was edited; blocks preparation decodes from now on select from it.
  void offer_zero_offsets(std::size_t ch, const config::ZeroOffsets& zero);
  // An operator's action (the Python session; from the thread that runs
  // the cycles): MDI text goes to its channel's preparation when the
  // channel may take it, the rest to the simulated machine's next cycle.
  // The refusal, if any (930710 MDI while a program runs, 960042 too many
  // at once).
  std::optional<Diagnostic> operate(const OperatorAction& op);
  // MDI text for channel ch (0-based) whose program state is `st`, or why
  // it is refused. Reads nothing the cycles write: a live kernel's server
  // thread calls it with the state the kernel last published. `queue`: a
  // text typed while another runs waits for it (the scenario, Python);
  // without it such a text is refused (nck serve unless asked).
  std::optional<Diagnostic> mdi(std::size_t ch, const std::string& text, kernel::ProgramState st,
                                const SourceLoc& loc, bool queue = true);
  // Every channel still running holds (M0/M1) and nothing will release it:
  // no automatic cycle start, no scenario line still to come.
  bool held_for_good() const noexcept;
  double time_s() const noexcept { return kernel_->time_s(); }
  // Between runs of a live session (at a cycle boundary, before this run's
  // first cycle): each channel's axes homed as in run `before`. rt
  void carry_homing(const DryRun& before) noexcept;

  std::size_t channel_count() const { return preps_.size(); }
  const prep::ChannelPrep& prep(std::size_t ch) const { return preps_.at(ch); }
  const kernel::Kernel& kernel() const { return *kernel_; }
  // The machine this run was made with (its own copy: later edits of the server's do not reach it).
  const config::Machine& config() const override { return *machine_; }
  const MachineSim& machine() const { return *sim_; }
  MachineSim& machine() { return *sim_; }
  ChannelSnapshot snapshot(std::size_t ch) const;
  // What events name (prep::RunRecords): files, spindles, the plan store.
  const nc::Decoder* decoder(std::size_t ch) const override { return ch < preps_.size() ? preps_[ch].decoder() : nullptr; }
  const std::string* spindle_name(std::size_t index) const override {
    return index < kernel_->spindle_count() ? &kernel_->spindle_name(index) : nullptr;
  }
  // setup: watches channel ch's decoded blocks (the report's programmed contour).
  void observe(std::size_t ch, prep::PrepObserver* o) { preps_.at(ch).set_observer(o); }

 private:
  DryRun() = default;
  const prep::PlanStore& store() const override { return *store_; }

  std::unique_ptr<const config::Machine> machine_;
  std::unique_ptr<kernel::Kernel> kernel_;
  std::unique_ptr<MachineSim> sim_;
  std::unique_ptr<prep::PlanStore> store_;
  std::vector<prep::ChannelPrep> preps_;
  // Each channel's queues in the kernel (it owns them; their addresses stay).
  struct ChannelQueues {
    kernel::CommandQueue* commands;
    kernel::FeedbackQueue* feedback;
  };
  std::vector<ChannelQueues> queues_;
  void prepare_now();
  static void name_unhomed_axes(DryRun& run, std::size_t ch);
  // Preparation has nothing to do now: no MDI line, no skip levels to hand
  // over, and in each channel nothing changed since a call that did nothing,
  // or its queue still holds more than the kernel looks ahead (as the
  // preparation thread keeps it). Refilling in bursts of a few blocks, not
  // one block each time the kernel takes one, keeps the cycle's code in the
  // instruction cache across cycles and the decoder's across blocks.
  bool quiet() const noexcept {
    if (!sim_->mdi_requests().empty() || sim_->skip_levels_used()) return false;
    for (bool r : reset_seen_)
      if (r) return false;
    for (std::size_t ch = 0; ch < queues_.size(); ++ch) {
      const ChannelQueues& q = queues_[ch];
      const bool ahead = q.commands->size() > kernel::kMaxLookAheadDepth && q.feedback->empty();
      if (!ahead && !preps_[ch].idle(*q.commands, *q.feedback, kernel_->channel_done(ch))) return false;
    }
    return true;
  }
  std::unique_ptr<kernel::TickInput> in_;
  bool threaded_ = false;
  std::vector<Refusal> refusals_;
  // Per channel: the kernel took a reset in the last cycle (set by cycle(),
  // taken by take_resets()); the channel brakes after a reset until done.
  std::array<bool, config::kMaxChannels> reset_seen_{}, braking_{};
  // setup side: a reset drops the MDI texts typed before it.
  void take_resets();
  // setup side: hands the MDI lines that came due to preparation.
  void submit_mdi();
  void feed_preparation_thread();
  void switch_sensors_on();
  std::unique_ptr<PrepThread> prep_thread_;  // last: ends before what it uses
};

}  // namespace nck::sim
