#include "nck/prep/channel_prep.hpp"

#include <algorithm>
#include <cassert>

#include "nck/plc/hli.hpp"
#include "nck/prep/assumed_feedback.hpp"
#include "nck/prep/decoder_setup.hpp"
#include "nck/prep/error_command.hpp"
#include "nck/prep/planner.hpp"

namespace nck::prep {

ChannelPrep::ChannelPrep(const config::Machine& m, std::size_t ch, const std::filesystem::path& program,
                         PlanStore& store, const PrepOptions& options)
    : planner_(std::make_unique<Planner>(m, ch, store, PlannerOptions{options.clamp_index},
                                         kernel_spindles(m, ch))),
      window_(std::min<std::size_t>(m.channels[ch].lookahead_blocks, kernel::kMaxLookAheadDepth),
              m.cycle_time_us * 1e-6),
      trc_(m, ch),
      store_(&store),
      record_frames_(options.record_frames),
      record_modal_(options.record_modal) {
  window_.set_blend_axes(planner_->blend_axes());
  nc::DecoderConfig cfg = decoder_config(m, ch);
  cfg.stop = options.stop;
  cfg.allowed_roots = options.allowed_roots;
  has_program_ = !program.empty();
  done_ = !has_program_;  // a channel without a program waits for MDI
  if (has_program_) decoder_.emplace(program, std::move(cfg));
  else decoder_.emplace(std::move(cfg));
  // The planner lives on the heap, so the pointer survives moves of this object.
  decoder_->set_kernel_state_reader(planner_.get());
  for (const auto& [name, value] : initial_variables(m, ch, options.clamp_index))
    (void)decoder_->set_variable(name, value);
  if (options.search && has_program_) {
    // The axes stand where the planner starts; the channel learns at once that it searches.
    search_.emplace(*options.search, planner_->planned_mcs());
    PlannedBlock b;
    (void)b.push_back(SearchRun::begins());
    (void)window_.push(b);
    flushing_ = true;
  }
}

ChannelPrep::~ChannelPrep() = default;
ChannelPrep::ChannelPrep(ChannelPrep&&) noexcept = default;
ChannelPrep& ChannelPrep::operator=(ChannelPrep&&) noexcept = default;

bool ChannelPrep::needs_feedback(const nc::Block& b) {
  if (b.hash && std::holds_alternative<nc::CAxis>(*b.hash) && std::get<nc::CAxis>(*b.hash).on)
    return true;  // C starts where the spindle stands (Planner::take_c_axis_position)
  return b.g_nonmodal.has(nc::GCode::g100) ||
         (b.hash && std::holds_alternative<nc::GetManualOffsets>(*b.hash));
}

bool ChannelPrep::feed(kernel::CommandQueue& commands, kernel::FeedbackQueue& feedback, bool channel_done) {
  // A call that did nothing does nothing again until the kernel has taken a
  // command or sent feedback, or the channel ended.
  if (idle(commands, feedback, channel_done)) return false;
  if (channel_done) take_stop(feedback);
  take_zero_offsets();
  if (!in_mdi_ && done() && mdi_pending()) start_mdi();
  const std::uint64_t before = decoded_ + window_.released();
  feed_blocks(commands, feedback, channel_done);
  const bool progressed = decoded_ + window_.released() != before;
  if (progressed) idle_.reset();
  else idle_ = Idle{commands.free_slots(), channel_done};
  return progressed;
}

// The kernel ended the program before its end (a reset, an error it met):
// what preparation has of it is dropped, and planning (MDI) goes on from
// where the path stands. Nothing to do when no such record came.
void ChannelPrep::take_stop(kernel::FeedbackQueue& feedback) {
  bool stopped = false;
  for (std::size_t i = 0; i < feedback.size(); ++i) stopped = stopped || feedback.at(i).kind == kernel::FeedbackKind::stopped;
  if (!stopped) return;
  for (; !feedback.empty(); feedback.pop()) {  // records before the stop belong to the dropped program
    if (feedback.front().kind != kernel::FeedbackKind::stopped) continue;
    take_feedback(feedback.front(), *planner_, *decoder_);
    ++stops_taken_;  // what is planned from now on starts where the path stopped
  }
  window_.drop_all();
  backlog_.clear();
  search_.reset();
  flushing_ = awaiting_feedback_ = false;
  done_ = true;
  idle_.reset();
  if (in_mdi_) {   // a reset ended the text in progress: the kernel drops what it has of it
    in_mdi_ = false;
    mdi_->pending.fetch_sub(1, std::memory_order_release);
  }
}

void ChannelPrep::feed_blocks(kernel::CommandQueue& commands, kernel::FeedbackQueue& feedback,
                              bool channel_done) {
  if (!drain_backlog(commands)) return;
  if (flushing_) {
    if (!window_.release(commands, true)) return;
    flushing_ = false;
  }
  if (awaiting_feedback_) {
    if (feedback.empty() && !channel_done) return;
    if (!feedback.empty()) {
      take_feedback(feedback.front(), *planner_, *decoder_);
      feedback.pop();
    }
    ++decoded_;
    awaiting_feedback_ = false;
  }
  while (!done_ && !awaiting_feedback_ && backlog_.empty() &&
         commands.free_slots() >= kernel::kMaxCommandsPerBlock) {
    nc::Decoder::Result r = decoder_->next();
    collect_warnings();
    // The caller stops the run; no progress, so a preparation thread rests.
    if (r.status == nc::Decoder::Status::stopped) return;
    ++decoded_;
    if (r.status == nc::Decoder::Status::block) {
      take_block(r.block, commands);
    } else if (r.status == nc::Decoder::Status::end && in_mdi_) {
      finish_mdi(commands);
    } else if (r.status == nc::Decoder::Status::end) {
      // Where the program ends: its last block (file 0 is the main program).
      hand_over(error_command(make_diagnostic(ErrorId::KernelMissingProgramEnd, {"", last_main_line_, 0},
                                              "the program has no M30 (or M2) at its end"),
                              0, *store_),
                commands);
      done_ = true;
    } else {
      const auto& ds = decoder_->diagnostics();
      const Diagnostic d = ds.empty() ? make_diagnostic(ErrorId::NcFileUnreadable, {}, "decoder stopped")
                                      : ds.back();
      // The error names the file its line is in (a subroutine's, not the main program's).
      hand_over(error_command(d, decoder_->file_id(d.loc.file).value_or(0), *store_), commands);
      done_ = true;
      if (in_mdi_) finish_mdi(commands);  // an error ends the MDI text, never the channel
    }
  }
}

// A decoded block: planned (or searched), and whether later blocks wait for
// feedback from its execution.
void ChannelPrep::take_block(const nc::Block& b, kernel::CommandQueue& commands) {
  if (b.depth == 0) last_main_line_ = b.line;
  if (search_) search_->decoded(b, decoder_->file_name(b.file_id));
  if (search_ && b.program_end && !search_->restarts_at(b)) {
    search_not_found(b, commands);
    return;
  }
  (void)prepare(b, commands);
  done_ = done_ || b.program_end;  // an MDI text may have ended in prepare()
  if (in_mdi_ && b.program_end) finish_mdi(commands);  // M30 typed in MDI
  awaiting_feedback_ = needs_feedback(b);
  if (awaiting_feedback_ && search_) {  // still searching: nothing executes
    take_feedback(assumed_feedback(b, *planner_), *planner_, *decoder_);
    awaiting_feedback_ = false;
  }
}

bool ChannelPrep::prepare(const nc::Block& b, kernel::CommandQueue& commands) {
  if (!window_.has_room() && !window_.release(commands, false)) return false;
  if (observer_) observer_->decoded(b, *planner_, trc_.holding());
  if (trc_.passes_through(b)) {
    plan_out(b, false, std::nullopt, commands);  // most blocks: planned from the decoder's own
  } else {
    trc_outs_.clear();  // kept: no allocation per block
    trc_.push(b, *planner_, trc_outs_);
    for (const TrcOut& o : trc_outs_)
      if (!plan_out(o.block, o.inserted, o.error, commands)) break;
  }
  // A block that needs feedback, and the program end, must reach the channel now.
  flushing_ = flushing_ || needs_feedback(b) || b.program_end;
  return push_out(commands);
}

namespace {

void set_trc_event(PlannedCommand& c, const RadiusComp::State& s) {
  c.detach<trc::TrcChange>();
  c.attach(trc::TrcChange{s.mode, s.d, s.radius_mm});
}

}  // namespace

bool ChannelPrep::plan_out(const nc::Block& block, bool inserted, const std::optional<Diagnostic>& error,
                           kernel::CommandQueue& commands) {
  // A planned block is 13.5 KB: built once in place, not zeroed and copied.
  auto plan_one = [&] {
    if (!error) return planner_->plan(block);
    PlannedBlock b;
    (void)b.push_back(error_command(*error, block.file_id, *store_));
    return b;
  };
  PlannedBlock planned = plan_one();
  if (search_) {
    search_out(block, planned, commands);
    return true;
  }
  if (!planned.empty()) attach_warnings(planned[0]);
  if (!error) {
    if (inserted)
      for (PlannedCommand& c : planned) c.head.emit_block_event = false;
    else if (const auto st = trc_.report(block); st && !planned.empty())
      set_trc_event(planned[0], *st);
    if (record_frames_) {
      const std::uint32_t frame = frame_index_now();
      for (PlannedCommand& c : planned) c.head.frame_index = frame;
    }
  }
  if (in_mdi_) mark_mdi(planned);
  queue(planned, commands);
  if (in_mdi_ && !planned.empty() && planned[0].kind == CommandKind::error) {
    done_ = true;
    finish_mdi(commands);
    return false;
  }
  return true;
}

void ChannelPrep::queue(const PlannedBlock& planned, kernel::CommandQueue& commands) {
  if (backlog_.empty() && (window_.has_room() || window_.release(commands, false)))
    (void)window_.push(planned);
  else
    backlog_.push_back(planned);
}

// In search nothing is handed over but errors (the run would abort there
// too); decoder warnings wait for the restart. From the mark block on the
// real run begins.
void ChannelPrep::search_out(const nc::Block& block, const PlannedBlock& planned, kernel::CommandQueue& commands) {
  const bool failed = !planned.empty() && planned[0].kind == CommandKind::error;
  if (!search_->restarts_at(block) && !failed) {
    search_->searched(planned);
    return;
  }
  const SourceLoc at{decoder_->file_name(block.file_id), block.line, 0};
  auto restart = search_->restart(planned, *planner_, at);
  search_.reset();
  if (!restart) {
    hand_over(error_command(restart.error(), block.file_id, *store_), commands);
    return;
  }
  for (PlannedBlock& b : *restart) {
    if (record_frames_) {
      const std::uint32_t frame = frame_index_now();
      for (PlannedCommand& c : b) c.head.frame_index = frame;
    }
    if (!b.empty()) attach_warnings(b[0]);
    queue(b, commands);
  }
}

// The program ended before the mark: the search failed (TF5200 20704).
void ChannelPrep::search_not_found(const nc::Block& end, kernel::CommandQueue& commands) {
  const SourceLoc at{decoder_->file_name(end.file_id), end.line, 0};
  const std::vector<Diagnostic> found = search_->not_found(at);
  search_.reset();
  done_ = true;
  for (const Diagnostic& d : found) {
    if (d.severity == Severity::warning) pending_warnings_.push_back(d);
    else hand_over(error_command(d, end.file_id, *store_), commands);
  }
}


bool ChannelPrep::drain_backlog(kernel::CommandQueue& commands) {
  std::size_t i = 0;
  for (; i < backlog_.size(); ++i) {
    if (!window_.has_room() && !window_.release(commands, false)) break;
    (void)window_.push(backlog_[i]);
  }
  backlog_.erase(backlog_.begin(), backlog_.begin() + static_cast<std::ptrdiff_t>(i));
  return backlog_.empty();
}

// An error or the missing program end comes after every block before it.
// What tool radius compensation still holds does not run: its end would
// depend on blocks that never come (the same rule as for its own errors).
void ChannelPrep::hand_over(const PlannedCommand& c, kernel::CommandQueue& commands) {
  trc_.discard();
  PlannedBlock b;
  (void)b.push_back(c);
  attach_warnings(b[0]);
  if (in_mdi_) mark_mdi(b);
  flushing_ = true;
  if (!backlog_.empty()) {
    backlog_.push_back(b);
    return;
  }
  // Room: release() keeps at most depth() commands, fewer than the window holds.
  if (!window_.has_room()) (void)window_.release(commands, false);
  (void)window_.push(b);
  (void)push_out(commands);
}

// Hands over what may leave the window; false while a flush is unfinished
// (feed() goes on with it when the queue has room again).
bool ChannelPrep::push_out(kernel::CommandQueue& commands) {
  if (!window_.release(commands, flushing_)) return false;
  if (!backlog_.empty()) return false;  // feed() goes on with the backlog first
  flushing_ = false;
  return true;
}


// The planner's program -> machine map after the block just planned, put
// into the store only when it differs from the last one.
std::uint32_t ChannelPrep::frame_index_now() {
  const ChannelFrames& offsets = planner_->frames();
  // No offset changed since the last map: the same map. (Not when the modal
  // state is recorded with it: that changes without an offset.)
  if (frame_index_ != kernel::kNoMessage && offsets.changes() == frame_changes_ && !record_modal_) {
    assert(store_->frames[frame_index_] == offsets.affine(frames::SuppressMask::none()));
    return frame_index_;
  }
  frame_changes_ = offsets.changes();
  const kernel::AffineMap m = offsets.affine(frames::SuppressMask::none());
  if (frame_index_ != kernel::kNoMessage) {
    const bool same_modal = !record_modal_ || store_->frame_modals[frame_index_] == planner_->modal();
    if (store_->frames[frame_index_] == m && same_modal) return frame_index_;
  }
  // one writer: the modal state is in place before the map's index is published
  if (record_modal_) (void)store_->frame_modals.push_back(planner_->modal());
  return frame_index_ = store_->add_frame(m);
}

void ChannelPrep::collect_warnings() {
  const auto& ds = decoder_->diagnostics();
  for (; diagnostics_seen_ < ds.size(); ++diagnostics_seen_)
    if (ds[diagnostics_seen_].severity == Severity::warning) pending_warnings_.push_back(ds[diagnostics_seen_]);
}

void ChannelPrep::attach_warnings(PlannedCommand& c) {
  if (pending_warnings_.empty()) return;
  add_warnings(c, pending_warnings_, *store_);
  pending_warnings_.clear();
}

void ChannelPrep::offer_zero_offsets(config::ZeroOffsets zero) {
  const std::lock_guard lock(zero_inbox_->mutex);
  zero_inbox_->zero = std::move(zero);
  zero_inbox_->offered.store(true, std::memory_order_release);
}

void ChannelPrep::take_zero_offsets() {
  if (!zero_inbox_->offered.load(std::memory_order_acquire)) return;
  const std::lock_guard lock(zero_inbox_->mutex);
  planner_->set_zero_offsets(zero_inbox_->zero);
  zero_inbox_->offered.store(false, std::memory_order_release);
}

void ChannelPrep::submit_mdi(std::string text) {
  const std::lock_guard lock(mdi_->mutex);
  mdi_->texts.push_back(std::move(text));
  mdi_->pending.fetch_add(1, std::memory_order_release);
  mdi_->used.store(true, std::memory_order_release);
}

void ChannelPrep::start_mdi() {
  std::string text;
  {
    const std::lock_guard lock(mdi_->mutex);
    if (mdi_->texts.empty()) return;
    text = std::move(mdi_->texts.front());
    mdi_->texts.pop_front();
  }
  decoder_->run_mdi(std::move(text));
  in_mdi_ = true;
  done_ = false;
  idle_.reset();
}

// The text is prepared (or ended by an error): the command after its last
// returns the channel to idle.
void ChannelPrep::finish_mdi(kernel::CommandQueue& commands) {
  PlannedCommand end;
  end.kind = CommandKind::nop;
  end.head.emit_block_event = false;
  end.head.file_id = decoder_->file_id(nc::kMdiFileName).value_or(0);
  end.head.mdi = kernel::Mdi::end;
  end.head.stops_taken = stops_taken_;
  PlannedBlock b;
  (void)b.push_back(end);
  attach_warnings(b[0]);
  queue(b, commands);
  flushing_ = true;  // the text's commands reach the channel now
  (void)push_out(commands);
  in_mdi_ = false;
  done_ = true;
  mdi_->pending.fetch_sub(1, std::memory_order_release);
}

void ChannelPrep::mark_mdi(PlannedBlock& b) const {
  for (PlannedCommand& c : b) {
    if (c.head.mdi == kernel::Mdi::none) c.head.mdi = kernel::Mdi::block;
    c.head.stops_taken = stops_taken_;
  }
}

std::size_t ChannelPrep::discard_mdi() {
  const std::lock_guard lock(mdi_->mutex);
  const std::size_t n = mdi_->texts.size();
  mdi_->texts.clear();
  mdi_->pending.fetch_sub(n, std::memory_order_release);
  return n;
}

void ChannelPrep::start_at(const motion::AxisVector& path_mcs) { planner_->take_stopped_position(path_mcs); }

}  // namespace nck::prep
