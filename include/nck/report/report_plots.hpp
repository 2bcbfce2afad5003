#pragma once
// The report's plots: each channel's tool path and cause timeline, and the
// envelopes of the time series. The run's thread only records its cycles
// into batches (ReportBatch); a thread of their own folds them into the
// plots, in the order they were recorded, so the page is the same as if the
// run's thread had folded them itself, and the run does not wait for the
// report's geometry (docs/decisions.md, "Performance-driven decisions", the
// report's plots on a thread).
#include <array>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "nck/kernel/tick_io.hpp"
#include "nck/output/trace_columns.hpp"
#include "nck/report/report_batch.hpp"
#include "nck/report/report_series.hpp"
#include "nck/report/timed_path.hpp"

namespace nck::app {

class ReportPlots {
 public:
  struct Channel {
    TimedPath path;
    // The row's path velocity column: path.a and path.j as --trace-columns
    // computes them go into the two after it (none: not plotted).
    std::optional<std::size_t> velocity_column;
    PathDerivatives path_deriv;
    // the cause timeline (the time cursor's class): when each class began, and its name
    std::vector<double> cause_t;
    std::vector<std::string> cause_name;
    std::string cause_now;
    std::optional<std::pair<kernel::CycleCause, int>> cause_key;  // cause_now's cause and wait reason
  };
  static constexpr std::size_t kMaxCauses = 20000;  // timeline entries per channel; beyond, the cursor shows none
  static constexpr std::size_t kSlots = 16;          // batches recorded ahead of the folding
  static constexpr std::size_t kWakeBatches = kSlots / 2;

  explicit ReportPlots(std::size_t channels) : channels_(channels) {}
  ReportPlots(const ReportPlots&) = delete;
  ReportPlots& operator=(const ReportPlots&) = delete;
  ~ReportPlots() { finish(); }

  // After each channel's path start and path velocity column (channel(c)):
  // the time series and the folding thread.
  void start(std::size_t series_count, double cycle_s);
  Channel& channel(std::size_t c) { return channels_[c]; }  // before start() and after finish() only
  const Channel& channel(std::size_t c) const { return channels_[c]; }
  const EnvelopeSeries& series() const { return series_; }  // after finish() only

  // The batch the run's thread records into; hand it over when full.
  ReportBatch& batch() { return ring_[published_.load(std::memory_order_relaxed) % kSlots]; }
  void publish();
  // Folds every recorded cycle and stops the thread (idempotent).
  void finish();

 private:
  void run();
  void wake(bool stop);
  void fold(ReportBatch& b);
  void note_cause(Channel& ch, kernel::CycleCause cause, kernel::WaitReason wait_reason, double t_s);

  std::vector<Channel> channels_;
  EnvelopeSeries series_;
  std::array<ReportBatch, kSlots> ring_;
  std::atomic<std::uint64_t> published_{0};  // batches handed over (written by the run's thread)
  std::atomic<std::uint64_t> folded_{0};     // batches folded (written by the folding thread)
  // Sleeping and waking: a side sets its flag under the mutex before it
  // waits; the other side, having moved its counter, wakes it if the flag is set.
  std::mutex mutex_;
  std::condition_variable woken_;
  std::atomic<bool> folder_idle_{false}, recorder_waits_{false};
  bool stopping_ = false;  // under mutex_
  bool failed_ = false;    // a fold ran out of memory (folding thread only)
  std::thread thread_;
};

}  // namespace nck::app
