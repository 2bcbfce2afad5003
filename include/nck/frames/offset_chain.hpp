#pragma once
// The offset chain of one channel: every kind of offset of FCT-C2 §2 kept
// separately, and the mapping between program (PCS) and machine (MCS)
// coordinates. A value type with fixed arrays and no heap, so the planner can
// copy it into the cyclic path.
//
// Order of the chain, PCS -> MCS (docs/coordinate-systems.md explains why):
//   1. #ROTATION   turns the programmed point in the working plane about
//                  CENTER1/CENTER2; it acts before every other offset.
//   2. PCS level   manual (handwheel) offset and tool offsets whose
//                  directions follow the machining CS (tool_fixed 0),
//                  incl. the #TLC delta; they are added in the innermost CS.
//   3. #ECS        effector frame (only ever alone: 20774 otherwise).
//   4. #CS stack   innermost (last activated) first: parent = V + R * child.
//   5. #ACS stack  the clamping correction, outside the CS (a tilted plane on
//                  a skewed workpiece = ACS then CS).
//   6. WCS level   zero offset (G54.., G159), G92, #PSET, measuring offset
//                  (G101) and clamp offset: translations along machine axes.
//                  The CS is defined relative to this WCS.
//   7. MCS level   tool offsets with tool_fixed 1 (machine directions).
// #MCS ON swaps the whole state for an empty one and restores it at OFF.
// Translation offsets (zero, G92, PSET, G101, tool, TLC) obey the G91 rule:
// a new value becomes effective on axis j only at commit_axis(j), which the
// caller does when axis j is next programmed absolutely.
#include <cstdint>
#include <expected>
#include <optional>
#include <string_view>

#include "nck/core/fixed_vector.hpp"
#include "nck/frames/cs_store.hpp"
#include "nck/frames/rotation.hpp"
#include "nck/frames/types.hpp"
#include "nck/frames/zero_offset_table.hpp"

namespace nck::frames {

struct ChainConfig {
  std::size_t axis_count = 3;               // channel axes (<= kMaxAxes)
  RotationConvention rotation{};            // P-CHAN-00393 / P-CHAN-00394
  bool move_tool_offsets_directly = false;  // P-CHAN-00100
};

// One tool record as the D word selects it (tool list, converted to mm).
struct ToolOffsets {
  int d_number = 0;             // 0 = D0, no offsets
  double length_mm = 0;         // wz[i].laenge: along the tool axis
  AxisValues axis_offset_mm{};   // wz[i].ax_versatz[j]: per channel axis
  bool tool_fixed = false;      // P-TOOL-00010: 1 = machine directions
};

// #SUPPRESS OFFSETS [..]: the kinds left out for one block. CS, ACS, ECS and
// #ROTATION are never suppressed (use #MCS for that).
struct SuppressMask {
  static constexpr std::uint8_t kZero = 1, kAddZero = 2, kPset = 4, kClamp = 8,
                                kTool = 16, kMeasure = 32, kManual = 64;
  std::uint8_t bits = 0;
  static constexpr SuppressMask none() { return {0}; }
  static constexpr SuppressMask all() { return {127}; }  // no option list
  constexpr bool has(std::uint8_t b) const { return (bits & b) != 0; }
};

enum class OffsetKind : std::uint8_t {
  rotation, ecs, cs, acs, zero, g92, pset, measure, manual, clamp, tool, tlc
};
inline constexpr std::size_t kOffsetKinds = 12;  // values of OffsetKind
std::string_view to_string(OffsetKind k);  // "rotation", "cs", "zero" ...

enum class CsFamily : std::uint8_t { cs, acs };

// One line of active_offsets(): what acts, with its effective values.
struct OffsetEntry {
  OffsetKind kind{};
  int id = 0;               // CS/ACS id, zero-offset index, D number
  AxisValues values_mm{};   // per axis; CS/ACS/ECS: shift in X Y Z;
                            // rotation: CENTER1/CENTER2 on the plane axes
  Vec3 angle_deg{};         // CS/ACS phi1..phi3; rotation: angle in [2]
  std::uint32_t pending_axes = 0;  // bit j: new value waits for axis j
  AxisValues selected_mm{};        // what the program selected (= values_mm unless pending)
};
using ActiveOffsets = FixedVector<OffsetEntry, 20>;

// #CS MODE ON [..] parsed: what to change (unset = keep).
struct CsModeChange {
  std::optional<RotationSequence> sequence;
  std::optional<RotationMode> mode;
};
// Accepts "ROTATION_SEQUENCE=ZYX", "ROTATION_SEQUENCE ZYX",
// "ROTATION_MODE_FIXED" (= extrinsic), "ROTATION_MODE_FIXED=0|1", combined.
std::expected<CsModeChange, FrameError> parse_cs_mode(std::string_view text);

// A value selected now and the value acting now, per axis (G91 rule).
struct Deferred {
  AxisValues selected{};
  AxisValues effective{};
  void commit(std::size_t j) { effective[j] = selected[j]; }
  void commit_all() { effective = selected; }
  bool pending(std::size_t j) const { return selected[j] != effective[j]; }
};

class OffsetChain {
 public:
  using Result = std::expected<void, FrameError>;  // the error may be a warning

  OffsetChain() = default;
  explicit OffsetChain(const ChainConfig& config);

  // Program start: everything off, plane G17, CS mode back to the config.
  void reset();

  // --- channel state the checks need -------------------------------------
  void set_trc_active(bool on) { trc_active_ = on; }    // G41/G42 (20802, 20671)
  void set_rtcp_active(bool on) { rtcp_active_ = on; }  // #TRAFO ON (20669)
  // G17/G18/G19. A real change switches an active #ROTATION off and returns
  // warning 21143 for the caller to report; the tool axis follows the plane.
  std::optional<FrameError> set_plane(Plane p);
  Plane plane() const { return plane_; }

  // --- coordinate systems ------------------------------------------------
  Result rotation_on(double angle_deg, double center1_mm = 0, double center2_mm = 0);
  void rotation_off();
  Result cs_define(CsFamily f, std::optional<int> id, const CsValues& v);  // DEF
  // ON [[id]][v..] with values, ON [id] / ON without.
  Result cs_on(CsFamily f, std::optional<int> id, const std::optional<CsValues>& v);
  Result cs_off(CsFamily f);
  Result cs_off_all(CsFamily f);
  Result cs_add(std::string_view name, const CsValues& v);  // #CS ADD
  Result cs_select(std::string_view name);                  // #CS SELECT
  void cs_mode_on(const CsModeChange& change);              // #CS MODE ON
  void cs_mode_off();                                       // back to P-CHAN values
  const RotationConvention& cs_convention() const { return convention_; }
  // #ECS ON: `effector` comes from the tool orientation (kinematics, caller).
  Result ecs_on(const RigidFrame& effector = {});
  Result ecs_off();
  Result mcs_on(bool ex_tool);
  Result mcs_off();
  bool mcs_active() const { return mcs_active_; }

  // --- translation offsets -----------------------------------------------
  // G53/G54..G59 (index 0..6) and G159=index.
  Result select_zero_offset(const ZeroOffsetTable& table, int index);
  int zero_index() const { return state_.zero_index; }
  Result set_g92(int axis, double value_mm, bool incremental);
  // #PSET: the actual position `actual` shall read value_mm on `axis` in
  // program coordinates (through the whole chain: tool, #CS, #ROTATION);
  // the preset itself is a translation along the machine axis.
  Result pset(int axis, double value_mm, const McsPoint& actual);
  Result preset(std::optional<int> axis);  // #PRESET [axis]; also G74
  // G101 axis factor: (measured - target) * factor. nullopt = not measured.
  Result measure_apply(int axis, double factor, std::optional<double> measured_mm,
                       double target_mm);
  Result measure_clear(std::optional<int> axis);  // G102 [axis]
  // #GET MANUAL OFFSETS: the handwheel offset is already travelled, so it
  // acts at once.
  Result set_manual_offset(int axis, double value_mm);
  Result set_clamp_offsets(const AxisValues& offset_mm);  // at program start
  // D word (D0 = ToolOffsets{}); P-CHAN-00100 decides whether it moves now.
  Result select_tool(const ToolOffsets& tool);
  const ToolOffsets& tool() const { return state_.tool; }  // the D in force
  Result tlc_on(double delta_mm);
  Result tlc_off();

  // --- G91 rule -----------------------------------------------------------
  void commit_axis(std::size_t j);  // axis j programmed absolutely (G90)
  void commit_all();
  bool is_pending(std::size_t j) const;
  std::uint32_t pending_axes() const;

  // --- mapping (rt: noexcept, no allocation) --------------------------------
  // True when a #ROTATION, #ECS, #CS or #ACS is on: the map turns or mixes
  // the main axes; otherwise each axis is only shifted.
  bool turns() const noexcept {
    return state_.rotation.active || state_.ecs_active || state_.cs.effective_depth() > 0 ||
           state_.acs.effective_depth() > 0;
  }
  McsPoint to_mcs(const PcsPoint& p, SuppressMask m = SuppressMask::none()) const noexcept;
  PcsPoint to_pcs(const McsPoint& p, SuppressMask m = SuppressMask::none()) const noexcept;
  // #SUPPRESS OFFSETS needs G90 (20985).
  static Result check_suppress(bool incremental);

  ActiveOffsets active_offsets() const;
  const CsStore& cs_store(CsFamily f) const { return f == CsFamily::cs ? state_.cs : state_.acs; }
  const ChainConfig& config() const { return config_; }

 private:
  struct RotationState {
    bool active = false;
    double angle_deg = 0, center1_mm = 0, center2_mm = 0;
  };
  // Zero and G92 offsets as they were when a CS/ACS was switched on; put
  // back at its OFF, so offsets programmed inside it are dropped.
  struct Scope {
    Deferred zero, g92;
    int zero_index = 0;
  };
  struct State {
    RotationState rotation;
    CsStore cs, acs;
    bool ecs_active = false;
    RigidFrame ecs;
    Deferred zero, g92, pset, measure;
    Deferred tool_pcs, tool_mcs, tlc;  // vectors; tlc acts in the tool's frame
    AxisValues manual{}, clamp{};
    int zero_index = 0;
    ToolOffsets tool;
    bool tlc_active = false;
    double tlc_delta_mm = 0;
    FixedVector<Scope, CsStore::kMaxActive> cs_scopes, acs_scopes;
  };

  Result check_axis(int axis, double value) const;
  Result check_cs_change(CsFamily f) const;
  CsStore& store(CsFamily f) { return f == CsFamily::cs ? state_.cs : state_.acs; }
  void push_scope(CsFamily f);
  void pop_scope(CsFamily f, bool all);
  void apply_tool(State& s, bool commit_now) const;
  void apply_tlc(State& s) const;
  AxisValues wcs_sum(const State& s, SuppressMask m) const;
  void add_pcs_level(AxisValues& v, SuppressMask m, double sign) const;
  void add_mcs_level(AxisValues& v, SuppressMask m, double sign) const;
  void append_deferred(ActiveOffsets& out, OffsetKind k, const Deferred& d, int id) const;

  ChainConfig config_{};
  RotationConvention convention_{};
  Plane plane_ = Plane::g17;
  bool trc_active_ = false;
  bool rtcp_active_ = false;
  State state_{};
  bool mcs_active_ = false;
  bool mcs_ex_tool_ = false;
  State saved_{};  // the state before #MCS ON
};

}  // namespace nck::frames
