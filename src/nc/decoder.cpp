// The block loop of the streaming decoder: read a block, classify it
// (section header, skip, $ statement, #VAR / #COMMENT, call, words) and run
// the word stages. Only executable blocks leave next().
#include "nck/nc/decoder.hpp"

#include <fmt/format.h>

#include "decoder_impl.hpp"

namespace nck::nc {

using namespace detail;

Decoder::Impl::Impl(DecoderConfig c)
    : cfg(std::move(c)),
      vars(cfg.axis_names, cfg.max_zero_offset_index, cfg.max_variable_elements, cfg.max_variable_bytes),
      x{vars, err, 0},
      main_target(cfg.main_spindle),
      bctx{cfg, x, main_target, {}, {}, 0, false},
      cache(cfg.use_cached_files, cfg.max_cache_number, cfg.max_cache_size_kb),
      meter(cfg.max_lines_read, cfg.stop) {
  modal.slope = cfg.slope_default;
  for (const auto& a : cfg.axis_names) bctx.axis_upper.push_back(to_upper(a));
  for (const auto& a : cfg.axis_aliases) bctx.alias_upper.push_back(to_upper(a));
}

SourceLoc Decoder::Impl::loc(std::size_t pos) const {
  SourceLoc l;
  if (frames.empty()) return l;
  const Frame& f = frames.back();
  l.file = files[f.file_id];
  f.reader->locate(pos, l.line, l.column);
  return l;
}

// ", called from main.nc line 12" for an error in a subroutine (innermost
// caller first), like a compiler's "included from".
// A recursion names each calling line once: repeats of the line before
// (the error's own line first) are counted, not listed.
std::string Decoder::Impl::call_chain() const {
  std::string out;
  if (frames.empty()) return out;
  std::uint16_t last_file = frames.back().file_id;
  std::uint32_t last_line = frames.back().reader->block_pos().line;
  std::size_t repeats = 0;
  auto flush = [&] {
    if (repeats > 0) out += fmt::format(", called from the same line {} time(s)", repeats);
    repeats = 0;
  };
  for (std::size_t i = frames.size(); i-- > 1;) {
    const std::uint16_t file = frames[i - 1].file_id;
    const std::uint32_t line = frames[i - 1].reader->block_pos().line;
    if (file == last_file && line == last_line) {
      ++repeats;
      continue;
    }
    flush();
    out += fmt::format(", called from {} line {}", files[file], line);
    last_file = file;
    last_line = line;
  }
  flush();
  return out;
}

std::optional<std::uint16_t> Decoder::Impl::find_file(std::string_view name) const {
  for (std::size_t i = 0; i < files.size(); ++i)
    if (files[i] == name) return static_cast<std::uint16_t>(i);
  return std::nullopt;
}

std::uint16_t Decoder::Impl::file_id(const std::string& name) {
  if (auto id = find_file(name)) return *id;
  if (files.size() >= 65535) return 65535;
  files.push_back(name);
  return static_cast<std::uint16_t>(files.size() - 1);
}

void Decoder::Impl::flush_warnings() {
  for (auto& w : err.warnings) diags.push_back(make_diagnostic(w.id, loc(w.pos), std::move(w.message)));
  err.warnings.clear();
}

Outcome Decoder::Impl::report(ErrorId id, std::size_t pos, std::string msg, bool is_fatal) {
  err.fail(id, pos, std::move(msg));
  if (is_fatal) fatal = true;
  return Outcome::error;
}

Decoder::Result Decoder::Impl::error_result() {
  flush_warnings();
  if (err.error) {
    Diagnostic d = make_diagnostic(err.error->id, loc(err.error->pos), err.error->message + call_chain());
    err.error.reset();
    // Lint goes on after an error; an error met again (a loop body, a
    // subroutine called many times) is reported once.
    if (!cfg.continue_after_error || reported.emplace(number(d.id), d.loc.file, d.loc.line).second)
      diags.push_back(std::move(d));
  }
  if (!cfg.continue_after_error) fatal = true;
  return Result{Status::error, {}};
}

// A halted meter cut the reading short: whatever the cut made of the block
// (an "unclosed" structure, a missing M30) is no diagnostic of the program.
Decoder::Result Decoder::Impl::next() {
  if (meter.halted() != WorkMeter::Halt::none) return halted();
  const std::size_t known = diags.size();
  Result r = next_block();
  if (meter.halted() == WorkMeter::Halt::none) return r;
  diags.resize(known);
  err.clear();
  fatal = false;  // set by the cut, if at all: halted() says what happened
  return halted();
}

Decoder::Result Decoder::Impl::halted() {
  if (meter.halted() == WorkMeter::Halt::stop) return Result{Status::stopped, {}};
  if (!fatal) {
    const SourceLoc at = loc(0);
    diags.push_back(make_diagnostic(
        ErrorId::NcReadLimit, at,
        fmt::format("the decoder read {} blocks beyond the program's first pass (loop bodies, skipped "
                    "branches, $GOTO searches, subroutines), the run's limit, when it came here; check the "
                    "loops and jumps around this line{}",
                    meter.max_lines(), call_chain())));
    fatal = true;
  }
  return Result{Status::error, {}};
}

Decoder::Result Decoder::Impl::next_block() {
  if (ended) return Result{Status::end, {}};
  if (fatal) return Result{Status::error, {}};
  for (;;) {
    err.clear();
    if (goto_pending) {  // the $GOTO of the block just handed out
      goto_pending = false;
      if (jump(goto_label, goto_pos) == Outcome::error) return error_result();
      continue;
    }
    if (end_pending) {
      ended = true;
      return Result{Status::end, {}};
    }
    if (return_pending) {
      return_pending = false;
      if (do_return() == Outcome::error) return error_result();
      continue;
    }
    if (modal_cycle_due) {  // a modal cycle after the block just handed out
      modal_cycle_due = false;
      if (start_cycle(modal_cycle.target, 0) == Outcome::error) return error_result();
      continue;
    }
    if (frames.empty()) {
      ended = true;
      return Result{Status::end, {}};
    }
    Frame& f = frames.back();
    if (!f.reader->read_block(cfg.max_block_chars)) {
      if (comment_mode) {
        report(ErrorId::NcCommentBlock, 0, "#COMMENT BEGIN is never closed with #COMMENT END", true);
        return error_result();
      }
      Outcome o = end_of_section();
      if (o == Outcome::error) return error_result();
      if (o == Outcome::end) {
        flush_warnings();
        ended = true;
        return Result{Status::end, {}};
      }
      continue;
    }
    ++rows_read;
    if (f.reader->block_too_long()) {
      report(ErrorId::NcBlockTooLong, cfg.max_block_chars,
             fmt::format("the block has more than {} characters; split it", cfg.max_block_chars));
      return error_result();
    }
    Result r;
    Outcome o = process_block(r.block);
    switch (o) {
      case Outcome::nothing:
        flush_warnings();
        continue;
      case Outcome::error:
        return error_result();
      case Outcome::end:
        flush_warnings();
        ended = true;
        return Result{Status::end, {}};
      case Outcome::block:
        flush_warnings();
        note_modal_cycle(r.block);
        r.status = Status::block;
        return r;
    }
  }
}

namespace {

// "#COMMENT BEGIN" etc. at the cursor (case-insensitive, blanks between words).
bool hash_keywords(Cursor c, std::string_view a, std::string_view b) {
  if (!c.match('#')) return false;
  c.skip_spaces();
  if (!c.match_keyword(a)) return false;
  if (b.empty()) return true;
  c.skip_spaces();
  return c.match_keyword(b);
}

bool is_label(const Cursor& c) {
  if (c.peek() != '[') return false;
  std::size_t p = c.pos + 1;
  if (p >= c.s.size() || !(is_alpha(c.s[p]) || c.s[p] == '_')) return false;
  while (p < c.s.size() && is_ident_char(c.s[p])) ++p;
  return p < c.s.size() && c.s[p] == ']';
}

}  // namespace

Outcome Decoder::Impl::process_block(Block& out) {
  Frame& f = frames.back();
  Cursor c{f.reader->text(), 0};
  c.skip_spaces();
  if (comment_mode) {  // only "[N..] #COMMENT END" counts (nesting is not enabled)
    const std::size_t e = comment_phrase_end(c.s, "END");
    if (e == std::string_view::npos) return Outcome::nothing;
    comment_mode = false;
    Cursor rest{c.s, e};
    if (!rest.rest_empty())
      return report(ErrorId::NcCommentEndNotAlone, rest.pos, "#COMMENT END must be alone in its block; move the rest to the next block");
    return Outcome::nothing;
  }
  c.skip_blanks();
  if (c.at_end()) return Outcome::nothing;
  if (c.peek() == '%') return frames.size() > 1 ? end_of_section() : header_in_main_program(c.pos);
  if (c.peek() == '/') {  // block skip: "/" = level 1, "/1" ... "/10"
    std::size_t at = c.pos++;
    int level = 0;
    while (is_digit(c.peek()) && level < 100) level = level * 10 + (c.get() - '0');
    if (level == 0) level = 1;
    if (level > 10) return report(ErrorId::NcBadSkipLevel, at, fmt::format("/{} is not a skip level (1..10)", level));
    if (cfg.skip_mask & (1u << (level - 1))) return Outcome::nothing;
    c.skip_blanks();
  }
  std::optional<std::int64_t> n;
  // "N10" block number, or DIN 66025's main-block mark ":" / ":10".
  bool main_mark = c.peek() == ':';
  if (main_mark && !is_digit(c.peek(1))) {
    ++c.pos;
    c.skip_blanks();
  } else if (main_mark || (upper(c.peek()) == 'N' && is_digit(c.peek(1)))) {
    ++c.pos;
    std::int64_t v = 0;
    int digits = 0;
    while (is_digit(c.peek())) {
      v = v * 10 + (c.get() - '0');
      if (++digits > 15) return report(ErrorId::NcBadValue, c.pos, "block number too long");
    }
    c.match(':');
    n = v;
    c.skip_blanks();
  }
  if (is_label(c)) {
    c.pos = c.s.find(']', c.pos) + 1;
    c.skip_blanks();
  }
  if (c.at_end()) return Outcome::nothing;
  if (var_mode) {
    if (hash_keywords(c, "ENDVAR", "")) {
      var_mode = false;
      return Outcome::nothing;
    }
    if (hash_keywords(c, "COMMENT", "BEGIN")) {
      comment_mode = true;
      return Outcome::nothing;
    }
    return declare(c);
  }
  if (c.peek() == '$' && !Cursor{c.s, c.pos + 1}.peek_keyword("GOTO")) return control(c);
  if (const std::size_t at = find_goto(c.s, c.pos); at != std::string_view::npos)
    return words_with_goto(c, n, out, at);  // "$GOTO [X]", also with commands beside it
  if (c.peek() == '#') {
    if (disable_modal_cycle(c)) return Outcome::nothing;
    if (const std::size_t e = comment_phrase_end(c.s.substr(c.pos), "BEGIN"); e != std::string_view::npos) {
      comment_mode = true;
      comment_start = f.reader->block_pos();
      Cursor rest{c.s, c.pos + e};
      if (!rest.rest_empty())
        return report(ErrorId::NcCommentBeginNotAlone, rest.pos,
                      "#COMMENT BEGIN must be alone in its block; move the rest to the next block");
      return Outcome::nothing;
    }
    if (hash_keywords(c, "COMMENT", "END"))
      return report(ErrorId::NcCommentBlock, c.pos, "#COMMENT END without #COMMENT BEGIN");
    if (hash_keywords(c, "VAR", "")) {
      c.pos += 4;
      if (!c.rest_empty()) return report(ErrorId::NcVarDeclaration, c.pos, "#VAR must be alone in its block");
      var_mode = true;
      return Outcome::nothing;
    }
    if (hash_keywords(c, "ENDVAR", ""))
      return report(ErrorId::NcVarDeclaration, c.pos, "#ENDVAR without #VAR");
  }
  if (upper(c.peek()) == 'L') {
    if (upper(c.peek(1)) == 'L' && (c.peek(2) == ' ' || c.peek(2) == '\t')) return call(c, true);
    if (c.peek(1) == ' ' || c.peek(1) == '\t') return call(c, false);
  }
  return run_words(c, n, out);
}

Outcome Decoder::Impl::run_words(Cursor& c, std::optional<std::int64_t> n, Block& out) {
  Frame& f = frames.back();
  words.clear();
  if (n) words.n.set(*n, 0);
  bctx.plane = modal.plane;  // a cycle's @X/@Y/@Z follow the plane
  if (!parse_words(c, bctx, words) || !check_words(words, bctx, modal)) return Outcome::error;
  const MWord* ret = words.find_m(17);
  if (!ret) ret = words.find_m(29);
  if (ret && frames.size() == 1)
    return report(ErrorId::NcReturnOutsideSubroutine, ret->pos,
                  "M17/M29 ends a subroutine; end the main program with M30");
  if (!apply_words(words, bctx, modal, out)) return Outcome::error;
  slope_default_pending = slope_default_pending || words.slope_default;
  out.file_id = f.file_id;
  out.line = f.reader->block_pos().line;
  out.offset = f.reader->block_pos().offset;
  out.offset_end = f.reader->next_pos().offset;
  out.row = rows_read;
  out.modal = modal;
  out.depth = static_cast<std::uint8_t>(frames.size() - 1);
  if (out.program_end) {
    if (!frames.back().ctl.empty() && !open_structures_closed_later()) {
      err.clear();  // one message for the program: this one
      return report(ErrorId::NcUnclosedControl, 0, "a $ structure before M30/M2 is never closed", true);
    }
    if (frames.size() > 1)
      err.warn(ErrorId::NcEndInSubroutine, words.find_m(30) ? words.find_m(30)->pos : 0,
               "M30/M2 in a subroutine ends the whole program");
    end_pending = true;
  }
  bool content = out.has_axis_words() || out.ijk[0] || out.ijk[1] || out.ijk[2] || out.r || out.f ||
                 !words.g.empty() || !out.m.empty() || !out.h.empty() || out.t || out.d ||
                 out.dwell_s || out.dwell_revs || !out.spindles.empty() || out.hash ||
                 !out.kernel_writes.empty() || out.program_end || out.stop || out.optional_stop;
  if (content) {
    out.slope_default = slope_default_pending;
    slope_default_pending = false;
  }
  if (ret) {
    if (!content) return do_return();
    return_pending = true;
  }
  return content || cfg.every_block ? Outcome::block : Outcome::nothing;
}

// ---------------------------------------------------------------- public API

std::optional<std::uint16_t> Decoder::file_id(std::string_view name) const { return impl_->find_file(name); }

Decoder::Decoder(const std::filesystem::path& program, DecoderConfig cfg)
    : impl_(std::make_unique<Impl>(std::move(cfg))) {
  impl_->open_main(program);
}
Decoder::Decoder(DecoderConfig cfg) : impl_(std::make_unique<Impl>(std::move(cfg))) { impl_->ended = true; }

void Decoder::run_mdi(std::string text) { impl_->open_mdi(std::move(text)); }

Decoder::~Decoder() = default;
Decoder::Decoder(Decoder&&) noexcept = default;
Decoder& Decoder::operator=(Decoder&&) noexcept = default;

Decoder::Result Decoder::next() {
  try {
    return impl_->next();
  } catch (const std::exception& e) {  // allocation failure and the like: never escape
    impl_->diags.push_back(make_diagnostic(ErrorId::NcUnsupported, impl_->loc(0),
                                           fmt::format("internal decoder failure: {}", e.what())));
    impl_->fatal = true;
    return Result{Status::error, {}};
  }
}

const std::vector<Diagnostic>& Decoder::diagnostics() const { return impl_->diags; }

bool Decoder::can_continue() const { return !impl_->fatal && !impl_->ended; }

const std::string& Decoder::file_name(std::uint16_t id) const {
  static const std::string kNone;
  return id < impl_->files.size() ? impl_->files[id] : kNone;
}

std::size_t Decoder::file_count() const { return impl_->files.size(); }

const DecoderConfig& Decoder::config() const { return impl_->cfg; }

std::optional<double> Decoder::get_variable(std::string_view name) const {
  ErrorSlot e;
  ExprCtx x{impl_->vars, e, 0};
  Cursor c{name, 0};
  Lvalue lv;
  double v = 0;
  if (!looks_like_lvalue(c) || !parse_lvalue(c, x, lv) || !c.at_end() || !read_lvalue(lv, x, v))
    return std::nullopt;
  return v;
}

void Decoder::set_kernel_state_reader(const KernelStateReader* reader) { impl_->vars.set_state_reader(reader); }

void Decoder::set_skip_mask(std::uint32_t mask) noexcept { impl_->cfg.skip_mask = mask; }

bool Decoder::set_variable(std::string_view name, double value) {
  ErrorSlot e;
  ExprCtx x{impl_->vars, e, 0};
  Cursor c{name, 0};
  Lvalue lv;
  return looks_like_lvalue(c) && parse_lvalue(c, x, lv) && c.at_end() && write_lvalue(lv, x, value);
}

}  // namespace nck::nc
