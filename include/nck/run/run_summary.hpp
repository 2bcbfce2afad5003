#pragma once
// The end-of-run summary on stderr (issue 17): why the run ended, its cycle
// time, and what happened on the way (blocks, errors, warnings, time spent
// waiting per reason).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "nck/kernel/event.hpp"

namespace nck::app {

class RunSummary {
 public:
  void take(const kernel::Event& e);
  void warning() { ++warnings_; }  // a decoder warning, reported outside the cycle
  // "nck: M30 after 0:00:29.749 simulated; 123 blocks, 0 errors, 1 warning; waited plc_ack 0.010 s ..."
  std::string text(const std::string& end_reason, double end_s) const;
  // A PLC reset ended a channel's program (counted as an error: 940007).
  bool reset_seen() const { return resets_ > 0; }

 private:
  struct OpenWait {
    std::uint8_t channel;
    kernel::ev::Wait wait;
    double since_s;  // since when the channel waits for this reason (overlapping waits count once)
  };
  // The start of the channel's open waits for `reason`, if it waits for one.
  std::optional<double> first_open(std::uint8_t channel, kernel::WaitReason reason) const;
  std::uint64_t blocks_ = 0, errors_ = 0, warnings_ = 0, resets_ = 0;
  std::vector<OpenWait> open_;
  std::array<double, 16> waited_s_{};  // by WaitReason
};

// h:mm:ss.mmm
std::string clock_time(double s);

}  // namespace nck::app
