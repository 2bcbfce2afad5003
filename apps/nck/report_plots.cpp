#include "report_plots.hpp"

#include <chrono>

#include "output_writers.hpp"
#include "time_by_cause.hpp"

namespace nck::app {
namespace {

// How long the folding thread sleeps when it has caught up, and the run's
// thread when every slot waits to be folded (rare: folding a batch costs a
// fraction of running its cycles).
constexpr std::chrono::microseconds kIdleWait{100};

}  // namespace

void ReportPlots::configure(std::size_t channels, std::size_t series_count, double cycle_s) {
  channels_.resize(channels);
  series_.start(series_count, cycle_s);
  for (ReportBatch& b : ring_) b.start(channels, series_count);
}

void ReportPlots::start() {
  thread_ = std::jthread([this](std::stop_token stop) { run(stop); });
}

void ReportPlots::publish() {
  const std::uint64_t next = published_.load(std::memory_order_relaxed) + 1;
  published_.store(next, std::memory_order_release);
  // The slot to record into next must have been folded and emptied.
  while (next - folded_.load(std::memory_order_acquire) >= kSlots) std::this_thread::sleep_for(kIdleWait);
}

void ReportPlots::finish() {
  if (!thread_.joinable()) return;
  if (batch().size() > 0) publish();
  thread_.request_stop();
  thread_.join();
}

// Folds the batches in the order they were handed over; after a stop
// request, what was handed over still is folded before the thread ends.
void ReportPlots::run(std::stop_token stop) {
  std::uint64_t folded = folded_.load(std::memory_order_relaxed);
  for (;;) {
    const bool stopping = stop.stop_requested();
    if (folded == published_.load(std::memory_order_acquire)) {
      if (stopping) return;
      std::this_thread::sleep_for(kIdleWait);
      continue;
    }
    ReportBatch& b = ring_[folded % kSlots];
    fold(b);
    b.clear();
    folded_.store(++folded, std::memory_order_release);
  }
}

void ReportPlots::fold(const ReportBatch& b) {
  for (std::size_t i = 0; i < b.size(); ++i) {
    for (std::size_t c = 0; c < channels_.size(); ++c) {
      Channel& ch = channels_[c];
      const ReportBatch::ChannelSample& s = b.channel(i, c);
      ch.path.add(s.pos, s.line, s.file, s.rapid, s.frame, b.t_s(i));
      note_cause(ch, s.cause, s.wait_reason, b.t_s(i));
    }
    series_.add(b.cycle(i), b.row(i));
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
