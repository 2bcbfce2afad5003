#pragma once
// The report's cycles between two folds into its plots: each cycle's time,
// its plot values (one row) and per channel what the backplot and the
// cause timeline need. The run's thread only writes here; ReportPlots folds
// whole batches on its own thread (docs/decisions.md, "Performance-driven
// decisions", the report's plots on a thread).
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "nck/kernel/tick_io.hpp"

namespace nck::app {

class ReportBatch {
 public:
  static constexpr std::size_t kCycles = 512;
  struct ChannelSample {
    std::array<double, 3> pos{};  // X, Y, Z of the backplot
    double path_velocity_mm_s = 0;  // its derivatives are plotted (computed where the batch is folded)
    std::uint32_t line = 0;       // the block in execution: its line, file and map
    std::uint32_t frame = 0;
    std::uint16_t file = 0;
    bool rapid = false;           // G0
    kernel::CycleCause cause = kernel::CycleCause::none;
    kernel::WaitReason wait_reason{};
  };

  void start(std::size_t channels, std::size_t row_size) {
    channels_ = channels;
    row_size_ = row_size;
    cycles_.clear();
    cycles_.reserve(kCycles);
    rows_.assign(kCycles * row_size, 0.0);
    samples_.assign(kCycles * channels, {});
  }
  // A new cycle (only when !full()): its row and channel samples to fill.
  std::size_t add(std::uint64_t cycle, double t_s) {
    cycles_.push_back({cycle, t_s});
    return cycles_.size() - 1;
  }
  bool full() const { return cycles_.size() == kCycles; }
  std::size_t size() const { return cycles_.size(); }
  void clear() { cycles_.clear(); }

  std::uint64_t cycle(std::size_t i) const { return cycles_[i].cycle; }
  double t_s(std::size_t i) const { return cycles_[i].t_s; }
  double* row(std::size_t i) { return &rows_[i * row_size_]; }
  std::span<const double> row(std::size_t i) const { return {&rows_[i * row_size_], row_size_}; }
  ChannelSample& channel(std::size_t i, std::size_t c) { return samples_[i * channels_ + c]; }
  const ChannelSample& channel(std::size_t i, std::size_t c) const { return samples_[i * channels_ + c]; }

 private:
  struct Cycle {
    std::uint64_t cycle;
    double t_s;
  };
  std::size_t channels_ = 0, row_size_ = 0;
  std::vector<Cycle> cycles_;
  std::vector<double> rows_;             // kCycles rows of row_size_ values
  std::vector<ChannelSample> samples_;   // kCycles rows of one per channel
};

}  // namespace nck::app
