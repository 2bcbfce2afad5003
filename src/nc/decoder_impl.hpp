#pragma once
// Internal state of nck::nc::Decoder, shared by decoder.cpp (block loop),
// control_flow.cpp ($ statements), subprograms.cpp (calls, returns,
// sections) and var_declarations.cpp (#VAR).
#include <map>
#include <memory>
#include <set>
#include <tuple>
#include <unordered_map>
#include <optional>
#include <string>
#include <vector>

#include "nck/core/append_log.hpp"
#include "block_words.hpp"
#include "file_cache.hpp"
#include "nck/nc/decoder.hpp"
#include "source_reader.hpp"

namespace nck::nc {

namespace detail {

enum class CtlKind : std::uint8_t { if_, while_, for_, do_, switch_ };

struct Ctl {
  CtlKind kind = CtlKind::if_;
  SourcePos start;           // the opening statement's block
  SourcePos body;            // the block after it ($DO, $REPEAT)
  bool until = false;        // a $DO opened by $REPEAT: closed by $UNTIL, which ends the loop when true
  Lvalue var;                // $FOR variable
  double end = 0, step = 1;  // $FOR limits
};

struct Frame {
  std::uint16_t file_id = 0;
  std::filesystem::path path;
  std::unique_ptr<SourceReader> reader;
  std::shared_ptr<const std::string> mem;  // cached file text, if any
  std::shared_ptr<const ProgramIndex> index;
  std::vector<Ctl> ctl;
  SourcePos start;  // the program's or subroutine's first block ($GOTO searches from here)
  std::map<std::string, SourcePos> labels;  // $GOTO labels found so far ("N20", "[NAME]"), capped
  // A cycle's frame: the caller's modal state, restored at the cycle's end.
  std::optional<ModalState> cycle_modal;
};

// What a cycle call starts: a global file or a local section, and its @P
// values. A modal call keeps it to start it again after motion blocks.
struct CycleTarget {
  std::string name;                        // as written after NAME=
  bool local = false;                      // LL CYCLE: a %L section of the calling file
  std::filesystem::path path;              // the file found (global) or the calling file (local)
  std::uint16_t file_id = 0;
  std::shared_ptr<const std::string> mem;  // cached text of a local cycle's file
  std::shared_ptr<const ProgramIndex> index;
  SourcePos body;                          // a local cycle's first block
  std::unordered_map<std::int64_t, double> params;
};

struct ModalCycle {
  bool active = false;
  bool every_block = false;  // MODAL_BLOCK: after every block, else after motion blocks (MODAL_MOVE)
  std::size_t depth = 0;     // frames.size() of the level that called it
  CycleTarget target;
};

// What processing one block led to.
enum class Outcome : std::uint8_t { nothing, block, error, end };

// Where "$GOTO" stands in a block from `from` on (not in comments or
// strings); npos when nowhere.
std::size_t find_goto(std::string_view text, std::size_t from);

}  // namespace detail

struct Decoder::Impl {
  explicit Impl(DecoderConfig c);

  DecoderConfig cfg;
  AppendLog<std::string> files;  // read by other threads while decoding (event file names)
  std::vector<Diagnostic> diags;
  detail::Variables vars;
  detail::ErrorSlot err;
  detail::ExprCtx x;
  std::string main_target;
  detail::BlockCtx bctx;
  ModalState modal;
  std::vector<detail::Frame> frames;
  detail::FileCache cache;
  detail::WorkMeter meter;  // every block read: the reading budget and the stop request
  detail::Words words;

  bool fatal = false;        // decoding cannot go on
  bool refused_file = false; // the last open_frame failed: outside cfg.allowed_roots
  bool ended = false;        // Status::end reached
  bool mdi = false;          // decoding MDI text: its end is no missing M30
  std::uint64_t rows_read = 0;  // NC rows read so far (Block::row)
  bool end_pending = false;  // M30 block handed out, end comes next
  bool return_pending = false;  // M17 block handed out, return comes next
  // #SLOPE DEFAULT makes no block of its own: the next block handed out
  // carries it (Block::slope_default), so the weightings restore in order.
  bool slope_default_pending = false;
  bool comment_mode = false;    // inside #COMMENT BEGIN .. END
  bool var_mode = false;        // inside #VAR .. #ENDVAR
  detail::SourcePos comment_start;
  bool loop_reentry = false;    // seeking back to a $WHILE/$FOR statement
  std::uint64_t loop_iterations = 0;  // of all loops of the run: one budget (max_loop_iterations)
  std::set<std::tuple<std::uint32_t, std::string, std::uint32_t>> reported;  // lint: id, file, line once
  std::uint64_t reentry_offset = 0;
  detail::ModalCycle modal_cycle;  // MODAL_MOVE / MODAL_BLOCK call in effect
  bool modal_cycle_due = false;    // start it before the next block
  // "G90 $GOTO [END]": the jump after the block has been handed out.
  bool goto_pending = false;
  std::string goto_label;
  std::size_t goto_pos = 0;
  std::string goto_text;           // the block without its $GOTO

  Result next();
  Result next_block();  // next() without the meter's verdict
  Result halted();      // the result once the meter has halted

  // decoder.cpp
  detail::Outcome process_block(Block& out);
  detail::Outcome run_words(detail::Cursor& c, std::optional<std::int64_t> n, Block& out);
  Result error_result();
  detail::Outcome report(ErrorId, std::size_t pos, std::string msg, bool is_fatal = false);
  void flush_warnings();
  SourceLoc loc(std::size_t pos) const;
  std::string call_chain() const;
  std::optional<std::uint16_t> find_file(std::string_view name) const;
  std::uint16_t file_id(const std::string& name);  // found or added

  // control_flow.cpp
  detail::Outcome control(detail::Cursor& c);
  // At M30/M2: are the open structures closed further down the file?
  bool open_structures_closed_later();
  // goto_jump.cpp: $GOTO N<expr> / $GOTO [NAME]; `c` after the keyword
  detail::Outcome go_to(detail::Cursor& c, std::size_t pos);
  detail::Outcome jump(const std::string& label, std::size_t pos);
  // A block with commands beside its $GOTO (at `at`): the commands, then the jump.
  detail::Outcome words_with_goto(detail::Cursor& c, std::optional<std::int64_t> n, Block& out, std::size_t at);
  // subprograms.cpp
  // `main`: the main program, whose first pass is free of the reading budget.
  bool open_frame(const std::filesystem::path& p, bool cached, detail::Frame& f, bool main = false);
  // The ID for a file open_frame could not open: refused, or `otherwise`.
  ErrorId open_error(ErrorId otherwise) const { return refused_file ? ErrorId::NcFileNotAllowed : otherwise; }
  // A frame reading a section of an open file again (a local subroutine or
  // cycle: path, cached text, index of the caller's file) from `body`; false
  // when the file cannot be read again.
  bool open_local_frame(const std::filesystem::path& path, std::shared_ptr<const std::string> mem,
                        std::shared_ptr<const detail::ProgramIndex> index, detail::SourcePos body, detail::Frame& f);
  bool open_main(const std::filesystem::path& p);
  // MDI: the operator's text becomes the main level; the state goes on.
  void open_mdi(std::string text);
  // Loads a streamed frame's file into `f.mem` once, so that its local
  // subroutines and cycles are read from memory on every call.
  void keep_text_for_local_calls(detail::Frame& f);
  detail::Outcome call(detail::Cursor& c, bool local);
  // A called file's frame: to where its program starts (error 920053 when
  // the file holds only local subroutines).
  detail::Outcome enter_program(detail::Frame& f, std::size_t at);
  detail::Outcome end_of_section();
  // A % line at the main program's level, before M30/M2: TF5200 20193.
  detail::Outcome header_in_main_program(std::size_t pos);
  detail::Outcome do_return();
  std::string unclosed_message(std::string_view section) const;
  // cycle_call.cpp: `c` at CYCLE after L / LL
  detail::Outcome cycle_call(detail::Cursor& c, bool local, std::size_t at);
  detail::Outcome start_cycle(const detail::CycleTarget& t, std::size_t at);
  void restore_after_cycle(const ModalState& caller);
  // After handing out `b`: is the modal cycle due?
  void note_modal_cycle(const Block& b);
  bool disable_modal_cycle(detail::Cursor c);  // "#DISABLE MODAL CYCLE" block?
  // var_declarations.cpp
  detail::Outcome declare(detail::Cursor& c);
};

}  // namespace nck::nc
