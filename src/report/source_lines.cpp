#include "nck/report/source_lines.hpp"

#include <limits>

namespace nck::app {

SourceLines::SourceLines(std::string path) : name_(std::move(path)) {
  std::ifstream in(name_, std::ios::binary);
  std::uint64_t offset = 0;
  for (std::string l; line_count_ < std::numeric_limits<std::uint32_t>::max() && std::getline(in, l);) {
    if (line_count_ % kStride == 0) offsets_.push_back(offset);
    ++line_count_;
    offset += l.size() + 1;
  }
}

void SourceLines::close() {
  in_.close();
  next_ = 0;
}

bool SourceLines::read_line(std::string& out) {
  if (!std::getline(in_, out)) {
    next_ = 0;
    return false;
  }
  if (!out.empty() && out.back() == '\r') out.pop_back();
  if (next_ == 1 && out.starts_with("\xEF\xBB\xBF")) out.erase(0, 3);  // a UTF-8 byte-order mark
  ++next_;
  return true;
}

const std::string& SourceLines::line(std::uint32_t n) {
  static const std::string none;
  if (n == 0 || n > line_count_) return none;
  Cached& slot = cache_[n % kCacheLines];
  if (slot.line == n) return slot.text;
  // Forward from where the stream is when the line is near, else from the
  // noted offset before it.
  if (!in_.is_open()) {
    in_.open(name_, std::ios::binary);
    next_ = 0;
  }
  if (next_ == 0 || n < next_ || n - next_ >= kStride) {
    const std::uint32_t block = (n - 1) / kStride;
    in_.clear();
    in_.seekg(static_cast<std::streamoff>(offsets_[block]));
    next_ = block * kStride + 1;
  }
  // read into the slot (its buffer serves again; line 0 is no line while it fills)
  slot.line = 0;
  while (next_ != 0 && next_ <= n)
    if (!read_line(slot.text)) break;
  if (next_ != n + 1) return none;
  slot.line = n;
  return slot.text;
}

}  // namespace nck::app
