// Stage 2 of a block: check the combination of words against the modal
// state. Reads only; the first violation becomes the block's error.
#include <cmath>
#include <limits>
#include <type_traits>
#include <fmt/format.h>

#include "block_words.hpp"

namespace nck::nc::detail {

std::optional<GGroup> g_group(GCode code) {
  using enum GCode;
  switch (code) {
    case g0: case g1: case g2: case g3: case g33: case g63: case g331: case g332: return GGroup::motion;
    case g17: case g18: case g19: return GGroup::plane;
    case g90: case g91: return GGroup::dim;
    case g93: case g94: case g95: case g194: return GGroup::feed;
    case g96: case g97: return GGroup::speed;
    case g40: case g41: case g42: return GGroup::comp;
    case g51: case g52: return GGroup::diam;
    case g70: case g71: return GGroup::unit;
    case g53: case g54: case g55: case g56: case g57: case g58: case g59: case g159: return GGroup::zero;
    case g161: case g162: return GGroup::center;
    case g201: case g202: return GGroup::manual;
    case g359: case g360: return GGroup::exact_stop;
    case g260: case g261: return GGroup::contour;
    case g25: case g26: return GGroup::trc_corner;
    default: break;  // the non-modal codes are listed once, in GCodeSet
  }
  if (GCodeSet::is_nonmodal(code)) return GGroup::nonmodal;
  return std::nullopt;
}

std::optional<GCode> to_gcode(int number) {
  if (number < 0 || number > std::numeric_limits<std::underlying_type_t<GCode>>::max()) return std::nullopt;
  const auto code = static_cast<GCode>(number);
  if (!g_group(code)) return std::nullopt;  // a number between the enumerators
  return code;
}

namespace {

bool fail(BlockCtx& b, ErrorId id, std::size_t pos, std::string msg) {
  return b.x.err.fail(id, pos, std::move(msg));
}

bool check_groups(const Words& w, BlockCtx& b) {
  for (std::size_t i = 0; i < w.g.size(); ++i) {
    auto gi = g_group(w.g[i].code);
    if (*gi == GGroup::nonmodal) continue;
    if (*gi == GGroup::dim && b.cfg.multi_dimension_in_block) continue;  // P-CHAN-00116: check_dimensions
    for (std::size_t j = i + 1; j < w.g.size(); ++j)
      if (g_group(w.g[j].code) == gi)
        return fail(b, ErrorId::NcModalConflict, w.g[j].pos,
                    fmt::format("G{} and G{} belong to the same group; program one of them",
                                g_number(w.g[i].code), g_number(w.g[j].code)));
  }
  for (const auto& g : w.g) {
    if (g.code != GCode::g159) continue;
    double r = std::round(g.value);
    if (r < 0 || std::fabs(r - g.value) > 1e-9)
      return fail(b, ErrorId::NcZeroOffsetIndexInvalid, g.pos,
                  fmt::format("G159={} is not an integer >= 0", g.value));
    if (r > b.cfg.max_zero_offset_index)
      return fail(b, ErrorId::NcZeroOffsetIndexTooLarge, g.pos,
                  fmt::format("G159={} exceeds the zero-offset table (0..{})", r, b.cfg.max_zero_offset_index));
  }
  return true;
}

bool check_dwell(const Words& w, BlockCtx& b, const ModalState& modal) {
  if (!w.has_g(GCode::g4)) {
    if (w.time_s.v && w.word_count > 0)
      return fail(b, ErrorId::NcDwellNotAlone, w.time_s.pos, "#TIME must be alone in its block");
    return true;
  }
  std::uint32_t gpos = 0;
  for (const auto& g : w.g)
    if (g.code == GCode::g4) gpos = g.pos;
  (void)modal;
  const int axis = kDwellAxis;  // G4 reads the first main axis: the channel's first, in every plane
  const std::string first = b.axis_upper.empty() ? std::string("X") : b.axis_upper.front();
  int values = (w.dwell_direct.v ? 1 : 0) + (w.s.v ? 1 : 0) + (w.axes[axis] ? 1 : 0);
  if (values > 1)
    return fail(b, ErrorId::NcDwellTwoValues, gpos, "G4 has more than one dwell value; program one");
  if (values == 0 && w.axis_count > 0)
    for (int i = 0; i < static_cast<int>(kMaxAxes); ++i)
      if (w.axes[i])
        return fail(b, ErrorId::NcDwellNotFirstAxis, w.axis_pos[i],
                    fmt::format("G4 takes the dwell on the first main axis {}, not on {}: G4 {}<s>", first,
                                b.axis_upper[static_cast<std::size_t>(i)], first));
  if (values == 0)
    return fail(b, ErrorId::NcBadValue, gpos,
                fmt::format("G4 needs a dwell: G4 <s>, G4 {}<s> (the first main axis) or G4 S<revs>", first));
  int others = w.word_count - 1 - values - (w.axis_count - (w.axes[axis] ? 1 : 0));
  if (others > 0 || w.g.size() > 1 || w.time_s.v)
    return fail(b, ErrorId::NcDwellNotAlone, gpos, "G4 must be alone in its block (only N may precede it)");
  for (int i = 0; i < static_cast<int>(kMaxAxes); ++i)
    if (w.axes[i] && i != axis)
      b.x.err.warn(ErrorId::NcDwellExtraAxes, w.axis_pos[i],
                   fmt::format("G4 with {} beside the first main axis {}: the dwell is read from {} only, {} "
                               "is ignored",
                               b.axis_upper[static_cast<std::size_t>(i)], first, first,
                               b.axis_upper[static_cast<std::size_t>(i)]));
  double v = w.dwell_direct.v ? *w.dwell_direct.v : w.s.v ? *w.s.v : *w.axes[axis];
  if (v < 0) return fail(b, ErrorId::NcDwellOutOfRange, gpos, fmt::format("dwell {} is negative", v));
  return true;
}

bool check_spindle_m(const Words& w, BlockCtx& b, const ModalState& after) {
  const MWord* dir = nullptr;
  const MWord* m19 = w.find_m(19);
  const MWord* gear = nullptr;
  for (const auto& m : w.m) {
    if (spindle_m_function(m.code) && m.value)
      return fail(b, ErrorId::NcMValueNotAllowed, m.pos,
                  fmt::format("M{}={}: the spindle function M{} takes no additional value", m.code, *m.value, m.code));
    if (m.code == 3 || m.code == 4 || m.code == 5) {
      if (dir)
        return fail(b, ErrorId::NcSpindleMConflict, m.pos,
                    fmt::format("M{} conflicts with M{}: at most one of M3/M4/M5 per block", m.code, dir->code));
      dir = &m;
    }
    if (m.code >= 40 && m.code <= 45) {
      if (gear)
        return fail(b, ErrorId::NcGearStageConflict, m.pos, "more than one gear stage M40..M45 in the block");
      gear = &m;
    }
  }
  if (m19 && dir && dir->code == 5)
    return fail(b, ErrorId::NcM19WithM5, dir->pos, "M19 cannot be combined with M5");
  bool g74 = w.has_g(GCode::g74);
  if (g74 && gear)
    return fail(b, ErrorId::NcGearChangeWithG74, gear->pos, "gear change and G74 homing in one block");
  bool bracket_m = false;
  for (const auto& sc : w.brackets) bracket_m = bracket_m || sc.m != SpindleM::none || sc.g74;
  if ((g74 || [&] { for (auto& sc : w.brackets) if (sc.g74) return true; return false; }()) &&
      (dir || m19 || [&] { for (auto& sc : w.brackets) if (sc.m != SpindleM::none) return true; return false; }()))
    return fail(b, ErrorId::NcG74WithSpindleM, dir ? dir->pos : m19 ? m19->pos : 0,
                "G74 homing cannot share a block with spindle M functions");
  bool tapping = after.motion == Motion::tap || after.motion == Motion::tap_rigid ||
                 after.motion == Motion::tap_retract;
  if (tapping && (dir || m19))
    return fail(b, ErrorId::NcTapSpindleM, (dir ? dir : m19)->pos,
                "M3/M4/M5/M19 are not allowed while G63/G331/G332 tapping is active");
  // DIN and spindle syntax for the main spindle in one block.
  bool din = dir || m19 || gear || w.s.v || w.s_pos.v || w.s_offset.v || w.s_pos_shift.v;
  for (const auto& sc : w.brackets)
    if (din && sc.target == b.main_target && !w.has_g(GCode::g4))
      return fail(b, ErrorId::NcSpindleTwice, sc.column, "the main spindle is programmed twice (DIN and S[..])");
  return true;
}

bool check_values(const Words& w, BlockCtx& b, const ModalState& before, const ModalState& after) {
  if (w.f.v && *w.f.v < 0)
    return fail(b, ErrorId::NcNegativeFeed, w.f.pos, fmt::format("F{} is negative", *w.f.v));
  if (w.f.v && after.feed_mode == FeedMode::g194 && *w.f.v >= 100)
    return fail(b, ErrorId::NcFeedPercentRange, w.f.pos,
                fmt::format("G194 F{}: the weighting must be below 100 %", *w.f.v));
  for (const At<double>* td : {&w.t, &w.d})
    if (td->v && (*td->v < 0 || *td->v != std::round(*td->v) || *td->v > 1e12))
      return fail(b, ErrorId::NcBadToolNumber, td->pos, fmt::format("{} must be an integer >= 0", *td->v));
  if (w.r.v && (w.ijk[0].v || w.ijk[1].v || w.ijk[2].v) && after.motion != Motion::thread &&
      after.motion != Motion::tap_rigid && after.motion != Motion::tap_retract)
    return fail(b, ErrorId::NcRadiusWithCenter, w.r.pos, "R and I/J/K in one circle block: program one");
  bool g63_new = w.has_g(GCode::g63);
  if (g63_new && after.feed_mode == FeedMode::g95)
    return fail(b, ErrorId::NcTapWithG95, w.g[0].pos, "G63 needs G94: deselect G95 first");
  if (g63_new && after.speed_mode == SpeedMode::g96)
    return fail(b, ErrorId::NcTapWithG96, w.g[0].pos, "G63 needs G97: deselect G96 first");
  const bool special_s = w.has_any_g(kGCodesTakingS);
  if (w.s.v && !special_s) {
    bool tap = after.motion == Motion::tap;
    if (tap && *w.s.v == 0)
      return fail(b, ErrorId::NcTapSpeedZero, w.s.pos, "G63 with S0: program the tapping speed");
    if (after.speed_mode == SpeedMode::g96) {
      if (*w.s.v <= 0)
        return fail(b, ErrorId::NcCssZero, w.s.pos, "G96 cutting speed must be greater than 0");
    } else if (*w.s.v < 0 && !tap && after.motion != Motion::tap_rigid && after.motion != Motion::tap_retract) {
      return fail(b, ErrorId::NcNegativeSpeed, w.s.pos,
                  fmt::format("S{} is negative; only G63 tapping takes a negative S (retract)", *w.s.v));
    }
  }
  if (w.has_g(GCode::g196) && (!w.s.v || *w.s.v <= 0))
    return fail(b, ErrorId::NcG196MaxNotPositive, w.s.v ? w.s.pos : 0,
                "G196 needs S<max rpm> greater than 0");
  // Thread pitch: G33 needs a pitch when selected, G331 a K.
  bool ijk = w.ijk[0].v || w.ijk[1].v || w.ijk[2].v;
  if (after.motion == Motion::thread) {
    for (const auto& p : w.ijk)
      if (p.v && *p.v == 0) return fail(b, ErrorId::NcThreadPitchZero, p.pos, "G33 pitch must not be 0");
    if (!ijk && before.thread_pitch_mm == 0 && w.has_g(GCode::g33))
      return fail(b, ErrorId::NcThreadPitchZero, w.g[0].pos, "G33 needs a pitch: program I, J or K");
  }
  if (after.motion == Motion::tap_rigid || after.motion == Motion::tap_retract) {
    for (const auto& p : w.ijk)
      if (p.v && *p.v == 0) return fail(b, ErrorId::NcThreadPitchZero, p.pos, "G331 pitch must not be 0");
    if (!ijk && before.tap_pitch_mm == 0 && w.has_g(GCode::g331))
      return fail(b, ErrorId::NcThreadPitchZero, w.g[0].pos, "G331 needs the pitch K");
  }
  if (w.has_g(GCode::g201) && w.axis_count == 0)
    return fail(b, ErrorId::NcG201WithoutAxis, w.g[0].pos, "G201 needs at least one axis, e.g. G201 X1");
  if (w.hash && (std::holds_alternative<PSet>(*w.hash) || std::holds_alternative<PReset>(*w.hash))) {
    for (const auto& g : w.g)
      if (g_group(g.code) == GGroup::motion)
        return fail(b, ErrorId::NcPsetWithPathCondition, g.pos,
                    fmt::format("G{} cannot share a block with #PSET/#PRESET", g_number(g.code)));
    if (std::holds_alternative<PSet>(*w.hash) && w.axis_count == 0)
      return fail(b, ErrorId::NcHashArguments, w.hash_pos, "#PSET needs at least one axis value, e.g. #PSET X20");
  }
  return true;
}

}  // namespace

// The modal state after the block's G codes, without the values (for checks).
ModalState preview_modal(const Words& w, const ModalState& m);

// G60 stops exactly at the end of this block's motion: a block without
// motion has no end to stop at (TF5200 20003).
bool check_exact_stop(const Words& w, BlockCtx& b) {
  for (const auto& g : w.g)
    if (g.code == GCode::g60 && w.axis_count == 0)
      return fail(b, ErrorId::NcExactStopWithoutMotion, g.pos, "G60 needs a motion in its block (axis words)");
  for (const auto& g : w.g)
    if (g.code == GCode::g61 && (w.axis_count == 0 || w.has_g(GCode::g60)))
      return fail(b, ErrorId::KernelContourNeedsMotion, g.pos,
                  w.axis_count == 0 ? "G61 needs a motion in its block (axis words)" : "G61 and G60 in one block");
  return true;
}

bool check_words(const Words& w, BlockCtx& b, const ModalState& modal) {
  if (!check_groups(w, b) || !check_dimensions(w, b, modal) || !check_exact_stop(w, b) || !check_weightings(w, b))
    return false;
  ModalState after = preview_modal(w, modal);
  return check_dwell(w, b, modal) && check_spindle_m(w, b, after) && check_values(w, b, modal, after);
}

}  // namespace nck::nc::detail
