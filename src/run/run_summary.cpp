#include "nck/run/run_summary.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "nck/output/output_writers.hpp"

namespace nck::app {

std::string clock_time(double s) {
  const auto ms = static_cast<std::uint64_t>(std::llround(std::max(0.0, s) * 1000));
  return fmt::format("{}:{:02}:{:02}.{:03}", ms / 3'600'000, ms / 60'000 % 60, ms / 1000 % 60, ms % 1000);
}

void RunSummary::take(const kernel::Event& e) {
  using K = kernel::EventKind;
  switch (e.kind()) {
    case K::block: ++blocks_; break;
    case K::error: ++errors_; break;
    case K::warning: ++warnings_; break;
    case K::end:
      if (e.get<kernel::ev::End>()->reason == kernel::EndReason::reset) ++resets_;
      break;
    case K::wait: {
      // A channel waiting for two spindles at once waits once: the time
      // counts from the first of them (the one open before this, if any).
      const kernel::ev::Wait& w = *e.get<kernel::ev::Wait>();
      open_.push_back({e.channel, w, first_open(e.channel, w.reason).value_or(e.t_s)});
      break;
    }
    case K::wait_end: {
      const kernel::ev::Wait& end = *e.get<kernel::ev::WaitEnd>();
      auto it = std::find_if(open_.begin(), open_.end(), [&](const OpenWait& w) {
        return w.channel == e.channel && w.wait.spindle == end.spindle && w.wait.fn == end.fn &&
               w.wait.number == end.number && w.wait.reason == end.reason;
      });
      if (it == open_.end()) break;
      const OpenWait ended = *it;
      open_.erase(it);
      const auto r = static_cast<std::size_t>(ended.wait.reason);
      if (!first_open(ended.channel, ended.wait.reason) && r < waited_s_.size())
        waited_s_[r] += e.t_s - ended.since_s;  // the last of them
      break;
    }
    default: break;
  }
}

std::optional<double> RunSummary::first_open(std::uint8_t channel, kernel::WaitReason reason) const {
  for (const OpenWait& w : open_)
    if (w.channel == channel && w.wait.reason == reason) return w.since_s;
  return std::nullopt;
}

std::string RunSummary::text(const std::string& end_reason, double end_s) const {
  std::string waits;
  for (std::size_t r = 0; r < waited_s_.size(); ++r)
    if (waited_s_[r] > 0)
      waits += fmt::format("{} {} {:.3f} s", waits.empty() ? "; waited" : ",",
                           wait_reason_name(static_cast<kernel::WaitReason>(r)), waited_s_[r]);
  return fmt::format("nck: {} after {} simulated; {} block(s), {} error(s), {} warning(s){}", end_reason,
                     clock_time(end_s), blocks_, errors_, warnings_, waits);
}

}  // namespace nck::app
