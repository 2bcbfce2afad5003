// Axis list -> AxisConfig, with the checks that need only this one list.
#include <algorithm>

#include <fmt/format.h>

#include "build.hpp"

namespace nck::config::detail {
namespace {

std::string gkey(std::size_t g, std::string_view rest) { return fmt::format("getriebe[{}].{}", g, rest); }

void read_curve(const ParamList& l, std::size_t g, AccelCurve& c) {
  auto k = [g](std::string_view r) { return gkey(g, fmt::format("beschl_kennlinie.{}", r)); };
  c.type = l.u32(k("typ"), c.type);
  c.limit_speed_deg_s = l.num(k("n_grenz"), c.limit_speed_deg_s);
  c.const_accel_deg_s2 = l.num(k("a_konst"), c.const_accel_deg_s2);
  c.a_min_deg_s2 = l.num(k("a_min"), c.a_min_deg_s2);
  c.b1 = l.num(k("b1"), c.b1);
  c.b2 = l.num(k("b2"), c.b2);
  c.b3 = l.num(k("b3"), c.b3);
  c.a_max_deg_s2 = l.num(k("a_max"), c.a_max_deg_s2);
  c.n1_deg_s = l.num(k("n1"), c.n1_deg_s);
  c.n2_deg_s = l.num(k("n2"), c.n2_deg_s);
}

// encoder_ratio_num / encoder_ratio_denom 0: the seed's warning and correction to 1.
std::uint32_t encoder_part(const ParamList& l, const std::string& key, ErrorId id, Diagnostics& d) {
  std::uint32_t v = l.u32(key, 1);
  if (v != 0) return v;
  d.add(id, l.loc(key), fmt::format("'{}' is 0; nck uses 1", key));
  return 1;
}

void read_gear(const ParamList& l, std::size_t g, GearStage& s, Diagnostics& d) {
  auto k = [g](std::string_view r) { return gkey(g, r); };
  s.given = l.any_with_prefix(fmt::format("getriebe[{}].", g));
  s.accel_mm_s2 = l.num(k("slope_profil.a_beschl"), s.accel_mm_s2);
  s.decel_mm_s2 = l.num(k("slope_profil.a_brems"), s.decel_mm_s2);
  s.rapid_accel_mm_s2 = l.num(k("slope_profil.a_grenz"), s.rapid_accel_mm_s2);
  s.a_max = l.num(k("dynamik.a_max"), s.a_max);
  s.a_emergency = l.num(k("dynamik.a_emergency"), s.a_emergency);
  s.max_speed_mm_s = l.num(k("dynamik.vb_max"), s.max_speed_mm_s);
  s.rapid_mm_s = l.num(k("vb_eilgang"), s.rapid_mm_s);
  s.position_gain_1_s = l.num(k("kv"), s.position_gain_1_s);
  s.modulo_upper = l.num(k("moduloo"), s.modulo_upper);
  s.modulo_lower = l.num(k("modulou"), s.modulo_lower);
  s.zero_speed_deg_s = l.num(k("vb_min_null"), s.zero_speed_deg_s);
  s.control_limit_deg_s = l.num(k("vb_regelgrenze"), s.control_limit_deg_s);
  s.gear_change_pos_deg = l.num(k("getr_schalt_pos"), s.gear_change_pos_deg);
  s.reference_pos = l.num(k("pos_refpkt"), s.reference_pos);
  s.homing_fast_mm_s = l.num(k("vb_refmax"), s.homing_fast_mm_s);
  s.homing_slow_mm_s = l.num(k("vb_reflow"), s.homing_slow_mm_s);
  s.homing_accel_mm_s2 = l.num(k("a_ref"), s.homing_accel_mm_s2);
  s.encoder_ratio_num = encoder_part(l, k("wegaufz"), ErrorId::ConfigWegaufzZero, d);
  s.encoder_ratio_denom = encoder_part(l, k("wegaufn"), ErrorId::ConfigWegaufnZero, d);
  s.reverse_sense = l.flag(k("reverse"), s.reverse_sense);
  s.tr_acc_down_s = l.num(k("slope_profil.tr_beschl_ab"), s.tr_acc_down_s);
  s.tr_acc_up_s = l.num(k("slope_profil.tr_beschl_zu"), s.tr_acc_up_s);
  s.tr_dec_down_s = l.num(k("slope_profil.tr_brems_ab"), s.tr_dec_down_s);
  s.tr_dec_up_s = l.num(k("slope_profil.tr_brems_zu"), s.tr_dec_up_s);
  s.tr_geom_s = l.num(k("dynamik.tr_geom"), s.tr_geom_s);
  s.tr_rapid_s = l.num(k("slope_profil.tr_grenz"), s.tr_rapid_s);
  s.tr_min_s = l.num(k("dynamik.tr_min"), s.tr_min_s);
  s.a_w_max_mm_s2 = l.num(k("dynamik.a_w_max"), s.a_w_max_mm_s2);
  s.tr_w_min_s = l.num(k("dynamik.tr_w_min"), s.tr_w_min_s);
  s.a_trans_weight = l.num(k("dynamik.a_trans_weight"), s.a_trans_weight);
  s.multi_gain_z = l.u32(k("multi_gain_z"), s.multi_gain_z);
  s.multi_gain_n = l.u32(k("multi_gain_n"), s.multi_gain_n);
  s.modulo_error_incr = static_cast<std::int32_t>(l.num(k("modulo_fehler"), 0));
  s.modulo_revolutions = static_cast<std::int32_t>(l.num(k("modulo_umdreh"), 0));
  read_curve(l, g, s.curve);
}

// P-AXIS-00270, a spindle's acceleration profile: 0..2 name STEP, TRAPEZ
// and SIN2; any other number is the TF5200's warning 60226, corrected to
// its default 0. A characteristic curve (beschl_kennlinie.typ 1..3) needs
// slope type 0 (TF5200, P-AXIS-00202's section): the curve gives the
// acceleration, so a jerk-limited type beside it is 930900 and STEP too.
void read_slope_type(const ParamList& l, std::size_t g, const AxisConfig& a, GearStage& s, Diagnostics& d) {
  const std::string key = gkey(g, "slope_type");
  const ParamValue* at = l.find(key);
  if (!at) return;
  const std::uint32_t n = l.u32(key, 0);
  if (n > 2) {
    d.add(ErrorId::ConfigSpindleSlopeType, at->loc,
          fmt::format("{} = {} (axis {}) is not 0 (STEP), 1 (TRAPEZ) or 2 (SIN2); nck uses 0", key, n, a.log_axis_nr));
    return;
  }
  s.slope_type = static_cast<SlopeProfile>(n);
  if (jerk_limited(s.slope_type) && a.is_spindle() && s.curve.type >= 1 && s.curve.type <= 3) {
    d.add(ErrorId::ConfigSpindleSlopeWithCurve, at->loc,
          fmt::format("{} = {} beside {} = {}: the curve gives the acceleration; nck uses slope type 0", key, n,
                      gkey(g, "beschl_kennlinie.typ"), s.curve.type));
    s.slope_type = SlopeProfile::step;
  }
}

// The ramp times of the jerk-limited slopes may not undercut the drive's
// tr_min (P-AXIS-00201): a shorter ramp would ask for more jerk than it
// allows. The error points at the ramp time, or at tr_min when only that
// is given (a default ramp time below a raised tr_min).
void check_ramp_times(const ParamList& l, std::size_t g, const GearStage& s, Diagnostics& d) {
  auto k = [g](std::string_view r) { return gkey(g, r); };
  const std::string min_key = k("dynamik.tr_min");
  for (auto [key, v] : {std::pair{k("slope_profil.tr_beschl_ab"), s.tr_acc_down_s},
                        {k("slope_profil.tr_beschl_zu"), s.tr_acc_up_s}, {k("slope_profil.tr_brems_ab"), s.tr_dec_down_s},
                        {k("slope_profil.tr_brems_zu"), s.tr_dec_up_s}, {k("slope_profil.tr_grenz"), s.tr_rapid_s}}) {
    if (v >= s.tr_min_s) continue;
    const ParamValue* at = l.find(key) ? l.find(key) : l.find(min_key);
    if (!at) continue;
    d.add(ErrorId::ConfigRampBelowMin, at->loc,
          fmt::format("{} = {:.0f} µs is below {} = {:.0f} µs", key, v * 1e6, min_key, s.tr_min_s * 1e6));
  }
}

// The weighting limits, where given: a_w_max between the larger feed
// acceleration and a_max, tr_w_min between tr_min and the shortest feed
// ramp time (P-AXIS-00292/00293's ranges).
void check_weight_limits(const ParamList& l, std::size_t g, const GearStage& s, Diagnostics& d) {
  auto k = [g](std::string_view r) { return gkey(g, r); };
  // 0 (the TF5200 default) stands for no limit of its own.
  if (const ParamValue* at = l.find(k("dynamik.a_w_max")); at && s.a_w_max_mm_s2 > 0) {
    const double lo = std::max(s.accel_mm_s2, s.decel_mm_s2);
    if (s.a_w_max_mm_s2 < lo || s.a_w_max_mm_s2 > s.a_max)
      d.add(ErrorId::ConfigWeightLimit, at->loc,
            fmt::format("{} = {} is outside max(a_beschl, a_brems) = {} ... a_max = {}", k("dynamik.a_w_max"),
                        s.a_w_max_mm_s2, lo, s.a_max));
  }
  if (const ParamValue* at = l.find(k("dynamik.tr_w_min")); at && s.tr_w_min_s > 0) {
    const double hi = std::min({s.tr_acc_up_s, s.tr_acc_down_s, s.tr_dec_up_s, s.tr_dec_down_s});
    if (s.tr_w_min_s < s.tr_min_s || s.tr_w_min_s > hi)
      d.add(ErrorId::ConfigWeightLimit, at->loc,
            fmt::format("{} = {:.0f} µs is outside tr_min = {:.0f} µs ... the shortest feed ramp time {:.0f} µs",
                        k("dynamik.tr_w_min"), s.tr_w_min_s * 1e6, s.tr_min_s * 1e6, hi * 1e6));
  }
}

// P-AXIS-00078's range: strictly between the software limits (P-AXIS-00177
// < getr_schalt_pos < P-AXIS-00178), where the position is given: the
// default 0 of a stage that never shifts is never approached.
void check_gear_change_position(const ParamList& l, const AxisConfig& a, std::size_t g, Diagnostics& d) {
  const std::string key = gkey(g, "getr_schalt_pos");
  const ParamValue* at = l.find(key);
  const double pos = a.gears[g].gear_change_pos_deg;
  if (!at || (pos > a.sw_limit_neg && pos < a.sw_limit_pos)) return;
  const std::size_t unit_part = a.kind == AxisKind::translatory ? 0 : 1;
  d.add(ErrorId::ConfigCrossRange, at->loc,
        fmt::format("{} must lie strictly between {} and {}", listed(l, key, pos, unit_part),
                    listed(l, "kenngr.swe_neg", a.sw_limit_neg, unit_part),
                    listed(l, "kenngr.swe_pos", a.sw_limit_pos, unit_part)));
}

// Parameter relations of one gear stage (ranges that name another parameter).
void check_gear(const ParamList& l, const AxisConfig& a, std::size_t g, Diagnostics& d) {
  const GearStage& s = a.gears[g];
  auto k = [g](std::string_view r) { return gkey(g, r); };
  auto amax = k("dynamik.a_max");
  // Values in the list's own units; linear axes read the first unit of "µm/s · 0.001°/s".
  const std::size_t unit_part = a.kind == AxisKind::translatory ? 0 : 1;
  auto show = [&](const std::string& key, double v) { return listed(l, key, v, unit_part); };
  cross_check(l, k("vb_eilgang"), k("dynamik.vb_max"), s.rapid_mm_s <= s.max_speed_mm_s,
              fmt::format("{} must not exceed {}", show(k("vb_eilgang"), s.rapid_mm_s),
                          show(k("dynamik.vb_max"), s.max_speed_mm_s)), d);
  cross_check(l, k("vb_reflow"), k("vb_refmax"), s.homing_slow_mm_s <= s.homing_fast_mm_s,
              fmt::format("{} must not exceed {}", show(k("vb_reflow"), s.homing_slow_mm_s),
                          show(k("vb_refmax"), s.homing_fast_mm_s)), d);
  for (auto [key, v] : {std::pair{k("slope_profil.a_beschl"), s.accel_mm_s2}, {k("slope_profil.a_brems"), s.decel_mm_s2},
                        {k("slope_profil.a_grenz"), s.rapid_accel_mm_s2}, {k("beschl_kennlinie.a_max"), s.curve.a_max_deg_s2},
                        {k("a_ref"), s.homing_accel_mm_s2}})
    cross_check(l, key, amax, v <= s.a_max,
                fmt::format("{} must not exceed {}", show(key, v), show(amax, s.a_max)), d);
  check_ramp_times(l, g, s, d);
  check_weight_limits(l, g, s, d);
  check_gear_change_position(l, a, g, d);
  cross_check(l, k("dynamik.a_emergency"), amax, s.a_emergency <= 2 * s.a_max,
              fmt::format("{} must not exceed 2 x {}", k("dynamik.a_emergency"), amax), d);
  if (a.is_modulo())
    cross_check(l, k("modulou"), k("moduloo"), s.modulo_lower < s.modulo_upper,
                fmt::format("{} must be below {}", show(k("modulou"), s.modulo_lower), show(k("moduloo"), s.modulo_upper)), d);
  const AccelCurve& c = s.curve;
  auto ck = [&](std::string_view r) { return k(fmt::format("beschl_kennlinie.{}", r)); };
  if (c.type == 1 || c.type == 2)
    cross_check(l, ck("typ"), ck("n_grenz"), c.limit_speed_deg_s > 0,
                fmt::format("curve type {} needs {} > 0", c.type, ck("n_grenz")), d);
  if (c.type == 3) {
    cross_check(l, ck("typ"), ck("a_max"), c.a_max_deg_s2 > 0,
                fmt::format("curve type 3 needs {} > 0", ck("a_max")), d);
    cross_check(l, ck("n1"), ck("n2"), c.n1_deg_s <= c.n2_deg_s,
                fmt::format("{} must not exceed {}", show(ck("n1"), c.n1_deg_s), show(ck("n2"), c.n2_deg_s)), d);
    cross_check(l, ck("n2"), k("dynamik.vb_max"), c.n2_deg_s <= s.max_speed_mm_s,
                fmt::format("{} must not exceed {}", show(ck("n2"), c.n2_deg_s), show(k("dynamik.vb_max"), s.max_speed_mm_s)),
                d);
  }
}

void read_head(const ParamList& l, AxisConfig& a) {
  a.source = SourceRef{l.file(), l.loc("kopf.achs_nr").line};
  a.log_axis_nr = l.u32("kopf.achs_nr", 1);
  a.name = l.text("kopf.log_achs_name", a.name);
  a.kind = static_cast<AxisKind>(l.u32("kenngr.achs_typ", 1));
  a.axis_mode = l.u32("kenngr.achs_mode", a.axis_mode);
  a.drive_type = l.u32("kenngr.antr_typ", a.drive_type);
  a.drive_simulation = l.flag("kenngr.drive_simulation", a.drive_simulation);
  a.drive_enable_timeout_s = l.num("antr.enable_timeout_ms", a.drive_enable_timeout_s);
  a.drive_homing_timeout_s = l.num("antr.homing_timeout_ms", a.drive_homing_timeout_s);
  a.sw_limit_neg = l.num("kenngr.swe_neg", a.sw_limit_neg);
  a.sw_limit_pos = l.num("kenngr.swe_pos", a.sw_limit_pos);
  a.initial_gear_stage = l.u32("kenngr.getriebe_stufe", a.initial_gear_stage);
  a.has_preferred_direction = l.flag("kenngr.vorz_richtung", a.has_preferred_direction);
  a.preferred_direction_positive = l.flag("kenngr.beweg_richt", a.preferred_direction_positive);
  a.speed_reached_tolerance_permille = l.num("kenngr.vb_prozent", a.speed_reached_tolerance_permille);
  a.homing_without_cam = l.flag("kenngr.ref_ohne_nocken", a.homing_without_cam);
  a.homing_without_reversal = l.flag("kenngr.ref_ohne_rev", a.homing_without_reversal);
  a.homing_positive = l.flag("kenngr.ref_richt", a.homing_positive);
  a.drive_controlled_homing = l.text("kenngr.homing.homing_type", "CNC_CONTROLLED") == "DRIVE_CONTROLLED";
  a.prog_move_requires_homing = l.flag("kenngr.prog_move_requires_homing", a.prog_move_requires_homing);
  a.no_stop_by_channel_reset = l.flag("kenngr.no_stop_by_channel_reset", a.no_stop_by_channel_reset);
  a.cax_gear_stage = l.u32("kenngr.def_cax_gear_st", a.cax_gear_stage);
  a.diameter_prog_abs = l.flag("kenngr.durchm_prog_abs", a.diameter_prog_abs);
  a.diameter_prog_rel = l.flag("kenngr.durchm_prog_rel", a.diameter_prog_rel);
  a.fast_from_cam = l.flag("kenngr.fast_from_cam", a.fast_from_cam);
  a.measure_speed = l.num("kenngr.vb_messen", a.measure_speed);
  a.feedhold_deceleration_mode = l.text("kenngr.feedhold_deceleration_mode", a.feedhold_deceleration_mode);
  a.jog_speed_mm_s = l.num("handbetrieb.tipp.geschw[0]", a.jog_speed_mm_s);
  a.jog_increment_speed_mm_s = l.num("handbetrieb.jog.geschw[0]", a.jog_increment_speed_mm_s);
  a.manual_max_speed_mm_s = l.num("handbetrieb.hb.vb_max", a.manual_max_speed_mm_s);
  a.manual_a_max_mm_s2 = l.num("handbetrieb.hb.a_max", a.manual_a_max_mm_s2);
  a.modulo_compensation = l.flag("lr_param.mod_komp", a.modulo_compensation);
  a.distance_control_on = l.flag("lr_param.distance_control_on", a.distance_control_on);
}

void read_drive(const ParamList& l, AxisConfig& a) {
  if (const auto mode = drive_mode_from(l.text("antr.operation_mode", "DRIVE_DEFAULT"))) a.drive_mode = *mode;
  a.speed_increments_num = l.u32("antr.v_reso_num", a.speed_increments_num);
  a.speed_increments_denom = l.u32("antr.v_reso_denom", a.speed_increments_denom);
  a.speed_time_base = l.u32("antr.v_time_base", a.speed_time_base);
  a.velocity_position_control_on = l.num("antr.velocity_position_control_on", a.velocity_position_control_on);
  a.velocity_position_control_off = l.num("antr.velocity_position_control_off", a.velocity_position_control_off);
  a.secondary_encoder = l.text("antr.secondary_encoder", a.secondary_encoder);
  double faktor_us = l.num("vorsteuer.vs_a_faktor", 1);
  double nenner = l.num("vorsteuer.vs_a_nenner", 1);
  a.feedforward_ta_s = faktor_us * 1e-6 / (nenner > 0 ? nenner : 1);
}

}  // namespace

AxisConfig build_axis(const ParamList& l, Diagnostics& d) {
  AxisConfig a;
  read_head(l, a);
  read_drive(l, a);
  for (std::size_t g = 0; g < kMaxGearStages; ++g) {
    read_gear(l, g, a.gears[g], d);
    read_slope_type(l, g, a, a.gears[g], d);
  }
  if (a.homing_without_cam && !a.homing_without_reversal)
    d.add(ErrorId::ConfigRefWithoutCam, l.loc("kenngr.ref_ohne_nocken"),
          "kenngr.ref_ohne_nocken 1 requires kenngr.ref_ohne_rev 1");
  if (!a.is_modulo())
    cross_check(l, "kenngr.swe_neg", "kenngr.swe_pos", a.sw_limit_neg < a.sw_limit_pos,
                fmt::format("kenngr.swe_neg ({}) must be below kenngr.swe_pos ({})", a.sw_limit_neg, a.sw_limit_pos), d);
  for (std::size_t g = 0; g < kMaxGearStages; ++g)
    if (g == 0 || a.gears[g].given) check_gear(l, a, g, d);
  return a;
}

}  // namespace nck::config::detail

namespace nck::config {

std::optional<DriveMode> drive_mode_from(std::string_view symbol) noexcept {
  struct Name {
    std::string_view symbol;
    DriveMode mode;
  };
  static constexpr Name kNames[] = {
      {"DRIVE_DEFAULT", DriveMode::drive_default},
      {"DRIVE_POSITION_CONTROL", DriveMode::drive_position_control},
      {"CNC_POSITION_CONTROL", DriveMode::cnc_position_control},
      {"DSC_POSITION_CONTROL", DriveMode::dsc_position_control},
      {"OPEN_POSITION_LOOP_MODE", DriveMode::open_loop},
      {"OPEN_POSITION_LOOP_MODE_EXACT", DriveMode::open_loop_exact},
      {"OPEN_POSITION_LOOP_POS_FEEDBACK", DriveMode::open_loop_pos_feedback},
      {"OPEN_POSITION_LOOP_VEL_FEEDBACK", DriveMode::open_loop_vel_feedback},
      {"OPEN_POSITION_LOOP_NO_FEEDBACK", DriveMode::open_loop_no_feedback},
  };
  for (const Name& n : kNames)
    if (n.symbol == symbol) return n.mode;
  // Any other OPEN_POSITION_LOOP* spelling still means speed-controlled.
  if (symbol.starts_with("OPEN_POSITION_LOOP")) return DriveMode::open_loop;
  return std::nullopt;
}

}  // namespace nck::config
