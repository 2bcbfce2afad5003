// $GOTO N<expr> and $GOTO [NAME]: jumps to a label (N20: or [NAME] at the
// start of a block) of the same program or subroutine. The target is found
// without keeping the program in memory: a small capped map remembers the
// labels seen by earlier searches; otherwise the search reads forward to
// the end of the section, then from the section's start up to the $GOTO.
// A second pass between the $GOTO and the label tells which $ structures
// the jump leaves and which it enters.
#include <algorithm>
#include <cmath>
#include <string_view>
#include <cstdint>
#include <fmt/format.h>

#include "decoder_impl.hpp"
#include "expression.hpp"

namespace nck::nc {

using namespace detail;

namespace {

constexpr std::size_t kMaxRememberedLabels = 10'000;  // bounded memory for huge programs

enum class Shape : std::uint8_t { plain, open_if, open_loop, close_if, close_loop };

// What one block is for a $GOTO: its label ("" if none) and whether it
// opens or closes a $ structure. A one-line "$IF c $GOTO .." opens nothing.
struct BlockInfo {
  std::string label;
  Shape shape = Shape::plain;
  bool comment_begin = false, comment_end = false, section_end = false;
};

bool contains_goto(std::string_view rest) {
  for (std::size_t i = 0; i + 5 <= rest.size(); ++i)
    if (rest[i] == '$' && iequals(rest.substr(i + 1, 4), "GOTO")) return true;
  return false;
}

Shape shape_of(std::string_view kw, std::string_view rest) {
  if (iequals(kw, "IF")) return contains_goto(rest) ? Shape::plain : Shape::open_if;
  if (iequals(kw, "ENDIF")) return Shape::close_if;
  for (std::string_view k : {"WHILE", "FOR", "DO", "REPEAT", "SWITCH"})
    if (iequals(kw, k)) return Shape::open_loop;
  for (std::string_view k : {"ENDWHILE", "ENDFOR", "ENDDO", "UNTIL", "ENDSWITCH"})
    if (iequals(kw, k)) return Shape::close_loop;
  return Shape::plain;
}

BlockInfo inspect(std::string_view text) {
  BlockInfo b;
  Cursor c{text, 0};
  c.skip_spaces();
  if (c.peek() == '%') {
    b.section_end = true;
    return b;
  }
  if (c.match('#')) {
    c.skip_spaces();
    if (c.match_keyword("COMMENT")) {
      c.skip_spaces();
      b.comment_begin = c.match_keyword("BEGIN");
      b.comment_end = !b.comment_begin && c.match_keyword("END");
    }
    return b;
  }
  c.skip_blanks();
  if (c.match('/'))
    while (is_digit(c.peek())) ++c.pos;
  c.skip_blanks();
  if (upper(c.peek()) == 'N' && is_digit(c.peek(1))) {
    std::size_t from = ++c.pos;
    while (is_digit(c.peek())) ++c.pos;
    std::string digits(text.substr(from, c.pos - from));
    digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size() - 1));  // N010: = N10:
    if (c.match(':')) b.label = "N" + digits;
    c.skip_blanks();
  }
  if (c.peek() == '[') {
    std::size_t end = text.find(']', c.pos);
    if (end != std::string_view::npos) {
      b.label = "[" + to_upper(text.substr(c.pos + 1, end - c.pos - 1)) + "]";
      c.pos = end + 1;
      c.skip_blanks();
    }
  }
  if (c.match('$')) {
    std::string_view kw = c.read_ident();
    b.shape = shape_of(kw, text.substr(c.pos));
  }
  return b;
}

struct Jump {
  Decoder::Impl& d;
  Frame& f;
  SourcePos from;  // the $GOTO block

  void remember(const std::string& label, SourcePos p) {
    if (f.labels.size() < kMaxRememberedLabels) f.labels.try_emplace(label, p);
  }

  // Reads blocks from `p` on; stops at the label (true) or at `stop_offset`,
  // the section's end or the file's end (false).
  bool search(SourcePos p, std::uint64_t stop_offset, const std::string& label, SourcePos& found) {
    SourceReader& r = *f.reader;
    r.seek(p);
    bool in_comment = false;
    while (r.read_block(d.cfg.max_block_chars)) {
      SourcePos here = r.block_pos();
      if (here.offset > stop_offset) return false;  // the $GOTO block itself may be the label
      BlockInfo b = inspect(r.text());
      if (b.section_end) return false;
      if (in_comment || b.comment_begin) {
        in_comment = !b.comment_end;
        continue;
      }
      if (b.label.empty()) continue;
      remember(b.label, here);
      if (b.label == label) {
        found = here;
        return true;
      }
    }
    return false;
  }

  // Structures between the blocks at offsets a < b: `opened` = opened after
  // a and still open before b; `closed` = closed there without being opened.
  void between(SourcePos a, std::uint64_t b_offset, std::vector<Shape>& opened, std::vector<Shape>& closed) {
    SourceReader& r = *f.reader;
    r.seek(a);
    bool in_comment = false;
    while (r.read_block(d.cfg.max_block_chars) && r.block_pos().offset < b_offset) {
      BlockInfo bi = inspect(r.text());
      if (in_comment || bi.comment_begin) {
        in_comment = !bi.comment_end;
        continue;
      }
      if (bi.shape == Shape::open_if || bi.shape == Shape::open_loop) opened.push_back(bi.shape);
      else if (bi.shape == Shape::close_if || bi.shape == Shape::close_loop) {
        if (!opened.empty()) opened.pop_back();
        else closed.push_back(bi.shape == Shape::close_if ? Shape::open_if : Shape::open_loop);
      }
    }
  }

  // Puts the $GOTO block back into the reader (for the error's line).
  Outcome fail(ErrorId id, std::size_t pos, std::string msg, bool fatal = false) {
    f.reader->seek(from);
    f.reader->read_block(d.cfg.max_block_chars);
    return d.report(id, pos, std::move(msg), fatal);
  }

  Outcome run(const std::string& label, std::size_t pos) {
    SourcePos target;
    auto hit = f.labels.find(label);
    if (hit != f.labels.end()) target = hit->second;
    else if (!search(f.reader->next_pos(), UINT64_MAX, label, target) &&
             !search(f.start, from.offset, label, target))
      return fail(ErrorId::NcLabelNotFound, pos,
                  fmt::format("$GOTO {}: no label {} in {} (this program or subroutine level; write N20: or "
                              "[NAME] at a block's start)",
                              label, label, d.files[f.file_id]));
    bool backward = target.offset <= from.offset;
    std::vector<Shape> opened, closed;
    if (backward) between(target, from.offset, opened, closed);
    else between(SourcePos{from.offset, from.line}, target.offset, opened, closed);
    // Backward: `opened` are left, `closed` entered. Forward: the reverse.
    // (The forward pass starts at the $GOTO block itself, which opens nothing.)
    std::vector<Shape>& entered = backward ? closed : opened;
    std::size_t left = backward ? opened.size() : closed.size();
    for (Shape s : entered)
      if (s != Shape::open_if)
        return fail(ErrorId::NcGotoIntoBlock, pos,
                    fmt::format("$GOTO {} (line {}) jumps into a $WHILE/$FOR/$DO/$REPEAT/$SWITCH body from outside",
                                label, target.line));
    if (left > f.ctl.size())
      return fail(ErrorId::NcControlStructure, pos, fmt::format("$GOTO {}: the $ structures are not nested", label));
    for (std::size_t i = 0; i + left < f.ctl.size(); ++i)
      if (f.ctl[i].kind != CtlKind::if_)
        return fail(ErrorId::NcGotoInLoop, pos,
                    fmt::format("$GOTO {} (line {}) stays inside the $ loop or $SWITCH of line {}; a jump must "
                                "leave it completely",
                                label, target.line, f.ctl[i].start.line));
    if (backward && ++d.loop_iterations > d.cfg.max_loop_iterations)
      return fail(ErrorId::NcLoopLimit, pos,
                  fmt::format("the program's loops ran {} iterations in all, the run's limit, while jumping back "
                              "with $GOTO {}; check the condition that should end it",
                              d.cfg.max_loop_iterations, label),
                  true);
    f.ctl.resize(f.ctl.size() - left);
    for (std::size_t i = 0; i < entered.size(); ++i) {  // into $IF bodies: their $ELSE/$ENDIF follow
      Ctl t;
      t.kind = CtlKind::if_;
      t.start = target;
      f.ctl.push_back(t);
    }
    d.loop_reentry = false;
    f.reader->seek(target);
    return Outcome::nothing;
  }
};

// "N<expr>" or "[NAME]" after $GOTO; "" after an error.
std::string target_label(Decoder::Impl& d, Cursor& c) {
  c.skip_spaces();
  if (upper(c.peek()) == 'N') {
    ++c.pos;
    double v = 0;
    if (!eval_expr(c, d.x, v)) return {};
    if (!(v >= 0) || v > 1e15 || std::fabs(v - std::round(v)) > 1e-9) {
      d.err.fail(ErrorId::NcGotoSyntax, c.pos, fmt::format("$GOTO N{}: a block number is a whole number >= 0", v));
      return {};
    }
    return fmt::format("N{}", static_cast<std::int64_t>(std::llround(v)));
  }
  if (c.match('[')) {
    std::size_t from = c.pos;
    std::string_view name = c.read_ident();
    if (!name.empty() && c.match(']')) return "[" + to_upper(name) + "]";
    d.err.fail(ErrorId::NcGotoSyntax, from, "$GOTO [NAME]: a name of letters, digits and _ in [ ] expected");
    return {};
  }
  d.err.fail(ErrorId::NcGotoSyntax, c.pos, "$GOTO must be followed by N<block number> or [NAME]");
  return {};
}

}  // namespace

Outcome Decoder::Impl::go_to(Cursor& c, std::size_t pos) {
  std::string label = target_label(*this, c);
  if (label.empty()) return Outcome::error;
  if (!c.rest_empty())
    return report(ErrorId::NcGotoSyntax, c.pos, "nothing may follow the $GOTO target in its block");
  return jump(label, pos);
}

Outcome Decoder::Impl::jump(const std::string& label, std::size_t pos) {
  Frame& f = frames.back();
  return Jump{*this, f, f.reader->block_pos()}.run(label, pos);
}

std::size_t detail::find_goto(std::string_view text, std::size_t from) {
  // Most blocks have no '$' at all: one memchr instead of the walk below.
  if (text.find('$', from) == std::string_view::npos) return std::string_view::npos;
  for (std::size_t i = from; i < text.size(); ++i) {
    const char ch = text[i];
    if (ch == ';') return std::string_view::npos;
    if (ch == '(') {  // a comment, nested
      int depth = 0;
      for (; i < text.size(); ++i)
        if (text[i] == '(') ++depth;
        else if (text[i] == ')' && --depth == 0) break;
      continue;
    }
    if (ch == '"') {  // a string (#MSG ...)
      const std::size_t end = text.find('"', i + 1);
      if (end == std::string_view::npos) return std::string_view::npos;
      i = end;
      continue;
    }
    if (ch == '$' && Cursor{text, i + 1}.peek_keyword("GOTO")) return i;
  }
  return std::string_view::npos;
}

// The block's words without "$GOTO <target>" (blanked, so columns stay):
// they make the block; the jump follows when it has been handed out.
Outcome Decoder::Impl::words_with_goto(Cursor& c, std::optional<std::int64_t> n, Block& out, std::size_t at) {
  Cursor g{c.s, at + 5};
  std::string label = target_label(*this, g);
  if (label.empty()) return Outcome::error;
  goto_text.assign(c.s);
  std::fill(goto_text.begin() + static_cast<std::ptrdiff_t>(at), goto_text.begin() + static_cast<std::ptrdiff_t>(g.pos),
            ' ');
  Cursor words_cursor{goto_text, c.pos};
  if (words_cursor.rest_empty()) return jump(label, at);
  const Outcome o = run_words(words_cursor, n, out);
  if (o == Outcome::nothing) return jump(label, at);
  if (o == Outcome::block && !end_pending && !return_pending) {
    goto_pending = true;
    goto_label = std::move(label);
    goto_pos = at;
  }
  return o;
}

}  // namespace nck::nc
