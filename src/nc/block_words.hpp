#pragma once
// The staged decoding of one NC block (grblHAL-like, each stage its own file):
//   parse_words  (block_words.cpp, spindle_syntax.cpp, hash_commands.cpp)
//       reads every word and evaluates its value into Words;
//   check_words  (block_check.cpp) validates the combination against the
//       modal state, without changing anything;
//   apply_words  (modal_apply.cpp) updates the modal state and variables and
//       fills the output Block.
// Nothing takes effect before the whole block has passed the check.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "expression.hpp"
#include "nck/core/fixed_vector.hpp"
#include "nck/nc/block.hpp"
#include "nck/nc/decoder.hpp"

namespace nck::nc::detail {

struct GWord {
  GCode code = GCode::g0;
  std::uint32_t pos = 0;
  double value = 0;  // G159=<value>, G131=/G133=/G134=/G233=<percent>
};
// M3/M4/M5/M19 and the gear stages M40..M45: the main spindle's DIN functions.
constexpr bool spindle_m_function(int code) noexcept {
  return code == 3 || code == 4 || code == 5 || code == 19 || (code >= 40 && code <= 45);
}

struct MWord {
  int code = 0;
  std::uint32_t pos = 0;
  std::optional<std::int32_t> value;  // M52=-345: the additional value for the PLC
};
template <class T>
struct At {  // a value and where it was written
  std::optional<T> v;
  std::uint32_t pos = 0;
  void set(T x, std::size_t p) { v = x; pos = static_cast<std::uint32_t>(p); }
};
struct Assignment {
  Lvalue target;
  double value = 0;
  bool is_string = false;
  std::string str;
};

struct Words {
  At<std::int64_t> n;
  FixedVector<GWord, 24> g;
  FixedVector<MWord, 24> m;
  FixedVector<MWord, 24> h;
  std::array<std::optional<double>, kMaxAxes> axes{};
  std::array<std::uint32_t, kMaxAxes> axis_pos{};
  int axis_count = 0;
  std::uint32_t axis_mask = 0;  // bit j: axes[j] is set (clear() resets only those)
  static_assert(kMaxAxes <= 32, "axis_mask has a bit per axis");
  At<double> f, s, t, d, r;
  std::array<At<double>, 3> ijk{};
  At<double> dwell_direct;       // G4 <value>
  At<double> time_s;             // #TIME <value>
  At<double> contour_dev;        // #CONTOUR MODE [DEV PATH_DEV=<value>]
  At<SlopeProfile> slope;        // #SLOPE [TYPE=..], #SLOPE DEFAULT, #SET SLOPE PROFIL[n]
  bool slope_default = false;    // #SLOPE DEFAULT
  // DIN attributes of the main spindle.
  At<double> s_pos, s_pos_shift, s_offset;
  std::uint32_t din_spindle_pos = 0;
  std::vector<SpindleCommand> brackets;  // spindle syntax S..[ ]
  std::optional<HashCommand> hash;
  std::uint32_t hash_pos = 0;
  std::vector<Assignment> assigns;
  int word_count = 0;  // words other than N and the # command itself
  // P-CHAN-00116/00148 (axis_dimensions.cpp): the dimensions the axis words
  // got from the G90/G91 before them in the block (bits kDim*, with the
  // first word of each), the axes programmed more than once and their sums.
  std::uint8_t axis_dims = 0;
  std::array<std::uint32_t, 3> axis_dim_pos{};
  std::uint32_t axis_repeat_mask = 0;
  std::array<double, kMaxAxes> axis_sum{};

  void clear();
  // Axis word j with value v at column pos (one word of the block).
  void set_axis(std::size_t j, double v, std::size_t pos) {
    axes[j] = v;
    axis_sum[j] = v;
    axis_pos[j] = static_cast<std::uint32_t>(pos);
    axis_mask |= 1u << j;
    ++axis_count;
    ++word_count;
  }
  bool has_g(GCode code) const {
    for (const auto& x : g)
      if (x.code == code) return true;
    return false;
  }
  bool has_any_g(GCodeSet codes) const {
    for (const auto& x : g)
      if (codes.has(x.code)) return true;
    return false;
  }
  const MWord* find_m(int code) const {
    for (const auto& x : m)
      if (x.code == code) return &x;
    return nullptr;
  }
};

// Non-modal G functions whose S word is their value (dwell revolutions,
// homing, gear stage, limits, ...), not a spindle speed.
inline constexpr GCodeSet kGCodesTakingS{GCode::g4,   GCode::g74,  GCode::g112, GCode::g130,
                                         GCode::g135, GCode::g136, GCode::g137, GCode::g196};

// Decoder state the stages read (and apply writes).
struct BlockCtx {
  const DecoderConfig& cfg;
  ExprCtx& x;
  std::string& main_target;       // configured name of the current main spindle
  std::vector<std::string> axis_upper;  // axis names, upper case (the C axis's as #CAX names it)
  std::vector<std::string> alias_upper;  // P-CHAN-00253 alias names per axis ("" none)
  // #DIST CTRL state kept by the decoder (mode changes 310025, SET_POS 310024).
  int dist_state = 0;             // 0 off, 1 on surface, 2 on const, 3 freeze
  bool dist_set_pos_known = false;
  Plane plane = Plane::g17;       // the working plane before the block (cycle @X/@Y/@Z)
};

// G4 <axis><s>: TF5200's "first main axis" is the channel's first axis
// (gruppe[0].achse[0]) in every plane, X on a lathe in G18 (docs/decisions.md, "NC decoder").
inline constexpr int kDwellAxis = 0;

int find_axis(const BlockCtx& b, std::string_view name_upper);
// The axis with alias name A1..A32 (P-CHAN-00253), -1 when none or off.
int find_alias(const BlockCtx& b, std::string_view name_upper);

bool parse_words(Cursor& c, BlockCtx& b, Words& w);
// axis_dimensions.cpp. Axis word `j` (named `name` as written) with value
// v at column pos, for every form of axis word (X.., X2=.., A1=.., @X..): a
// second word for the same axis is 20203 unless P-CHAN-00148 allows it.
bool add_axis_word(BlockCtx& b, Words& w, int j, double v, std::size_t pos, std::string_view name);
// Under P-CHAN-00116 every axis word must get the dimension the block ends
// with (nck's Block has one per block); `before` is the modal state before.
bool check_dimensions(const Words& w, BlockCtx& b, const ModalState& before);
// A repeated axis's value: the last under G90, the sum under G91.
void resolve_repeated_axes(Words& w, bool absolute);
// A cycle's @ word (cycle_words.cpp): @P<n>=.., @X/@Y/@Z, @I/@J/@K, @S.
bool parse_cycle_word(Cursor& c, BlockCtx& b, Words& w);
// Spindle words: at 'S' (DIN or S..[ ]).
bool parse_spindle_word(Cursor& c, BlockCtx& b, Words& w);
// '#' commands; `exclusive` tells whether the rest of the block must be empty.
bool parse_hash(Cursor& c, BlockCtx& b, Words& w, bool& exclusive);
bool check_words(const Words& w, BlockCtx& b, const ModalState& modal);
// weighting_check.cpp: G130...G134, G233 (called by check_words).
bool check_weightings(const Words& w, BlockCtx& b);
// Applies to modal/variables and fills out. Returns false only on a write
// error (e.g. an undeclared variable).
bool apply_words(Words& w, BlockCtx& b, ModalState& modal, Block& out);
// Under G70 (inch_to_mm.cpp): the words' lengths, then the kernel writes, to mm.
void words_to_mm(Words& w, const ModalState& modal);
void kernel_writes_to_mm(std::vector<VariableWrite>& writes);

// G code groups (block_check.cpp).
enum class GGroup : std::uint8_t { motion, plane, dim, feed, speed, comp, diam, unit, zero,
                                   center, manual, exact_stop, contour, trc_corner, nonmodal };
std::optional<GGroup> g_group(GCode code);
// The import stage's only integer-to-G step: nullopt for a number nck does not know.
std::optional<GCode> to_gcode(int number);

}  // namespace nck::nc::detail
