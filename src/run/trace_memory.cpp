#include "nck/run/trace_memory.hpp"

#include <algorithm>

namespace nck::app {

void TraceMemory::start(const config::Machine& m, std::uint64_t every, std::uint64_t max_bytes) {
  enabled_ = true;
  every_ = every == 0 ? 1 : every;
  max_bytes_ = max_bytes;
  names = TraceWriter::column_names(m);
  layout_ = TraceLayout(m);
  values.assign(names.size(), {});
  max_rows_ = max_bytes / (8 * std::max<std::size_t>(names.size(), 1));
}

bool TraceMemory::write(std::uint64_t cycle, const kernel::TickOutput& out) {
  if (!enabled_ || cycle % every_ != 0) return true;
  if (!values.empty() && values[0].size() >= max_rows_) return false;
  std::size_t c = 0;
  layout_.visit(out, [&](double v, TraceLayout::Format) { values[c++].push_back(v); });
  return true;
}

}  // namespace nck::app
