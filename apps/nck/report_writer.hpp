#pragma once
// --report FILE.html: a self-contained report of a run — summary, errors,
// the event log, and plots (inline SVG, no scripts or network) of every
// path axis and every spindle's speed over time.
#include <optional>
#include <string>
#include <vector>

#include "nck/config/machine.hpp"
#include "nck/kernel/tick_io.hpp"

namespace nck::app {

class ReportWriter {
 public:
  // setup: the columns to plot; `enabled` false makes every call a no-op.
  void start(const config::Machine& m, std::vector<std::string> programs, bool enabled);
  // Once per cycle; keeps at most about kMaxPoints samples per series by
  // thinning (every 2nd, 4th ... cycle) as the run grows.
  void sample(const kernel::TickOutput& out);
  // One line of the event log (the JSON text of an event).
  void event(const std::string& json_line, bool is_error);
  // The error text when it cannot be written.
  std::optional<std::string> write(const std::string& path, double end_s, int exit_code) const;
  bool enabled() const { return enabled_; }

  static constexpr std::size_t kMaxPoints = 2000;
  static constexpr std::size_t kMaxEvents = 2000;

 private:
  struct Series {
    std::string name;
    std::string unit;
    std::vector<double> values;
  };
  bool enabled_ = false;
  std::vector<std::string> programs_;
  std::vector<double> t_;
  std::vector<Series> series_;
  std::vector<std::size_t> axis_count_;  // per channel
  std::size_t spindle_count_ = 0;
  std::vector<std::size_t> dist_channels_;  // channels with 3D distance control (3 series each)
  std::uint64_t stride_ = 1, cycle_ = 0;
  std::vector<std::string> events_, errors_;
  std::size_t events_dropped_ = 0;
};

}  // namespace nck::app
