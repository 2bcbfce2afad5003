#pragma once
// A decoded NC block: every word evaluated (expressions, parameters,
// variables), checked, and the modal state that is in force for it.
// Control flow ($IF, $WHILE, subroutine calls) is resolved by the decoder:
// the channel only ever sees executable blocks, in execution order.
//
// Fields may be added; existing names are an interface the kernel uses.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "nck/core/axes.hpp"
#include "nck/nc/gcode.hpp"
#include "nck/nc/hash_commands.hpp"
#include "nck/nc/modal.hpp"
#include "nck/nc/spindle_command.hpp"

namespace nck::nc {

// A write to a kernel variable (V.G. / V.A.) programmed in this block; the
// kernel applies them in order when the block executes.
struct VariableWrite {
  std::string name;  // normalised, e.g. "V.G.NP[1].V.X"
  double value = 0;
};

// The additional value of an M or H function (TF5200 "M/H functions with
// additional information"): the PLC gets it with the function.
struct FunctionValue {
  int number = 0;
  std::int32_t value = 0;
};
inline std::optional<std::int32_t> value_of(const std::vector<FunctionValue>& values, int number) {
  for (const FunctionValue& v : values)
    if (v.number == number) return v.value;
  return std::nullopt;
}

// Index into Block::group_weight_pct.
enum class GroupWeight : std::uint8_t { g131, g133, g134, g233 };
constexpr std::optional<GroupWeight> group_weight(GCode g) noexcept {
  switch (g) {
    case GCode::g131: return GroupWeight::g131;
    case GCode::g133: return GroupWeight::g133;
    case GCode::g134: return GroupWeight::g134;
    case GCode::g233: return GroupWeight::g233;
    default: return std::nullopt;
  }
}

struct Block {
  // Where it came from.
  std::uint16_t file_id = 0;    // Decoder::file_name(file_id)
  std::uint32_t line = 0;       // 1-based line of the block's first character
  // Block search (TF5200 types 1 and 3): the byte range of the block's text
  // in its file, and the block counter — NC rows read since program start,
  // comment and empty rows, loop passes and subroutine rows included.
  std::uint64_t offset = 0, offset_end = 0;
  std::uint64_t row = 0;
  std::optional<std::int64_t> n;  // N word

  // The modal state in force for this block (after applying its own words).
  ModalState modal;

  // Per-block words, in program units (mm or deg, absolute or incremental
  // as modal.absolute says; the channel resolves them).
  std::array<std::optional<double>, kMaxAxes> axes{};  // index = channel axis
  std::array<std::optional<double>, 3> ijk{};          // I, J, K
  std::optional<double> r;                             // circle radius (R)
  std::optional<double> f;                             // F as programmed (also kept in modal)
  // Non-modal / special G codes programmed here (GCodeSet::kCodes). With 74
  // 92 100 101 102 130 132 200 (and manual_g below) the axis words above
  // carry that function's values (order, offset, target, weighting in %,
  // factor or dummy), not a motion target.
  GCodeSet g_nonmodal;
  // M functions in program order, except the main spindle's DIN functions
  // (M3 M4 M5 M19 M40..M45, in spindles[]) and M17/M29 (handled here).
  std::vector<int> m;
  std::vector<int> h;            // H functions
  // Additional values (M52=-345, H10=P1) of the M and H functions above.
  std::vector<FunctionValue> m_values, h_values;
  std::optional<std::int64_t> t; // T word
  std::optional<std::int64_t> d; // D word
  std::optional<double> dwell_s; // G4 X.. / G4 .. / #TIME ..  (seconds)
  std::optional<double> dwell_revs;  // G4 S.. (main-spindle revolutions)
  double group_weight(GroupWeight w) const { return group_weight_pct[static_cast<std::size_t>(w)]; }

  // Spindle words: DIN words of the main spindle (M3 S1000, M19 S.POS=..) are
  // mapped onto the main spindle's entry, spindle syntax S1[..] gives one
  // entry per bracket.
  std::vector<SpindleCommand> spindles;

  // At most one # command per block (docs/nc-language.md), plus #PSET / #PRESET
  // which may share a block.
  std::optional<HashCommand> hash;

  // Kernel-variable assignments (V.G.NP[1].V.X = 10 ...), in program order.
  std::vector<VariableWrite> kernel_writes;
  std::uint8_t depth = 0;    // subroutine nesting level (0 = main program)

  // G201 / G202 programmed in this block (the manual-mode group is modal, so
  // modal.manual_mode alone cannot tell); its axis words select the axes.
  std::optional<GCode> manual_g;
  // G53..G59 / G159 programmed in this block: the offset is selected again
  // even when modal.zero_offset did not change (a CS's OFF may have put
  // another offset back in force meanwhile).
  bool zero_offset_programmed = false;
  // The percentages of G131=, G133=, G134=, G233= (each valid where
  // g_nonmodal has its G code); G130/G132 take theirs from the axis words.
  std::array<double, 4> group_weight_pct{};
  // #SLOPE DEFAULT programmed here: the weightings go back to 100 % too.
  bool slope_default = false;

  bool program_end = false;  // M2 / M30 reached (main program level)
  bool stop = false;           // M0
  bool optional_stop = false;  // M1: the kernel stops only while the HLI's optional-stop switch is on

  bool has_axis_words() const {
    for (const auto& a : axes)
      if (a) return true;
    return false;
  }
};

}  // namespace nck::nc
