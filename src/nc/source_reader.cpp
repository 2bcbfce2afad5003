#include "source_reader.hpp"

#include <cstring>

namespace nck::nc::detail {

namespace {
constexpr std::size_t kBufSize = 1 << 16;

// Position of a ';' comment start outside strings and ( ) comments, or npos.
std::size_t comment_start(const std::string& t, std::size_t from) {
  bool in_str = false;
  int paren = 0;
  for (std::size_t i = from; i < t.size(); ++i) {
    char c = t[i];
    if (in_str) {
      if (c == '"') in_str = false;
    } else if (c == '"' && paren == 0) {
      in_str = true;
    } else if (c == '(') {
      ++paren;
    } else if (c == ')' && paren > 0) {
      --paren;
    } else if (c == ';' && paren == 0) {
      return i;
    }
  }
  return std::string::npos;
}
}  // namespace

SourceReader::~SourceReader() {
  if (file_) std::fclose(file_);
}

bool SourceReader::open_file(const std::filesystem::path& p) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(p, ec)) return false;
  file_ = std::fopen(p.string().c_str(), "rb");
  if (!file_) return false;
  buf_.resize(kBufSize);
  return true;
}

void SourceReader::open_memory(std::shared_ptr<const std::string> text) { mem_ = std::move(text); }

bool SourceReader::fill() {
  if (mem_) return false;  // memory sources have everything in mem_
  if (!file_ || eof_) return false;
  buf_offset_ = offset_;
  buf_len_ = std::fread(buf_.data(), 1, buf_.size(), file_);
  buf_pos_ = 0;
  if (buf_len_ == 0) eof_ = true;
  return buf_len_ > 0;
}

void SourceReader::seek(SourcePos p) {
  offset_ = p.offset;
  line_ = p.line;
  if (file_) {
    // Reuse the buffer when the target lies inside it (short loops).
    if (buf_len_ > 0 && p.offset >= buf_offset_ && p.offset < buf_offset_ + buf_len_) {
      buf_pos_ = static_cast<std::size_t>(p.offset - buf_offset_);
    } else {
      std::fseek(file_, static_cast<long>(p.offset), SEEK_SET);
      buf_pos_ = buf_len_ = 0;
      buf_offset_ = p.offset;
    }
    eof_ = false;
  }
}

// Appends one physical line (without the line break) to text_, storing at
// most `room` characters. Returns false when nothing is left to read.
bool SourceReader::next_line(std::size_t room) {
  std::size_t stored = 0;
  bool any = false;
  if (mem_) {
    const std::string& m = *mem_;
    if (offset_ >= m.size()) return false;
    std::size_t b = static_cast<std::size_t>(offset_);
    const void* nl = std::memchr(m.data() + b, '\n', m.size() - b);
    std::size_t e = nl ? static_cast<std::size_t>(static_cast<const char*>(nl) - m.data()) : m.size();
    std::size_t n = e - b;
    std::size_t take = n < room ? n : room;
    text_.append(m.data() + b, take);
    if (n > room) too_long_ = true;
    offset_ = nl ? e + 1 : e;
    ++line_;
    return true;
  }
  for (;;) {
    if (buf_pos_ >= buf_len_ && !fill()) {
      if (any) ++line_;
      return any;
    }
    any = true;
    const char* start = buf_.data() + buf_pos_;
    std::size_t avail = buf_len_ - buf_pos_;
    const void* nl = std::memchr(start, '\n', avail);
    std::size_t n = nl ? static_cast<std::size_t>(static_cast<const char*>(nl) - start) : avail;
    std::size_t take = stored + n <= room ? n : (room > stored ? room - stored : 0);
    text_.append(start, take);
    stored += take;
    if (take < n) too_long_ = true;
    buf_pos_ += nl ? n + 1 : n;
    offset_ += nl ? n + 1 : n;
    if (nl) {
      ++line_;
      return true;
    }
  }
}

bool SourceReader::read_block(std::size_t max_chars) {
  if (meter_ == nullptr) return read_next(max_chars);
  if (!meter_->count(first_pass_free_ && offset_ >= first_pass_end_)) return false;
  const bool read = read_next(max_chars);
  if (offset_ > first_pass_end_) first_pass_end_ = offset_;
  return read;
}

bool SourceReader::read_next(std::size_t max_chars) {
  text_.clear();
  segs_.clear();
  too_long_ = false;
  block_pos_ = SourcePos{offset_, line_};
  bool first = true;
  for (;;) {
    std::size_t seg_start = text_.size();
    std::uint32_t seg_line = line_;
    std::size_t room = max_chars + 1 > text_.size() ? max_chars + 1 - text_.size() : 0;
    if (!next_line(room)) {
      // At the end of the file a diagnostic points at its last line, not one past it.
      if (first && block_pos_.line > 1) --block_pos_.line;
      return !first;
    }
    // A UTF-8 byte-order mark at the start of the file is not part of the
    // program (editors on Windows write one); blanks keep the columns.
    if (block_pos_.offset == 0 && first && text_.starts_with("\xEF\xBB\xBF")) text_.replace(0, 3, "   ");
    first = false;
    segs_.push_back(Segment{static_cast<std::uint32_t>(seg_start), seg_line, 0});
    if (!text_.empty() && text_.back() == '\r') text_.pop_back();
    // Continuation: the last non-blank character of the line is '\'.
    std::size_t e = text_.size();
    while (e > seg_start && (text_[e - 1] == ' ' || text_[e - 1] == '\t')) --e;
    if (e > seg_start && text_[e - 1] == '\\') {
      text_.resize(e - 1);
      // A ';' comment ends with its physical line when the block goes on.
      std::size_t c = comment_start(text_, seg_start);
      if (c != std::string::npos) text_.resize(c);
      text_.push_back(' ');
      continue;
    }
    break;
  }
  if (text_.size() > max_chars) too_long_ = true;
  return true;
}

void SourceReader::locate(std::size_t text_pos, std::uint32_t& line, std::uint32_t& column) const {
  line = block_pos_.line;
  column = static_cast<std::uint32_t>(text_pos + 1);
  for (const auto& s : segs_) {
    if (s.text_pos <= text_pos) {
      line = s.line;
      column = static_cast<std::uint32_t>(text_pos - s.text_pos + 1 + s.col0);
    }
  }
}

}  // namespace nck::nc::detail
