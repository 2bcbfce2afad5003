#pragma once
// A channel's block preparation (setup side: may allocate, never called from
// tick()): decoder -> look-ahead window -> planner -> the channel's command
// queue, and the feedback queue back into the decoder's variables.
//
// Threading contract: a ChannelPrep and its PlanStore belong to one thread
// (the "prep thread"); the kernel's tick() runs in another (or the same).
// They share only the two SPSC queues of nck/kernel/queues.hpp: this class is
// the only producer of commands and the only consumer of feedback.
#include <atomic>
#include <cstdint>
#include <deque>
#include <mutex>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "nck/config/machine.hpp"
#include "nck/core/diagnostic.hpp"
#include "nck/kernel/queues.hpp"
#include "nck/nc/block.hpp"
#include "nck/nc/decoder.hpp"
#include "nck/prep/block_search.hpp"
#include "nck/prep/lookahead_window.hpp"
#include "nck/prep/plan_store.hpp"
#include "nck/prep/prep_observer.hpp"
#include "nck/prep/radius_comp.hpp"

namespace nck::prep {

class Planner;

struct PrepOptions {
  std::uint32_t clamp_index = 0;  // clamp-offset group at program start (pzv_grp[i], --clamp-index)
  // Each command carries its block's program -> machine map (PlanStore::frames)
  // into the block event: the report's program-coordinate backplot.
  bool record_frames = false;
  // Set by the caller to stop decoding within one block read (SIGINT, SIGTERM,
  // --max-wall): feed() then returns and decodes nothing more. Not owned.
  const std::atomic<bool>* stop = nullptr;
  // Block search: the program runs without motion up to this mark, then
  // returns to the contour (block_search.hpp).
  std::optional<SearchMark> search;
  // nck serve: the folders every file the program opens must lie in (nc::DecoderConfig::allowed_roots).
  std::vector<std::filesystem::path> allowed_roots;
  // With record_frames: each map comes with the modal state (PlanStore::frame_modals).
  bool record_modal = false;
};

class ChannelPrep {
 public:
  // setup: program empty = the channel has no program and stays idle.
  ChannelPrep(const config::Machine& m, std::size_t ch, const std::filesystem::path& program,
              PlanStore& store, const PrepOptions& options);
  ~ChannelPrep();
  ChannelPrep(ChannelPrep&&) noexcept;
  ChannelPrep& operator=(ChannelPrep&&) noexcept;

  // Decodes and plans while the command queue has room, until the program
  // ends or a block needs feedback from execution (G100, #GET MANUAL
  // OFFSETS); takes that feedback when it has come. channel_done: the
  // channel ended (no feedback will come any more). Returns whether it did
  // anything (decoded, took feedback or handed commands over): a call that
  // did nothing will do nothing again until the kernel has run a cycle.
  bool feed(kernel::CommandQueue& commands, kernel::FeedbackQueue& feedback, bool channel_done);
  // True when feed() would return at once: nothing changed since a call
  // that did nothing. Inline: most cycles of a dry run end here (the
  // kernel takes one block while it runs for many cycles).
  bool idle(const kernel::CommandQueue& commands, const kernel::FeedbackQueue& feedback, bool channel_done) const {
    return idle_ && idle_->free_slots == commands.free_slots() && idle_->channel_done == channel_done &&
           feedback.empty() && !(!in_mdi_ && done() && mdi_pending()) &&
           !zero_inbox_->offered.load(std::memory_order_acquire);
  }
  // Plans one decoded block into the queue through the window (feed() uses
  // it; tests call it with blocks of their own). False when the queue has
  // no room for it.
  bool prepare(const nc::Block& b, kernel::CommandQueue& commands);

  bool has_program() const { return has_program_; }
  // MDI (from any thread): blocks the operator typed, prepared once all
  // before them is (after the program end, or at once in a channel without
  // a program) with the modal state, offsets and tool where they are. Each
  // text ends with a command that returns the channel to idle; an error
  // ends its text, never the channel.
  void submit_mdi(std::string text);
  // Any thread: a reset drops the texts submitted before it that preparation
  // has not begun (the one it prepares ends when it takes the kernel's stop).
  // Returns how many.
  std::size_t discard_mdi();
  // MDI text submitted and not yet all handed over (any thread).
  bool mdi_pending() const { return mdi_->pending.load(std::memory_order_acquire) > 0; }
  // Some MDI text was submitted in this run.
  bool mdi_used() const { return mdi_->used.load(std::memory_order_acquire); }
  // Any thread: the zero-offset list was edited while the program runs
  // (nck serve). Blocks decoded from now on select from it, as ISG takes a
  // new value at the offset's next selection; preparation runs ahead of
  // the kernel, so a selection it has already decoded keeps the old value.
  void offer_zero_offsets(config::ZeroOffsets zero);
  // The HLI's block-skip levels (/1 = 0x1 ... /10 = 0x200): blocks decoded
  // from now on skip by them.
  void set_skip_mask(std::uint32_t mask) noexcept {
    if (decoder_) decoder_->set_skip_mask(mask);
  }
  // Everything up to the program end (or the error that stopped decoding)
  // is in the command queue.
  bool done() const { return done_ && window_.empty() && backlog_.empty(); }
  // Planning waits for feedback from execution (a G100 result ...).
  bool awaiting_feedback() const { return awaiting_feedback_; }
  // Corner blending so far (G61/G261): fillets placed, path length they cut.
  const BlendStats& blend_stats() const { return window_.blend_stats(); }
  const nc::Decoder* decoder() const { return decoder_ ? &*decoder_ : nullptr; }
  const Planner& planner() const { return *planner_; }
  // setup: the program starts where the axes stand (a live session's new
  // run after the last one, a jog or MDI moved them).
  void start_at(const motion::AxisVector& path_mcs);

  // setup: watches every decoded block (nullptr: none); it must outlive the run.
  void set_observer(PrepObserver* o) { observer_ = o; }

  // Does executing b produce feedback that later blocks may read?
  static bool needs_feedback(const nc::Block& b);

 private:
  void feed_blocks(kernel::CommandQueue& commands, kernel::FeedbackQueue& feedback, bool channel_done);
  void take_block(const nc::Block& b, kernel::CommandQueue& commands);
  void hand_over(const PlannedCommand& c, kernel::CommandQueue& commands);
  bool push_out(kernel::CommandQueue& commands);
  void collect_warnings();
  void attach_warnings(PlannedCommand& c);
  // Plans what tool radius compensation handed out, into the window or,
  // while it is full, the backlog (one block may become several).
  // Plans one block (or the error raised in its place) and queues it; false
  // when an MDI error ended the MDI (nothing after it is planned).
  bool plan_out(const nc::Block& block, bool inserted, const std::optional<Diagnostic>& error,
                kernel::CommandQueue& commands);
  bool drain_backlog(kernel::CommandQueue& commands);
  // Into the window, or the backlog while the window is full.
  void queue(const PlannedBlock& planned, kernel::CommandQueue& commands);
  // Block search: a planned block is searched, or restarts the real run.
  void search_out(const nc::Block& block, const PlannedBlock& planned, kernel::CommandQueue& commands);
  void search_not_found(const nc::Block& end, kernel::CommandQueue& commands);
  // MDI: starts the next text once everything before it is prepared; ends
  // one (the command that returns the channel to idle).
  void take_stop(kernel::FeedbackQueue& feedback);
  void start_mdi();
  void finish_mdi(kernel::CommandQueue& commands);
  void mark_mdi(PlannedBlock& b) const;

  std::optional<nc::Decoder> decoder_;
  std::unique_ptr<Planner> planner_;
  LookAheadWindow window_;
  std::vector<TrcOut> trc_outs_;  // what radius compensation hands on for one block
  RadiusComp trc_;
  std::vector<PlannedBlock> backlog_;  // planned, waiting for room in the window
  std::optional<SearchRun> search_;    // while a block search runs
  bool has_program_ = false;
  // MDI texts submitted (by any thread), and whether one is being prepared.
  struct MdiInbox {
    std::mutex mutex;
    std::deque<std::string> texts;
    std::atomic<std::size_t> pending{0};  // texts submitted, not yet all handed over
    std::atomic<bool> used{false};
  };
  std::unique_ptr<MdiInbox> mdi_ = std::make_unique<MdiInbox>();
  // A zero-offset list offered by another thread, taken before decoding.
  struct ZeroOffsetInbox {
    std::mutex mutex;
    config::ZeroOffsets zero;
    std::atomic<bool> offered{false};
  };
  std::unique_ptr<ZeroOffsetInbox> zero_inbox_ = std::make_unique<ZeroOffsetInbox>();
  void take_zero_offsets();
  bool in_mdi_ = false;
  // The kernel's `stopped` records taken: stamped on every MDI command
  // (kernel::CommandHead::stops_taken).
  std::uint8_t stops_taken_ = 0;
  // The window must empty into the queue (program end, an error, a block
  // whose feedback later blocks need) before anything else is decoded.
  bool flushing_ = false;
  // Decoder warnings not yet handed over: they ride on the next command
  // (raised when it starts, with its block), never beside the queue.
  std::vector<Diagnostic> pending_warnings_;
  std::size_t diagnostics_seen_ = 0;
  bool done_ = false;
  bool awaiting_feedback_ = false;
  std::uint64_t decoded_ = 0;  // decoder calls and feedback taken (feed()'s progress)
  // What the kernel's side looked like after a feed() that did nothing.
  struct Idle {
    std::size_t free_slots = 0;
    bool channel_done = false;
    bool operator==(const Idle&) const = default;
  };
  std::optional<Idle> idle_;
  std::uint32_t last_main_line_ = 0;  // of the main program's last block decoded
  PlanStore* store_ = nullptr;
  bool record_frames_ = false;  // and the last map put there:
  bool record_modal_ = false;   // with the modal state
  std::uint32_t frame_index_ = kernel::kNoMessage;
  std::uint64_t frame_changes_ = 0;  // ChannelFrames::changes() when frame_index_ was put there
  PrepObserver* observer_ = nullptr;
  std::uint32_t frame_index_now();
};

}  // namespace nck::prep
