#pragma once
// Internal state of nck::nc::Decoder, shared by decoder.cpp (block loop),
// control_flow.cpp ($ statements), subprograms.cpp (calls, returns,
// sections) and var_declarations.cpp (#VAR).
#include <map>
#include <memory>
#include <set>
#include <tuple>
#include <string>
#include <vector>

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
  SourcePos body;            // the block after it ($DO)
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
};

// What processing one block led to.
enum class Outcome : std::uint8_t { nothing, block, error, end };

}  // namespace detail

struct Decoder::Impl {
  explicit Impl(DecoderConfig c);

  DecoderConfig cfg;
  std::vector<std::string> files;
  std::vector<Diagnostic> diags;
  detail::Variables vars;
  detail::ErrorSlot err;
  detail::ExprCtx x;
  std::string main_target;
  detail::BlockCtx bctx;
  ModalState modal;
  std::vector<detail::Frame> frames;
  detail::FileCache cache;
  detail::Words words;

  bool fatal = false;        // decoding cannot go on
  bool ended = false;        // Status::end reached
  bool end_pending = false;  // M30 block handed out, end comes next
  bool return_pending = false;  // M17 block handed out, return comes next
  bool comment_mode = false;    // inside #COMMENT BEGIN .. END
  bool var_mode = false;        // inside #VAR .. #ENDVAR
  detail::SourcePos comment_start;
  bool loop_reentry = false;    // seeking back to a $WHILE/$FOR statement
  std::uint64_t loop_iterations = 0;  // of all loops of the run: one budget (max_loop_iterations)
  std::set<std::tuple<std::uint32_t, std::string, std::uint32_t>> reported;  // lint: id, file, line once
  std::uint64_t reentry_offset = 0;

  Result next();

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
  // subprograms.cpp
  bool open_main(const std::filesystem::path& p);
  detail::Outcome call(detail::Cursor& c, bool local);
  detail::Outcome end_of_section();
  detail::Outcome do_return();
  std::string unclosed_message(std::string_view section) const;
  // var_declarations.cpp
  detail::Outcome declare(detail::Cursor& c);
};

}  // namespace nck::nc
