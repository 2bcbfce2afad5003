#pragma once
// The trace kept in memory, one vector of doubles per CSV column (the Python
// module hands each to numpy without a copy): rows x columns x 8 bytes,
// bounded by a limit so that a long run ends with an ID (940200) rather than
// exhausting memory.
#include <cstdint>
#include <string>
#include <vector>

#include "nck/output/output_writers.hpp"

namespace nck::app {

class TraceMemory {
 public:
  // setup: every `every`-th cycle, at most `max_bytes` of values; the
  // columns of TraceWriter with the extras asked for (path.v, path.a, path.j).
  void start(const config::Machine& m, std::uint64_t every, std::uint64_t max_bytes, TraceColumns extra = {});
  bool enabled() const { return enabled_; }
  // After each cycle; false (and nothing kept) once the row would pass the limit.
  bool write(std::uint64_t cycle, const kernel::TickOutput& out);
  std::uint64_t max_bytes() const { return max_bytes_; }
  std::vector<std::string> names;           // TraceWriter::column_names
  std::vector<std::vector<double>> values;  // values[column][row]

 private:
  bool enabled_ = false;
  std::uint64_t every_ = 1;
  std::uint64_t max_rows_ = 0;
  std::uint64_t max_bytes_ = 0;
  TraceLayout layout_;
  TraceColumns extra_{};
  std::vector<PathDerivatives> path_;  // per channel, every cycle (also between kept rows)
};

}  // namespace nck::app
