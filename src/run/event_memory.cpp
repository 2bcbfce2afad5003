#include "nck/run/event_memory.hpp"

#include <algorithm>

namespace nck::app {

void EventMemory::start(std::uint64_t max_bytes, Full policy) {
  enabled_ = true;
  max_bytes_ = max_bytes;
  policy_ = policy;
}

bool EventMemory::add(const kernel::Event& e, std::string_view line) {
  EventRecord r;
  r.t_s = e.t_s;
  r.n = e.at.n.value_or(-1);
  r.line = e.at.line;
  r.channel = e.channel;
  r.kind = static_cast<std::uint8_t>(e.kind());
  return add(r, line);
}

bool EventMemory::add(EventRecord r, std::string_view line) {
  if (!enabled_) return true;
  const std::uint64_t need = line.size() + sizeof(EventRecord);
  if (!lifted_ && bytes() + need > max_bytes_) {
    if (policy_ == Full::end_run) {
      full_ = true;
      return false;
    }
    // Halving, not one at a time: each drop moves the rest, so this keeps it amortised O(1).
    while (!records.empty() && bytes() + need > max_bytes_) drop_oldest_half();
  }
  text.append(line);
  r.text_end = text.size();
  records.push_back(r);
  return true;
}

std::string_view EventMemory::line(std::size_t i) const {
  const std::uint64_t begin = i == 0 ? 0 : records[i - 1].text_end;
  return std::string_view(text).substr(begin, records[i].text_end - begin);
}

std::uint64_t EventMemory::take_dropped() {
  const std::uint64_t n = dropped_;
  dropped_ = 0;
  return n;
}

void EventMemory::clear() {
  first_ += records.size();
  text.clear();
  records.clear();
}

void EventMemory::drop_oldest_half() {
  const std::size_t n = std::max<std::size_t>(records.size() / 2, 1);
  const std::uint64_t cut = records[n - 1].text_end;
  text.erase(0, cut);
  records.erase(records.begin(), records.begin() + static_cast<std::ptrdiff_t>(n));
  for (EventRecord& r : records) r.text_end -= cut;
  first_ += n;
  dropped_ += n;
}

}  // namespace nck::app
