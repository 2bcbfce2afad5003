#include "file_cache.hpp"

#include <fstream>

#include "lexer.hpp"

namespace nck::nc::detail {

const Section* ProgramIndex::main() const {
  for (const auto& s : sections)
    if (!s.local) return &s;
  return nullptr;
}

std::optional<SourcePos> ProgramIndex::program_start() const {
  if (first_code || sections.empty()) return SourcePos{};
  if (const Section* m = main()) return m->body;
  return std::nullopt;
}

const Section* ProgramIndex::local(const std::string& name_upper) const {
  for (const auto& s : sections)
    if (s.local && s.name == name_upper) return &s;
  return nullptr;
}

bool parse_header(std::string_view t, bool& local, std::string& name) {
  std::size_t p = 0;
  while (p < t.size() && (t[p] == ' ' || t[p] == '\t')) ++p;
  if (p >= t.size() || t[p] != '%') return false;
  ++p;
  local = false;
  // "%L name": L followed by a separator; "%Lname" is a main program's name.
  if (p + 1 < t.size() && upper(t[p]) == 'L' && (t[p + 1] == ' ' || t[p + 1] == '\t')) {
    local = true;
    ++p;
  }
  std::size_t e = p;
  while (e < t.size() && t[e] != '(' && t[e] != ';') ++e;
  std::string_view n = t.substr(p, e - p);
  while (!n.empty() && (n.front() == ' ' || n.front() == '\t')) n.remove_prefix(1);
  while (!n.empty() && (n.back() == ' ' || n.back() == '\t' || n.back() == '\r')) n.remove_suffix(1);
  name = to_upper(n);
  return true;
}

std::size_t comment_phrase_end(std::string_view block, std::string_view which) {
  Cursor c{block, 0};
  c.skip_spaces();
  if (upper(c.peek()) == 'N' && is_digit(c.peek(1))) {
    ++c.pos;
    while (is_digit(c.peek())) ++c.pos;
    c.match(':');
    c.skip_spaces();
  }
  if (!c.match('#')) return std::string_view::npos;
  c.skip_spaces();
  if (!c.match_keyword("COMMENT")) return std::string_view::npos;
  c.skip_spaces();
  if (!c.match_keyword(which)) return std::string_view::npos;
  return c.pos;
}

std::shared_ptr<const std::string> read_text(const std::filesystem::path& p, std::uintmax_t size) {
  std::ifstream in(p, std::ios::binary);
  std::string text(size, '\0');
  if (!in.read(text.data(), static_cast<std::streamsize>(size))) return nullptr;
  return std::make_shared<const std::string>(std::move(text));
}

ProgramIndex scan_sections(SourceReader& r, std::size_t max_chars) {
  ProgramIndex idx;
  bool in_comment = false;
  while (r.read_block(max_chars)) {
    const std::string& t = r.text();
    if (in_comment) {
      in_comment = comment_phrase_end(t, "END") == std::string_view::npos;
      continue;
    }
    if (comment_phrase_end(t, "BEGIN") != std::string_view::npos) {
      in_comment = true;
      continue;
    }
    Cursor c{t, 0};
    c.skip_blanks();
    if (c.at_end()) continue;
    if (c.peek() != '%') {
      if (idx.sections.empty() && !idx.first_code) idx.first_code = r.block_pos();
      continue;
    }
    Section s;
    parse_header(c.s.substr(c.pos), s.local, s.name);
    s.header = r.block_pos();
    s.body = r.next_pos();
    idx.sections.push_back(std::move(s));
  }
  return idx;
}

std::shared_ptr<const FileCache::Entry> FileCache::get(const std::filesystem::path& p,
                                                       std::size_t max_chars) {
  std::error_code ec;
  auto canon = std::filesystem::weakly_canonical(p, ec);
  std::string key = ec ? p.string() : canon.string();
  auto mtime = std::filesystem::last_write_time(p, ec);
  if (ec) return nullptr;
  auto size = std::filesystem::file_size(p, ec);
  if (ec) return nullptr;
  for (auto it = slots_.begin(); it != slots_.end(); ++it) {
    if (it->key != key) continue;
    if (it->mtime == mtime && it->size == size) {
      ++hits_;
      slots_.splice(slots_.begin(), slots_, it);
      return it->entry;
    }
    bytes_ -= it->size;
    slots_.erase(it);  // changed on disk: load again
    break;
  }
  if (size > max_bytes_) return nullptr;
  auto text = read_text(p, size);
  if (!text) return nullptr;
  SourceReader r;
  r.open_memory(text);
  auto entry = std::make_shared<Entry>();
  entry->text = text;
  entry->index = std::make_shared<const ProgramIndex>(scan_sections(r, max_chars));
  ++loads_;
  while (!slots_.empty() && (slots_.size() >= max_files_ || bytes_ + size > max_bytes_)) {
    bytes_ -= slots_.back().size;
    slots_.pop_back();
  }
  slots_.push_front(Slot{key, mtime, size, entry});
  bytes_ += size;
  return entry;
}

}  // namespace nck::nc::detail
