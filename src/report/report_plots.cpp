#include "nck/report/report_plots.hpp"

#include <exception>
#include <utility>

#include "nck/output/output_writers.hpp"
#include "nck/output/time_by_cause.hpp"

namespace nck::app {

void ReportPlots::start(std::size_t series_count, double cycle_s) {
  series_.start(series_count, cycle_s);
  for (ReportBatch& b : ring_) b.start(channels_.size(), series_count);
  thread_ = std::thread([this] { run(); });
}

// The folding thread is woken when half the ring waits (a wake per batch
// would be a system call every 512 cycles); the run's thread waits only
// when the whole ring waits, which a folding thread on a free core never
// lets happen.
void ReportPlots::publish() {
  const std::uint64_t next = published_.load(std::memory_order_relaxed) + 1;
  published_.store(next, std::memory_order_seq_cst);
  if (next - folded_.load(std::memory_order_seq_cst) >= kWakeBatches && folder_idle_.load(std::memory_order_seq_cst))
    wake(false);
  if (next - folded_.load(std::memory_order_acquire) < kSlots) return;  // the next slot is free
  std::unique_lock lock(mutex_);
  recorder_waits_.store(true, std::memory_order_seq_cst);
  woken_.wait(lock, [&] { return next - folded_.load(std::memory_order_seq_cst) < kSlots; });
  recorder_waits_.store(false, std::memory_order_relaxed);
}

void ReportPlots::wake(bool stop) {
  const std::lock_guard lock(mutex_);
  if (stop) stopping_ = true;
  woken_.notify_all();
}

void ReportPlots::finish() {
  if (!thread_.joinable()) return;
  if (batch().size() > 0) publish();
  wake(true);
  thread_.join();
  for (Channel& c : channels_) c.path.close();
}

// Folds the batches in the order they were handed over; once stopped, what
// was handed over still is folded before the thread ends.
void ReportPlots::run() {
  std::uint64_t folded = folded_.load(std::memory_order_relaxed);
  for (;;) {
    if (folded == published_.load(std::memory_order_acquire)) {
      std::unique_lock lock(mutex_);
      folder_idle_.store(true, std::memory_order_seq_cst);
      woken_.wait(lock, [&] {
        return stopping_ || published_.load(std::memory_order_seq_cst) - folded >= kWakeBatches;
      });
      folder_idle_.store(false, std::memory_order_relaxed);
      if (stopping_ && folded == published_.load(std::memory_order_acquire)) return;
      continue;
    }
    ReportBatch& b = ring_[folded % kSlots];
    // Out of memory in a plot ends the plots where they are (the page shows
    // what was folded), never the run: the batches are still taken.
    if (!failed_) {
      try {
        fold(b);
      } catch (const std::exception&) {
        failed_ = true;
      }
    }
    b.clear();
    folded_.store(++folded, std::memory_order_seq_cst);
    if (recorder_waits_.load(std::memory_order_seq_cst)) wake(false);
  }
}

void ReportPlots::fold(ReportBatch& b) {
  for (std::size_t i = 0; i < b.size(); ++i) {
    double* row = b.row(i);
    for (std::size_t c = 0; c < channels_.size(); ++c) {
      Channel& ch = channels_[c];
      const ReportBatch::ChannelSample& s = b.channel(i, c);
      ch.path.add({.pos = s.pos, .t_s = b.t_s(i), .line = s.line, .frame = s.frame, .file = s.file, .rapid = s.rapid});
      note_cause(ch, s.cause, s.wait_reason, b.t_s(i));
      if (!ch.velocity_column) continue;
      ch.path_deriv.update(s.path_velocity_mm_s);
      row[*ch.velocity_column + 1] = ch.path_deriv.a_mm_s2();
      row[*ch.velocity_column + 2] = ch.path_deriv.j_mm_s3();
    }
    series_.add(b.cycle(i), std::as_const(b).row(i));
  }
}

// One timeline entry where the class changes; the name is built only then.
void ReportPlots::note_cause(Channel& ch, kernel::CycleCause cause, kernel::WaitReason wait_reason, double t_s) {
  const auto reason = cause == kernel::CycleCause::wait ? static_cast<int>(wait_reason) : -1;
  if (ch.cause_key && ch.cause_key->first == cause && ch.cause_key->second == reason) return;
  ch.cause_key = {cause, reason};
  std::string name = cause_name(cause);
  if (cause == kernel::CycleCause::wait) name += std::string(" ") + wait_reason_name(wait_reason);
  if (cause == kernel::CycleCause::feedhold) name += " feedhold";
  if (name == ch.cause_now || ch.cause_t.size() >= kMaxCauses) return;
  ch.cause_now = name;
  ch.cause_t.push_back(t_s);
  ch.cause_name.push_back(name);
}

}  // namespace nck::app
