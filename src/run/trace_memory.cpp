#include "nck/run/trace_memory.hpp"

#include <algorithm>

namespace nck::app {

void TraceMemory::start(const config::Machine& m, std::uint64_t every, std::uint64_t max_bytes, TraceColumns extra) {
  enabled_ = true;
  every_ = every == 0 ? 1 : every;
  max_bytes_ = max_bytes;
  names = TraceWriter::column_names(m, extra);
  layout_ = TraceLayout(m);
  extra_ = extra;
  path_.assign(extra.any() ? m.channels.size() : 0, PathDerivatives(m.cycle_time_us * 1e-6));
  values.assign(names.size(), {});
  max_rows_ = max_bytes / (8 * std::max<std::size_t>(names.size(), 1));
}

bool TraceMemory::write(std::uint64_t cycle, const kernel::TickOutput& out) {
  if (!enabled_) return true;
  // The derivatives see every cycle, as the CSV's do, whatever rows are kept.
  for (std::size_t ch = 0; ch < path_.size(); ++ch) path_[ch].update(out.channels[ch].path_velocity_mm_s);
  if (cycle % every_ != 0) return true;
  if (!values.empty() && values[0].size() >= max_rows_) return false;
  std::size_t c = 0;
  layout_.visit(out, [&](double v, TraceLayout::Format) { values[c++].push_back(v); });
  for (std::size_t ch = 0; ch < path_.size(); ++ch) {  // the order of TraceWriter::column_names
    if (extra_.path_v) values[c++].push_back(out.channels[ch].path_velocity_mm_s);
    if (extra_.path_a) values[c++].push_back(path_[ch].a_mm_s2());
    if (extra_.path_j) values[c++].push_back(path_[ch].j_mm_s3());
  }
  return true;
}

}  // namespace nck::app
