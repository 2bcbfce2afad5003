#pragma once
// The progress line of `nck run` on a terminal: how far into the program,
// the block running, simulated time, real-time factor and the time left.
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "nck/kernel/tick_io.hpp"

namespace nck::app {

class Progress {
 public:
  // Off when stderr is not a terminal. programs: the main program per channel.
  Progress(bool enabled, const std::vector<std::string>& programs);
  ~Progress() { clear(); }
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // The blocks that started this cycle (main-program lines only).
  void take(const kernel::TickOutput& o);
  // Redraws the line, at most five times a second.
  void update(double t_s);
  // Removes the line: call before printing anything else on stderr.
  void clear();

 private:
  // The share of the program passed: main-program line over its line count,
  // averaged over the channels that run a program.
  double fraction() const;

  struct Channel {
    std::uint32_t lines = 0;  // of the main program
    std::uint32_t line = 0;   // of the block running
    bool has_n = false;
    std::int64_t n = 0;
  };
  bool enabled_;
  bool shown_ = false;
  std::vector<Channel> channels_;
  std::chrono::steady_clock::time_point start_, last_{};
};

}  // namespace nck::app
