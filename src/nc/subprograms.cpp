// Program sections and calls: the main program (%name, or the whole file),
// local subroutines (%L name, called with LL name) and global subroutine
// files (L file.nc, relative to the calling file's folder); M17/M29 and the
// next % header return, nesting is bounded.
#include <algorithm>

#include <fmt/format.h>

#include "decoder_impl.hpp"
#include "nck/core/path_within.hpp"

namespace nck::nc {

using namespace detail;

// Opens `p` for a frame: from the cache when enabled, else streamed from
// disk with a separate pass for the section index.
namespace {

// p, symbolic links resolved, lies inside one of the folders (or none is given).
bool inside_roots(const std::filesystem::path& p, const std::vector<std::filesystem::path>& roots) {
  if (roots.empty()) return true;
  std::error_code ec;
  const std::filesystem::path real = std::filesystem::weakly_canonical(p, ec);
  if (ec) return false;
  for (const std::filesystem::path& root : roots) {
    const std::filesystem::path r = std::filesystem::weakly_canonical(root, ec);
    if (!ec && path_within(r, real)) return true;
  }
  return false;
}

// The sections of a file that has no main program, for 920053.
std::string no_main_program(const ProgramIndex& idx) {
  std::string names;
  for (const Section& s : idx.sections) names += fmt::format("{}%L {} (line {})", names.empty() ? "" : ", ", s.name, s.header.line);
  return fmt::format("the file holds only local subroutines, {}, and no main program; add it after them, headed "
                     "%name, or write its blocks without a header",
                     names);
}

// "%MAIN", "%L SUB" or "%" as the header line names it.
std::string header_label(std::string_view text) {
  bool local = false;
  std::string name;
  parse_header(text, local, name);
  return fmt::format("%{}{}", local ? "L " : "", name);
}

}  // namespace

bool Decoder::Impl::open_frame(const std::filesystem::path& p, bool cached, Frame& f, bool main) {
  Decoder::Impl& d = *this;
  refused_file = !inside_roots(p, cfg.allowed_roots);
  if (refused_file) return false;
  f.path = p;
  f.reader = std::make_unique<SourceReader>();
  f.reader->set_meter(&meter, main);
  if (cached && d.cache.enabled()) {
    if (auto e = d.cache.get(p, d.cfg.max_block_chars)) {
      f.mem = e->text;
      f.index = e->index;
      f.reader->open_memory(f.mem);
      return true;
    }
  }
  SourceReader scan;
  if (!main) scan.set_meter(&meter, false);  // a subroutine's index, read again on every call
  if (!scan.open_file(p) || !f.reader->open_file(p)) return false;
  f.index = std::make_shared<const ProgramIndex>(scan_sections(scan, d.cfg.max_block_chars));
  return true;
}

bool Decoder::Impl::open_local_frame(const std::filesystem::path& path, std::shared_ptr<const std::string> mem,
                                    std::shared_ptr<const ProgramIndex> index, SourcePos body, Frame& f) {
  f.path = path;
  f.index = std::move(index);
  f.mem = std::move(mem);
  f.reader = std::make_unique<SourceReader>();
  f.reader->set_meter(&meter, false);
  if (f.mem) f.reader->open_memory(f.mem);
  else if (!f.reader->open_file(f.path)) return false;
  f.reader->seek(body);
  return true;
}

// A local call in a loop would otherwise open and read the caller's file again
// on every pass. Files above the cap stay streamed (reopened per call), so a
// huge main program never has to fit in memory.
void Decoder::Impl::keep_text_for_local_calls(Frame& f) {
  constexpr std::uintmax_t kMaxInMemoryBytes = 64u << 20;
  if (f.mem) return;
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(f.path, ec);
  if (ec || size > kMaxInMemoryBytes) return;
  f.mem = read_text(f.path, size);  // stays streamed when unreadable
}

bool Decoder::Impl::open_main(const std::filesystem::path& p) {
  Frame f;
  f.file_id = file_id(p.string());
  if (!open_frame(p, false, f, true)) {
    diags.push_back(make_diagnostic(open_error(ErrorId::NcFileUnreadable), SourceLoc{p.string(), 0, 0},
                                    fmt::format("cannot read the NC program '{}'", p.string())));
    fatal = true;
    return false;
  }
  const std::optional<SourcePos> start = f.index->program_start();
  if (!start) {
    diags.push_back(make_diagnostic(ErrorId::NcNoMainProgram, SourceLoc{p.string(), f.index->sections[0].header.line, 1},
                                    no_main_program(*f.index)));
    fatal = true;
    return false;
  }
  f.reader->seek(*start);
  f.start = f.reader->next_pos();
  frames.push_back(std::move(f));
  return true;
}

void Decoder::Impl::open_mdi(std::string text) {
  Frame f;
  f.path = kMdiFileName;
  f.file_id = file_id(kMdiFileName);
  f.mem = std::make_shared<const std::string>(std::move(text));
  SourceReader scan;
  scan.open_memory(f.mem);
  f.index = std::make_shared<const ProgramIndex>(scan_sections(scan, cfg.max_block_chars));
  f.reader = std::make_unique<SourceReader>();
  f.reader->set_meter(&meter, true);  // like a main program: its first pass is free
  f.reader->open_memory(f.mem);
  f.start = f.reader->next_pos();
  frames.clear();
  frames.push_back(std::move(f));
  mdi = true;
  ended = fatal = end_pending = return_pending = goto_pending = modal_cycle_due = false;
  comment_mode = var_mode = false;
  err.clear();
}

Outcome Decoder::Impl::call(Cursor& c, bool local) {
  std::size_t at = c.pos;
  c.pos += local ? 2 : 1;
  c.skip_spaces();
  if (c.peek_keyword("CYCLE")) return cycle_call(c, local, at);
  std::string name;
  if (local) {
    // The name runs to a comment or the end of the block (names may hold blanks).
    std::size_t b = c.pos;
    std::size_t e = b;
    while (e < c.s.size() && c.s[e] != '(' && c.s[e] != ';') ++e;
    std::string_view n = c.s.substr(b, e - b);
    while (!n.empty() && (n.back() == ' ' || n.back() == '\t')) n.remove_suffix(1);
    name = to_upper(n);
    c.pos = e;
  } else {
    std::size_t b = c.pos;
    while (!c.at_end() && c.peek() != ' ' && c.peek() != '\t' && c.peek() != ';' && c.peek() != '(') ++c.pos;
    name = std::string(c.s.substr(b, c.pos - b));
  }
  if (name.empty()) return report(ErrorId::NcCallSyntax, at, local ? "LL needs a subroutine name" : "L needs a file name");
  if (!c.rest_empty())
    return report(ErrorId::NcCallSyntax, c.pos, "a subroutine call must be alone in its block");
  if (frames.size() > cfg.max_subroutine_depth)
    return report(ErrorId::NcSubroutineDepth, at,
                  fmt::format("more than {} nested subroutine calls", cfg.max_subroutine_depth), true);
  Frame& caller = frames.back();
  Frame f;
  if (local) {
    const Section* s = caller.index->local(name);
    if (!s)
      return report(ErrorId::NcSubroutineNotFound, at,
                    fmt::format("no local subroutine '%L {}' in this file", name));
    keep_text_for_local_calls(caller);
    f.file_id = caller.file_id;
    if (!open_local_frame(caller.path, caller.mem, caller.index, s->body, f))
      return report(ErrorId::NcFileUnreadable, at, fmt::format("cannot reopen '{}'", caller.path.string()));
  } else {
    std::filesystem::path p(name);
    if (p.is_relative()) p = caller.path.parent_path() / p;
    if (!open_frame(p, true, f))
      return report(open_error(ErrorId::NcSubroutineNotFound), at,
                    fmt::format("subroutine file '{}' not found (looked for {})", name, p.string()));
    f.file_id = file_id(p.string());
    if (enter_program(f, at) == Outcome::error) return Outcome::error;
  }
  f.start = f.reader->next_pos();
  frames.push_back(std::move(f));
  vars.push_scope();
  return Outcome::nothing;
}

Outcome Decoder::Impl::enter_program(Frame& f, std::size_t at) {
  const std::optional<SourcePos> start = f.index->program_start();
  if (!start) return report(ErrorId::NcNoMainProgram, at, fmt::format("{}: {}", f.path.string(), no_main_program(*f.index)));
  f.reader->seek(*start);
  return Outcome::nothing;
}

// M17/M29 (or the end of the subroutine's section): back to the caller.
// An open structure at the end of a section cannot be recovered from: the
// error is fatal, also in lint mode (which would meet it again and again).
Outcome Decoder::Impl::do_return() {
  if (!frames.back().ctl.empty())
    return report(ErrorId::NcUnclosedControl, 0, unclosed_message("subroutine"), true);
  if (frames.back().cycle_modal) restore_after_cycle(*frames.back().cycle_modal);
  frames.pop_back();
  vars.pop_scope();
  if (modal_cycle.active && frames.size() < modal_cycle.depth) modal_cycle = {};  // its level ended
  return Outcome::nothing;
}

std::string Decoder::Impl::unclosed_message(std::string_view section) const {
  return fmt::format("the $ structure opened at line {} is not closed before the end of the {}",
                     frames.back().ctl.back().start.line, section);
}

// TF5200 20193: once the main program has started, % lines may not follow
// before its end; the file's structure is wrong, so decoding stops (lint
// would otherwise read the next section's blocks as the main program's).
Outcome Decoder::Impl::header_in_main_program(std::size_t pos) {
  const Frame& f = frames.back();
  const std::string header = header_label(std::string_view(f.reader->text()).substr(pos));
  std::string started;
  if (mdi) started = "the MDI blocks";
  else if (f.index->first_code)
    started = fmt::format("the unnamed main program that line {} started (its first block outside comments; only "
                          "comments may stand before the first %)",
                          f.index->first_code->line);
  else if (const Section* m = f.index->main())
    started = fmt::format("the main program %{} of line {} before its M30/M2", m->name, m->header.line);
  return report(ErrorId::NcPercentInMainProgram, pos,
                fmt::format("{} inside {}: local subroutines (%L) go before the main program, and a % may follow "
                            "only after its M30",
                            header, started),
                true);
}

// A % header or the end of the file ends the running program or subroutine.
Outcome Decoder::Impl::end_of_section() {
  if (frames.size() > 1) return do_return();
  if (!frames.back().ctl.empty())
    return report(ErrorId::NcUnclosedControl, 0, unclosed_message("program"), true);
  if (var_mode) return report(ErrorId::NcVarDeclaration, 0, "#VAR is never closed with #ENDVAR", true);
  if (!mdi) err.warn(ErrorId::NcMissingProgramEnd, 0, "the main program ends without M30/M2");
  return Outcome::end;
}

}  // namespace nck::nc
