#pragma once
// Streaming NC decoder: hands out executable blocks one at a time as the
// channel consumes them, reading the program incrementally (bounded memory
// for programs of millions of blocks). Setup-time code: allocates, never
// throws on bad input, never crashes, never hangs.
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string_view>
#include <string>
#include <vector>

#include "nck/core/diagnostic.hpp"
#include "nck/nc/block.hpp"

namespace nck::nc {

struct DecoderConfig {
  std::vector<std::string> axis_names;     // channel path axes, index = Block::axes index
  // P-CHAN-00253 on: per axis its alias A1..A32 (P-AXIS-00297), "" none;
  // empty when alias names are off. Programmed as A2=.. beside the names.
  std::vector<std::string> axis_aliases;
  // The main spindle's slot among the axes when it may become the C axis
  // (-1: none): addressed by the name #CAX gives it, else P-CHAN-00010's.
  int c_axis = -1;
  std::string c_axis_default_name;         // P-CHAN-00010, "" = none
  std::vector<std::string> spindle_names;  // channel spindles ("S1", "S2"...)
  std::string main_spindle_name = "S";     // the name DIN words address
  std::string main_spindle = "S1";         // which configured spindle is the main one
  SlopeProfile slope_default = SlopeProfile::step;  // P-CHAN-00071: at program start and #SLOPE DEFAULT
  std::uint32_t skip_mask = 0;             // active block-skip levels (/1 = bit 0 ... /10 = bit 9; "/" = bit 0)
  // P-CHAN-00015 = 1 (single step after every block): a block without
  // functions (only assignments, or only its N) is handed out too, so it
  // gets its block event and single step holds after it.
  bool every_block = false;
  bool use_cached_files = false;           // FCT_USE_CACHED_FILES
  std::uint32_t max_cache_number = 0;
  std::uint32_t max_cache_size_kb = 0;
  std::uint32_t max_subroutine_depth = 20;
  // One budget for all loop iterations of a run (nested loops share it):
  // guards against endless $WHILE / $FOR / $DO.
  std::uint64_t max_loop_iterations = 10'000'000;
  // One budget for the reading of a run: every block read except the first
  // pass through the main program (loop bodies read again, skipped
  // branches, $GOTO searches, subroutine and cycle bodies). A loop budget
  // alone does not bound the work: one iteration may skip 5,000 lines.
  std::uint64_t max_lines_read = 100'000'000;
  // Set by the caller (another thread or a signal handler) to stop decoding:
  // polled at every block read; next() then returns Status::stopped. Not owned.
  const std::atomic<bool>* stop = nullptr;
  // Declared program variables (#VAR, every scope together): bounded memory.
  std::size_t max_variable_elements = 1'000'000;
  // ... and their declared bytes: 8 per number, a STRING[n] element n (at
  // most 4,000) or the longer text assigned to it.
  std::size_t max_variable_bytes = 64u << 20;

  // Added by the decoder work:
  std::vector<int> spindle_log_axis_numbers;  // same order as spindle_names (#MAIN SPINDLE [nr])
  int max_zero_offset_index = 96;             // highest G159 index (zero-offset groups 0..96)
  bool dist_ctrl_available = true;            // FCT_3D_DIST_CTRL (else #DIST CTRL -> 310015)
  bool continue_after_error = false;          // lint mode: skip a bad block and go on
  // P-CHAN-00116: G90/G91 in one block act on the positions after them
  // (axis_dimensions.cpp); P-CHAN-00148 (only with 00116): an axis may be
  // programmed several times in one block, else TF5200 20203.
  bool multi_dimension_in_block = false;
  bool multi_axes_in_block = false;
  std::size_t max_block_chars = 4000;         // docs/nc-language.md (TF5200's limit)
  // Cycle search path after the program's folder: the machine's
  // cycle_path[i] folders (startup.lis), then --cycles DIR.
  std::vector<std::filesystem::path> cycle_dirs;
  // nck serve: every file the decoder opens (program, L subroutine, cycle)
  // must lie inside one of these folders, symbolic links resolved; empty:
  // any file. A file outside is refused with NcFileNotAllowed.
  std::vector<std::filesystem::path> allowed_roots;
};


// Kernel variables that describe the channel's state at the block being
// decoded (tool, rotation, zero offset, positions): the decoder asks for
// them each time a block reads one, so they are never a stale copy. The
// channel's preparation implements it from its planner.
class KernelStateReader {
 public:
  virtual ~KernelStateReader() = default;
  // `key` is normalised ("V.G.WZ_AKT.L", "V.A.ABS.X"); nullopt = not a
  // state variable, the decoder's own store answers.
  virtual std::optional<double> read(std::string_view key) const = 0;
};

inline constexpr const char* kMdiFileName = "MDI";

// The ISG functions the decoder refuses by name (920052) rather than as
// unknown: G functions ("G5", "G80 … G89") and # functions ("#RT CYCLE",
// "#MC_…"); docs/nc-language.md lists each.
std::vector<std::string> refused_isg_functions();

class Decoder {
 public:
  // stopped: DecoderConfig::stop was set; decoding ends here, without a
  // diagnostic (the caller asked for it).
  enum class Status { block, end, error, stopped };
  struct Result {
    Status status = Status::end;
    Block block;                 // valid when status == block
  };

  // Opens the main program. Errors (missing file...) are reported through
  // diagnostics() and the first next() returns Status::error.
  Decoder(const std::filesystem::path& program, DecoderConfig cfg);
  // A decoder without a program, for MDI only (run_mdi); next() is Status::end until then.
  explicit Decoder(DecoderConfig cfg);
  ~Decoder();
  Decoder(Decoder&&) noexcept;
  Decoder& operator=(Decoder&&) noexcept;

  // The next executable block, the end of the program (M30/M2 block is
  // returned as a block with program_end set, then Status::end), an error,
  // or Status::stopped (DecoderConfig::stop).
  Result next();

  // All diagnostics so far (warnings and the error that stopped decoding).
  const std::vector<Diagnostic>& diagnostics() const;
  // Whether next() may still hand out blocks: false once the program ended
  // or an error stopped decoding for good. With continue_after_error a bad
  // block returns Status::error and this stays true (an error met again is
  // not reported again, so a caller cannot tell by the diagnostics).
  bool can_continue() const;
  const std::string& file_name(std::uint16_t file_id) const;
  // Every file the decoder opened so far (ids 0 .. file_count() - 1; 0 is the main program).
  std::size_t file_count() const;
  // The id of a file named in a diagnostic (SourceLoc::file), if decoded.
  std::optional<std::uint16_t> file_id(std::string_view name) const;
  const DecoderConfig& config() const;

  // Kernel variables (V.G. / V.A.) and program variables by name, e.g.
  // "V.G.NP[1].V.X", "V.A.MESS.X", "V.G.AKT_PLATZ", "P1", "V.P.X".
  // The kernel uses these to bridge measured values and offsets into the
  // decoder. get: nullopt when unknown or not set; set: false when the name
  // is not a known kernel variable (or declared program variable).
  std::optional<double> get_variable(std::string_view name) const;
  bool set_variable(std::string_view name, double value);
  // The active block-skip levels (the HLI's program_block_ignore,
  // docs/plc-scenario.md): they act on the blocks decoded from now on.
  void set_skip_mask(std::uint32_t mask) noexcept;
  // MDI: decoding goes on with `text`, blocks the operator typed, with the
  // modal state, variables and offsets where decoding stopped (after the
  // program end, an error, or the last MDI text). Its end is Status::end;
  // an error ends it (the next MDI text starts afresh). Its blocks come
  // from the file named kMdiFileName.
  void run_mdi(std::string text);
  // Kernel state variables come from `reader` (not owned; nullptr: none,
  // as in `nck parse`, where they read 0).
  void set_kernel_state_reader(const KernelStateReader* reader);

  struct Impl;  // opaque (src/nc/decoder_impl.hpp)

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace nck::nc
