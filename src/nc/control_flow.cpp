// $ statements: $IF/$ELSEIF/$ELSE/$ENDIF, $WHILE/$ENDWHILE, $FOR/$ENDFOR,
// $DO/$ENDDO, $REPEAT/$UNTIL, $SWITCH/$CASE/$DEFAULT/$ENDSWITCH, $BREAK,
// $CONTINUE. A condition is TRUE when its value's magnitude is at least 0.5
// (TF5200 "The IF - ELSE branch": decimal values are allowed), $CASE values
// match the $SWITCH value within 0.001.
// Loops jump back by seeking the reader to the remembered byte offset of
// their opening statement; untaken branches are skipped by scanning ahead
// with a nesting counter, so no block is kept in memory.
#include <cmath>
#include <fmt/format.h>

#include "decoder_impl.hpp"

namespace nck::nc {

using namespace detail;

namespace {

enum class Kw : std::uint8_t { none, if_, elseif, else_, endif, while_, endwhile, for_, endfor,
                               do_, enddo, repeat_, until, switch_, case_, default_, endswitch, break_,
                               continue_, goto_, unknown };

Kw keyword_of(std::string_view id) {
  struct E { std::string_view s; Kw k; };
  static constexpr E table[] = {
      {"IF", Kw::if_}, {"ELSEIF", Kw::elseif}, {"ELSE", Kw::else_}, {"ENDIF", Kw::endif},
      {"WHILE", Kw::while_}, {"ENDWHILE", Kw::endwhile}, {"FOR", Kw::for_}, {"ENDFOR", Kw::endfor},
      {"DO", Kw::do_}, {"ENDDO", Kw::enddo}, {"REPEAT", Kw::repeat_}, {"UNTIL", Kw::until},
      {"SWITCH", Kw::switch_}, {"CASE", Kw::case_},
      {"DEFAULT", Kw::default_}, {"ENDSWITCH", Kw::endswitch}, {"BREAK", Kw::break_},
      {"CONTINUE", Kw::continue_}, {"GOTO", Kw::goto_}};
  for (const auto& e : table)
    if (iequals(id, e.s)) return e.k;
  return Kw::unknown;
}

Ctl mk(CtlKind k, SourcePos start) {
  Ctl c;
  c.kind = k;
  c.start = start;
  return c;
}

bool is_opener(Kw k) {
  return k == Kw::if_ || k == Kw::while_ || k == Kw::for_ || k == Kw::do_ || k == Kw::repeat_ || k == Kw::switch_;
}
bool is_closer(Kw k) {
  return k == Kw::endif || k == Kw::endwhile || k == Kw::endfor || k == Kw::enddo || k == Kw::until ||
         k == Kw::endswitch;
}

Kw closer_of(const Ctl& t) {
  switch (t.kind) {
    case CtlKind::if_: return Kw::endif;
    case CtlKind::while_: return Kw::endwhile;
    case CtlKind::for_: return Kw::endfor;
    case CtlKind::do_: return t.until ? Kw::until : Kw::enddo;
    case CtlKind::switch_: return Kw::endswitch;
  }
  return Kw::endif;
}

// TF5200: a condition is FALSE in -0.5 < value < 0.5, TRUE otherwise.
bool truth(double v) { return std::fabs(v) >= 0.5; }

// The $ keyword of a block (after skip mark, N number and label); the
// cursor is left after it. Kw::none for other blocks.
Kw block_keyword(Cursor& c) {
  c.skip_blanks();
  if (c.peek() == '/') {
    ++c.pos;
    while (is_digit(c.peek())) ++c.pos;
    c.skip_blanks();
  }
  if (upper(c.peek()) == 'N' && is_digit(c.peek(1))) {
    ++c.pos;
    while (is_digit(c.peek())) ++c.pos;
    c.match(':');
    c.skip_blanks();
  }
  if (!c.match('$')) return Kw::none;
  Kw k = keyword_of(c.read_ident());
  if (k == Kw::if_) {  // "$IF cond $GOTO N20" opens no structure
    Cursor rest = c;
    while (!rest.at_end())
      if (rest.get() == '$' && rest.match_keyword("GOTO")) return Kw::goto_;
  }
  return k;
}

}  // namespace

namespace {

struct Flow {
  Decoder::Impl& d;

  Frame& frame() { return d.frames.back(); }
  Outcome fail(ErrorId id, std::size_t pos, std::string msg, bool fatal = false) {
    return d.report(id, pos, std::move(msg), fatal);
  }

  // Reads ahead to the first statement in `stops` at nesting depth 0 (or a
  // stray closer). The reader then holds that block; `c` points after the
  // keyword. Comments blocks are skipped as a whole.
  bool skip(std::initializer_list<Kw> stops, Kw& found, Cursor& c) {
    int depth = 0;
    bool in_comment = false;
    SourceReader& r = *frame().reader;
    while (r.read_block(d.cfg.max_block_chars)) {
      c = Cursor{r.text(), 0};
      c.skip_spaces();
      if (c.peek() == '#') {
        Cursor h = c;
        ++h.pos;
        h.skip_spaces();
        if (h.match_keyword("COMMENT")) {
          h.skip_spaces();
          if (h.match_keyword("BEGIN")) in_comment = true;
          else if (h.match_keyword("END")) in_comment = false;
          continue;
        }
      }
      if (in_comment) continue;
      if (c.peek() == '%') break;  // the section ends: unclosed
      Kw k = block_keyword(c);
      if (k == Kw::none || k == Kw::unknown) continue;
      if (is_opener(k)) { ++depth; continue; }
      if (is_closer(k) && depth > 0) { --depth; continue; }
      if (depth > 0) continue;
      for (Kw s : stops)
        if (s == k) { found = k; return true; }
      if (is_closer(k)) { found = k; return true; }  // a closer of the wrong kind
    }
    fail(ErrorId::NcUnclosedControl, 0, "a $ structure is not closed before the end of the program or subroutine", true);
    return false;
  }

  // `then_goto` (only $IF passes it): "$IF cond $GOTO target" in one block;
  // `c` is then left after the $GOTO keyword.
  bool condition(Cursor& c, double& v, bool* then_goto = nullptr) {
    c.skip_spaces();
    if (c.at_end()) return d.err.fail(ErrorId::NcExprSyntax, c.pos, "condition expected");
    if (!eval_expr(c, d.x, v)) return false;
    c.skip_spaces();
    if (then_goto && c.peek() == '$') {
      Cursor g{c.s, c.pos + 1};
      if (g.match_keyword("GOTO")) {
        c = g;
        *then_goto = true;
        return true;
      }
    }
    if (c.peek() == '$')
      return d.err.fail(ErrorId::NcControlStructure, c.pos, "only $GOTO may follow an $IF condition in its block");
    if (!c.rest_empty())
      return d.err.fail(ErrorId::NcExprSyntax, c.pos, "unexpected text after the condition");
    return true;
  }

  Outcome expect_top(CtlKind k, std::size_t pos, std::string_view what) {
    auto& ctl = frame().ctl;
    if (ctl.empty() || ctl.back().kind != k)
      return fail(ErrorId::NcControlStructure, pos, fmt::format("{} without its opening statement", what));
    return Outcome::nothing;
  }

  // One budget for every loop of the run, so nested loops cannot multiply it.
  bool count_iteration(const Ctl& t, std::size_t pos) {
    if (++d.loop_iterations <= d.cfg.max_loop_iterations) return true;
    fail(ErrorId::NcLoopLimit, pos,
         fmt::format("the program's loops ran {} iterations in all, the run's limit, while repeating the loop "
                     "of line {}; check its condition",
                     d.cfg.max_loop_iterations, t.start.line),
         true);
    return false;
  }

  // $IF false or $ELSEIF false: find the branch to run.
  Outcome skip_if_branch() {
    for (;;) {
      Kw k = Kw::none;
      Cursor c;
      if (!skip({Kw::elseif, Kw::else_, Kw::endif}, k, c)) return Outcome::error;
      if (k == Kw::endif) return Outcome::nothing;
      if (k == Kw::else_) {
        frame().ctl.push_back(mk(CtlKind::if_, frame().reader->block_pos()));
        return Outcome::nothing;
      }
      if (k != Kw::elseif) return fail(ErrorId::NcControlStructure, 0, "$IF closed by the wrong statement");
      double v = 0;
      if (!condition(c, v)) return Outcome::error;
      if (truth(v)) {
        frame().ctl.push_back(mk(CtlKind::if_, frame().reader->block_pos()));
        return Outcome::nothing;
      }
    }
  }

  // Leaves the innermost `levels` structures by skipping to their closers.
  bool leave(std::size_t levels) {
    auto& ctl = frame().ctl;
    for (std::size_t i = 0; i < levels; ++i) {
      Kw want = closer_of(ctl.back());
      Kw k = Kw::none;
      Cursor c;
      if (!skip({want}, k, c)) return false;
      if (k != want) {
        fail(ErrorId::NcControlStructure, 0, "structures are not properly nested");
        return false;
      }
      ctl.pop_back();
    }
    return true;
  }

  Outcome loop_for(Cursor& c, std::size_t pos) {
    auto& ctl = frame().ctl;
    SourcePos here = frame().reader->block_pos();
    bool again = d.loop_reentry && d.reentry_offset == here.offset && !ctl.empty() &&
                 ctl.back().kind == CtlKind::for_ && ctl.back().start.offset == here.offset;
    d.loop_reentry = false;
    if (again) {
      Ctl& t = ctl.back();
      double v = 0;
      if (!read_lvalue(t.var, d.x, v) || !write_lvalue(t.var, d.x, v + t.step)) return Outcome::error;
      if (!count_iteration(t, pos)) return Outcome::error;
    } else {
      Ctl t = mk(CtlKind::for_, here);
      c.skip_spaces();
      if (!looks_like_lvalue(c))
        return fail(ErrorId::NcExprSyntax, c.pos, "$FOR needs a counter: $FOR P1 = start, end[, step]");
      if (!parse_lvalue(c, d.x, t.var)) return Outcome::error;
      c.skip_spaces();
      double start = 0;
      if (!c.match('=') || !eval_expr(c, d.x, start))
        return d.err.failed() ? Outcome::error : fail(ErrorId::NcExprSyntax, c.pos, "'= start' expected");
      c.skip_spaces();
      if (!c.match(',') || !eval_expr(c, d.x, t.end))
        return d.err.failed() ? Outcome::error : fail(ErrorId::NcExprSyntax, c.pos, "', end' expected");
      c.skip_spaces();
      if (c.match(',') && !eval_expr(c, d.x, t.step)) return Outcome::error;
      if (!c.rest_empty()) return fail(ErrorId::NcExprSyntax, c.pos, "unexpected text after $FOR");
      if (t.step == 0) return fail(ErrorId::NcLoopLimit, pos, "$FOR step 0 never ends", false);
      if (!write_lvalue(t.var, d.x, start)) return Outcome::error;
      ctl.push_back(std::move(t));
    }
    Ctl& t = ctl.back();
    double v = 0;
    if (!read_lvalue(t.var, d.x, v)) return Outcome::error;
    bool run = t.step > 0 ? v <= t.end + 1e-9 : v >= t.end - 1e-9;
    if (run) return Outcome::nothing;
    return leave(1) ? Outcome::nothing : Outcome::error;
  }

  Outcome loop_while(Cursor& c, std::size_t pos) {
    auto& ctl = frame().ctl;
    SourcePos here = frame().reader->block_pos();
    bool again = d.loop_reentry && d.reentry_offset == here.offset && !ctl.empty() &&
                 ctl.back().kind == CtlKind::while_ && ctl.back().start.offset == here.offset;
    d.loop_reentry = false;
    if (!again) ctl.push_back(mk(CtlKind::while_, here));
    else if (!count_iteration(ctl.back(), pos)) return Outcome::error;
    double v = 0;
    if (!condition(c, v)) return Outcome::error;
    if (truth(v)) return Outcome::nothing;
    return leave(1) ? Outcome::nothing : Outcome::error;
  }

  Outcome jump_back(Ctl& t) {
    d.loop_reentry = true;
    d.reentry_offset = t.start.offset;
    frame().reader->seek(t.start);
    return Outcome::nothing;
  }

  // $ENDDO c repeats while c is TRUE, $UNTIL c until c is TRUE.
  Outcome enddo(Cursor& c, std::size_t pos, bool until) {
    const char* what = until ? "$UNTIL" : "$ENDDO";
    if (expect_top(CtlKind::do_, pos, what) == Outcome::error) return Outcome::error;
    if (frame().ctl.back().until != until)
      return fail(ErrorId::NcControlStructure, pos,
                  until ? "$UNTIL closes a $DO: write $ENDDO" : "$ENDDO closes a $REPEAT: write $UNTIL");
    double v = 0;
    if (!condition(c, v)) return Outcome::error;
    Ctl& t = frame().ctl.back();
    if (truth(v) == until) {
      frame().ctl.pop_back();
      return Outcome::nothing;
    }
    if (!count_iteration(t, pos)) return Outcome::error;
    frame().reader->seek(t.body);
    return Outcome::nothing;
  }

  // "$SWITCH P1=INT[P1*P2/P3]": the value may be assigned to a variable
  // first (TF5200 "Switch branching"), the switch then takes that value.
  Outcome start_switch(Cursor& c) {
    double v = 0;
    c.skip_spaces();
    Cursor probe = c;
    Lvalue lv;
    bool assigned = false;
    if (looks_like_lvalue(probe)) {
      if (!parse_lvalue(probe, d.x, lv)) return Outcome::error;  // not a value either
      probe.skip_spaces();
      if (probe.peek() == '=' && probe.peek(1) != '=') {
        ++probe.pos;
        c = probe;
        assigned = true;
      }
    }
    if (!condition(c, v)) return Outcome::error;
    if (assigned && !write_lvalue(lv, d.x, v)) return Outcome::error;
    frame().ctl.push_back(mk(CtlKind::switch_, frame().reader->block_pos()));
    for (;;) {
      Kw k = Kw::none;
      Cursor cc;
      if (!skip({Kw::case_, Kw::default_, Kw::endswitch}, k, cc)) return Outcome::error;
      if (k == Kw::default_) return Outcome::nothing;
      if (k == Kw::endswitch) {
        frame().ctl.pop_back();
        return Outcome::nothing;
      }
      if (k != Kw::case_) return fail(ErrorId::NcControlStructure, 0, "$SWITCH closed by the wrong statement");
      double cv = 0;
      if (!condition(cc, cv)) return Outcome::error;
      if (std::fabs(cv - v) < 0.001) return Outcome::nothing;
    }
  }

  // Innermost loop (or switch for $BREAK); levels above it counted.
  std::optional<std::size_t> innermost_loop(bool with_switch) {
    auto& ctl = frame().ctl;
    for (std::size_t i = ctl.size(); i-- > 0;) {
      CtlKind k = ctl[i].kind;
      if (k == CtlKind::while_ || k == CtlKind::for_ || k == CtlKind::do_ || (with_switch && k == CtlKind::switch_))
        return ctl.size() - i;
    }
    return std::nullopt;
  }

  Outcome run(Cursor& c) {
    std::size_t pos = c.pos;
    ++c.pos;
    std::string_view id = c.read_ident();
    Kw k = keyword_of(id);
    auto& ctl = frame().ctl;
    switch (k) {
      case Kw::if_: {
        double v = 0;
        bool then_goto = false;
        if (!condition(c, v, &then_goto)) return Outcome::error;
        if (then_goto) return truth(v) ? d.go_to(c, pos) : Outcome::nothing;  // no $ENDIF follows
        if (truth(v)) {
          ctl.push_back(mk(CtlKind::if_, frame().reader->block_pos()));
          return Outcome::nothing;
        }
        return skip_if_branch();
      }
      case Kw::elseif:
      case Kw::else_:
        if (expect_top(CtlKind::if_, pos, k == Kw::else_ ? "$ELSE" : "$ELSEIF") == Outcome::error)
          return Outcome::error;
        return leave(1) ? Outcome::nothing : Outcome::error;  // the taken branch ends here
      case Kw::endif:
        if (expect_top(CtlKind::if_, pos, "$ENDIF") == Outcome::error) return Outcome::error;
        ctl.pop_back();
        return c.rest_empty() ? Outcome::nothing : fail(ErrorId::NcExprSyntax, c.pos, "unexpected text after $ENDIF");
      case Kw::while_: return loop_while(c, pos);
      case Kw::endwhile:
        if (expect_top(CtlKind::while_, pos, "$ENDWHILE") == Outcome::error) return Outcome::error;
        return jump_back(ctl.back());
      case Kw::for_: return loop_for(c, pos);
      case Kw::endfor:
        if (expect_top(CtlKind::for_, pos, "$ENDFOR") == Outcome::error) return Outcome::error;
        return jump_back(ctl.back());
      case Kw::do_:
      case Kw::repeat_: {
        Ctl t = mk(CtlKind::do_, frame().reader->block_pos());
        t.body = frame().reader->next_pos();
        t.until = k == Kw::repeat_;
        ctl.push_back(t);
        return Outcome::nothing;
      }
      case Kw::enddo: return enddo(c, pos, false);
      case Kw::until: return enddo(c, pos, true);
      case Kw::switch_: return start_switch(c);
      case Kw::case_:
      case Kw::default_:  // reached from the case above: falls through
        return expect_top(CtlKind::switch_, pos, k == Kw::case_ ? "$CASE" : "$DEFAULT");
      case Kw::endswitch:
        if (expect_top(CtlKind::switch_, pos, "$ENDSWITCH") == Outcome::error) return Outcome::error;
        ctl.pop_back();
        return Outcome::nothing;
      case Kw::break_: {
        auto lv = innermost_loop(true);
        if (!lv) return fail(ErrorId::NcControlStructure, pos, "$BREAK outside a loop or $SWITCH");
        return leave(*lv) ? Outcome::nothing : Outcome::error;
      }
      case Kw::continue_: {
        auto lv = innermost_loop(false);
        if (!lv) return fail(ErrorId::NcControlStructure, pos, "$CONTINUE outside a loop");
        if (!leave(*lv - 1)) return Outcome::error;
        Ctl& t = ctl.back();
        if (t.kind != CtlKind::do_) return jump_back(t);
        Kw kk = Kw::none;
        Cursor cc;
        const Kw closer = closer_of(t);
        if (!skip({closer}, kk, cc)) return Outcome::error;
        return enddo(cc, 0, closer == Kw::until);
      }
      case Kw::goto_: return d.go_to(c, pos);
      default:
        return fail(ErrorId::NcUnknownControl, pos, fmt::format("${} is not a $ statement", id));
    }
  }
};

}  // namespace

Outcome Decoder::Impl::control(Cursor& c) { return Flow{*this}.run(c); }

// M30 inside a structure is fine ($IF .. M30 .. $ENDIF), but only when its
// closing statements follow: read on to them (the program ends anyway).
bool Decoder::Impl::open_structures_closed_later() {
  return Flow{*this}.leave(frames.back().ctl.size());
}

}  // namespace nck::nc
