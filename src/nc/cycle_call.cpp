// Cycle calls: L CYCLE [NAME=<file> [MODAL_MOVE|MODAL|MODAL_BLOCK] @P1=<expr> ..]
// (a global file found on the cycle search path) and LL CYCLE [NAME=<section> ..]
// (a %L section of the calling file). A cycle is a subroutine whose level
// holds the @P transfer parameters; the caller's modal G functions and feed
// come back when it ends (P-CHAN-00210 at its default 0). A modal call runs
// the cycle at once and again after every motion block (MODAL_MOVE) or
// every block (MODAL_BLOCK) of the calling level until #DISABLE MODAL CYCLE.
#include <fmt/format.h>

#include "decoder_impl.hpp"

namespace nck::nc {

using namespace detail;

namespace {

struct CallText {
  CycleTarget target;
  bool modal_move = false;
  bool modal_block = false;
};

Outcome syntax(Decoder::Impl& d, std::size_t pos, std::string msg) {
  return d.report(ErrorId::NcCycleSyntax, pos, std::move(msg));
}

// Reads the bracket list after CYCLE; values are evaluated in the caller's scope.
Outcome read_call(Decoder::Impl& d, Cursor& c, CallText& out) {
  c.skip_spaces();
  if (!c.match('[')) return syntax(d, c.pos, "'[' expected after CYCLE: L CYCLE [NAME=<file> @P1=..]");
  for (;;) {
    c.skip_spaces();
    if (c.at_end()) return syntax(d, c.pos, "the cycle call is not closed with ']' (end a continued line with \\)");
    if (c.match(']')) break;
    const std::size_t pos = c.pos;
    if (c.match_keyword("NAME")) {
      c.skip_spaces();
      if (!c.match('=')) return syntax(d, c.pos, "'=' expected after NAME");
      c.skip_spaces();
      const std::size_t b = c.pos;
      while (!c.at_end() && c.peek() != ' ' && c.peek() != '\t' && c.peek() != ']') ++c.pos;
      if (c.pos == b) return syntax(d, b, "NAME= needs the cycle's file name");
      out.target.name = std::string(c.s.substr(b, c.pos - b));
      continue;
    }
    if (c.match_keyword("MODAL_MOVE") || c.match_keyword("MODAL")) {
      out.modal_move = true;
      continue;
    }
    if (c.match_keyword("MODAL_BLOCK")) {
      out.modal_block = true;
      continue;
    }
    if (looks_like_lvalue(c) && c.peek() == '@') {
      Lvalue lv;
      if (!parse_lvalue(c, d.x, lv)) return Outcome::error;
      c.skip_spaces();
      if (!c.match('=')) return syntax(d, c.pos, fmt::format("'=' expected after @P{}", lv.p));
      double v = 0;
      if (!eval_expr(c, d.x, v)) return Outcome::error;
      if (!out.target.params.emplace(lv.p, v).second)
        return syntax(d, pos, fmt::format("@P{} is given twice in this call", lv.p));
      continue;
    }
    const std::size_t e = c.s.find_first_of(" \t]", pos);
    return syntax(d, pos,
                  fmt::format("'{}' is not part of a cycle call (NAME=, MODAL_MOVE, MODAL_BLOCK, @P<n>=)",
                              c.s.substr(pos, e == std::string_view::npos ? c.s.size() - pos : e - pos)));
  }
  if (out.target.name.empty()) return syntax(d, c.pos, "the cycle call has no NAME=<file>");
  if (out.modal_move && out.modal_block) return syntax(d, c.pos, "MODAL_MOVE and MODAL_BLOCK exclude each other");
  if (!c.rest_empty()) return syntax(d, c.pos, "a cycle call must be alone in its block");
  return Outcome::nothing;
}

// The program's folder first, then the machine's and the command line's folders.
std::vector<std::filesystem::path> search_dirs(const Decoder::Impl& d) {
  std::vector<std::filesystem::path> dirs;
  auto add = [&](const std::filesystem::path& p) {
    for (const auto& x : dirs)
      if (x == p) return;
    dirs.push_back(p);
  };
  add(d.frames.back().path.parent_path());
  add(d.frames.front().path.parent_path());
  for (const auto& p : d.cfg.cycle_dirs) add(p);
  return dirs;
}

}  // namespace

Outcome Decoder::Impl::cycle_call(Cursor& c, bool local, std::size_t at) {
  c.match_keyword("CYCLE");
  CallText call;
  call.target.local = local;
  if (Outcome o = read_call(*this, c, call); o == Outcome::error) return o;
  if (modal_cycle.active && frames.size() <= modal_cycle.depth)
    return report(ErrorId::NcCycleWhileModalCycle, at,
                  fmt::format("the modal cycle '{}' is still active; #DISABLE MODAL CYCLE first",
                              modal_cycle.target.name));
  CycleTarget& t = call.target;
  Frame& caller = frames.back();
  if (local) {
    const Section* s = caller.index->local(to_upper(t.name));
    if (!s)
      return report(ErrorId::NcCycleNotFound, at,
                    fmt::format("no local cycle '%L {}' in {}", t.name, files[caller.file_id]));
    keep_text_for_local_calls(caller);
    t.path = caller.path;
    t.file_id = caller.file_id;
    t.mem = caller.mem;
    t.index = caller.index;
    t.body = s->body;
  } else {
    std::filesystem::path p(t.name);
    std::string looked;
    std::error_code ec;
    if (p.is_relative()) {
      for (const auto& dir : search_dirs(*this)) {
        std::filesystem::path q = dir / p;
        looked += fmt::format("{}{}", looked.empty() ? "" : ", ", q.string());
        if (std::filesystem::is_regular_file(q, ec)) {
          t.path = q;
          break;
        }
      }
    } else if (std::filesystem::is_regular_file(p, ec)) {
      t.path = p;
    } else {
      looked = p.string();
    }
    if (t.path.empty())
      return report(ErrorId::NcCycleNotFound, at, fmt::format("cycle '{}' not found; looked for {}", t.name, looked));
    t.file_id = file_id(t.path.string());
  }
  if (call.modal_move || call.modal_block) {
    modal_cycle.active = true;
    modal_cycle.every_block = call.modal_block;
    modal_cycle.depth = frames.size();
    modal_cycle.target = t;
  }
  return start_cycle(t, at);
}

Outcome Decoder::Impl::start_cycle(const CycleTarget& t, std::size_t at) {
  if (frames.size() > cfg.max_subroutine_depth)
    return report(ErrorId::NcSubroutineDepth, at,
                  fmt::format("more than {} nested subroutine or cycle calls", cfg.max_subroutine_depth), true);
  Frame f;
  if (t.local) {
    if (!open_local_frame(t.path, t.mem, t.index, t.body, f))
      return report(ErrorId::NcFileUnreadable, at, fmt::format("cannot reopen '{}'", t.path.string()));
  } else {
    if (!open_frame(t.path, true, f))
      return report(open_error(ErrorId::NcFileUnreadable), at, fmt::format("cannot read the cycle '{}'", t.path.string()));
    if (enter_program(f, at) == Outcome::error) return Outcome::error;
  }
  f.file_id = t.file_id;
  f.start = f.reader->next_pos();
  f.cycle_modal = modal;
  frames.push_back(std::move(f));
  vars.push_cycle_scope(t.params);
  return Outcome::nothing;
}

// The modal G functions that stand on their own, the circle data and the
// feed come back; zero offset, tool and offsets programmed in the cycle stay.
void Decoder::Impl::restore_after_cycle(const ModalState& caller) {
  modal.motion = caller.motion;
  modal.plane = caller.plane;
  modal.absolute = caller.absolute;
  modal.feed_mode = caller.feed_mode;
  modal.feed_mm_min = caller.feed_mm_min;
  modal.feed_mm_rev = caller.feed_mm_rev;
  modal.feed_time_s = caller.feed_time_s;
  modal.feed_pct = caller.feed_pct;
  modal.r = caller.r;
  modal.circle_center_absolute = caller.circle_center_absolute;
  modal.exact_stop = caller.exact_stop;
  modal.contour = caller.contour;
  modal.contour_dev_mm = caller.contour_dev_mm;
}

void Decoder::Impl::note_modal_cycle(const Block& b) {
  if (!modal_cycle.active || frames.size() != modal_cycle.depth || b.program_end || return_pending) return;
  // G130/G132 axis words are weightings, not a position.
  const bool weighting = b.g_nonmodal.has(GCode::g130) || b.g_nonmodal.has(GCode::g132);
  if (modal_cycle.every_block || (b.has_axis_words() && !weighting)) modal_cycle_due = true;
}

bool Decoder::Impl::disable_modal_cycle(Cursor c) {
  if (!c.match('#')) return false;
  c.skip_spaces();
  if (!c.match_keyword("DISABLE")) return false;
  c.skip_spaces();
  if (!c.match_keyword("MODAL")) return false;
  c.skip_spaces();
  if (!c.match_keyword("CYCLE")) return false;
  if (!c.rest_empty()) return false;
  modal_cycle = {};
  return true;
}

}  // namespace nck::nc
