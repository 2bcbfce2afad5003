// Channel list -> ChannelConfig, with the checks that need only this list.
#include <algorithm>
#include <fmt/format.h>
#include <set>

#include "build.hpp"
#include "nck/core/axis_name.hpp"

namespace nck::config::detail {
namespace {

constexpr std::string_view kNameRule =
    "must start with A, B, C, U, V, W, X, Y, Z or Q, followed by letters, digits and _ only";

void read_axes(const ParamList& l, ChannelConfig& c, Diagnostics& d) {
  auto js = l.indices("gruppe[0].achse[", 1);
  check_no_gaps(js, l.loc_prefix("gruppe[0].achse["), "gruppe[0].achse[j]", d);
  for (auto j : js) {
    auto k = [j](std::string_view r) { return fmt::format("gruppe[0].achse[{}].{}", j, r); };
    ChannelAxis ax;
    ax.name = l.text(k("bezeichnung"), "");
    ax.log_axis_nr = l.u32(k("log_achs_nr"), 0);
    SourceLoc where = l.has(k("bezeichnung")) ? l.loc(k("bezeichnung")) : l.loc_prefix(k(""));
    // A name the list reader refused (too long) has its diagnostic at its line.
    if (!valid_path_axis_name(ax.name) && !l.rejected(k("bezeichnung")))
      d.add(ErrorId::ConfigAxisName, where, fmt::format("path axis name '{}' {}", ax.name, kNameRule));
    if (ax.log_axis_nr == 0)
      d.add(ErrorId::ConfigAxisNrZero, l.has(k("log_achs_nr")) ? l.loc(k("log_achs_nr")) : where,
            fmt::format("{} needs a logical axis number other than 0", k("log_achs_nr")));
    c.axes.push_back(std::move(ax));
  }
}

void read_spindle_ranges(const ParamList& l, std::uint32_t i, ChannelSpindle& s, Diagnostics& d) {
  for (std::uint32_t j = 0; j < kMaxGearStages; ++j) {
    auto lo = fmt::format("spindel[{}].range_table[{}].min_speed", i, j);
    auto hi = fmt::format("spindel[{}].range_table[{}].max_speed", i, j);
    s.range_table[j] = SpindleRange{l.num(lo, 0), l.num(hi, 0)};
    cross_check(l, lo, hi, s.range_table[j].min_speed_rpm <= s.range_table[j].max_speed_rpm,
                fmt::format("{} must not exceed {}", listed(l, lo, s.range_table[j].min_speed_rpm),
                            listed(l, hi, s.range_table[j].max_speed_rpm)), d);
  }
  s.range_way_param = l.u32(fmt::format("spindel[{}].range_way", i), 0);
  for (std::size_t j = 0; j < kMaxGearStages; ++j)
    s.range_way[j] = static_cast<std::uint8_t>(s.range_way_param == 0 ? j + 1 : kMaxGearStages - j);
}

void read_spindles(const ParamList& l, ChannelConfig& c, Diagnostics& d) {
  auto is = l.indices("spindel[");
  check_no_gaps(is, l.loc_prefix("spindel["), "spindel[i]", d);
  for (auto i : is) {
    auto k = [i](std::string_view r) { return fmt::format("spindel[{}].{}", i, r); };
    ChannelSpindle s;
    s.source = SourceRef{l.file(), l.loc_prefix(fmt::format("spindel[{}].", i)).line};
    s.name = l.text(k("bezeichnung"), "");
    s.log_axis_nr = l.u32(k("log_achs_nr"), 0);
    s.plc_control = l.flag(k("plc_control"), false);
    s.autom_range = l.flag(k("autom_range"), false);
    s.s_sync = l.u32(k("s_synch"), s.s_sync);
    s.m3_sync = l.u32(k("m3_synch"), s.m3_sync);
    s.m4_sync = l.u32(k("m4_synch"), s.m4_sync);
    s.m5_sync = l.u32(k("m5_synch"), s.m5_sync);
    s.m19_sync = l.u32(k("m19_synch"), s.m19_sync);
    s.s_ack_timeout_s = l.num(k("s_prozess_zeit"), 0);
    s.m3_ack_timeout_s = l.num(k("m3_prozess_zeit"), 0);
    s.m4_ack_timeout_s = l.num(k("m4_prozess_zeit"), 0);
    s.m5_ack_timeout_s = l.num(k("m5_prozess_zeit"), 0);
    s.m19_ack_timeout_s = l.num(k("m19_prozess_zeit"), 0);
    read_spindle_ranges(l, i, s, d);
    SourceLoc where{l.file(), s.source.line, 0};
    if (!s.name.starts_with('S'))
      d.add(ErrorId::ConfigSpindleName, l.has(k("bezeichnung")) ? l.loc(k("bezeichnung")) : where,
            fmt::format("spindle name '{}' must start with S", s.name));
    if (s.log_axis_nr == 0)
      d.add(ErrorId::ConfigAxisNrZero, where, fmt::format("{} must be set to a number other than 0", k("log_achs_nr")));
    c.spindles.push_back(std::move(s));
  }
}

void warn_no_synch(const ParamList& l, const ChannelConfig& c, Diagnostics& d) {
  for (std::size_t n = 0; n < c.spindles.size(); ++n) {
    const auto& s = c.spindles[n];
    // Unlike M3..M19, S under NO_SYNCH is still executed: say what is lost.
    if ((s.s_sync & ~sync::PLC_INFO) == sync::NO_SYNCH)
      d.add(ErrorId::ConfigNoSynchSpeed, l.loc(fmt::format("spindel[{}].s_synch", n)),
            fmt::format("spindel[{}].s_synch of spindle {} is NO_SYNCH: S changes the speed but is "
                        "not output to the PLC and the path does not wait for the speed",
                        n, s.name));
    if (c.spindle_m_fct_free) continue;  // M3..M19 are plain M functions then
    for (auto [fn, v] : {std::pair{"m3", s.m3_sync}, {"m4", s.m4_sync}, {"m5", s.m5_sync}, {"m19", s.m19_sync}}) {
      if (v != sync::NO_SYNCH) continue;
      auto key = fmt::format("spindel[{}].{}_synch", n, fn);
      d.add(ErrorId::ConfigNoSynchSpindle, l.loc(key),
            fmt::format("{} of spindle {} is NO_SYNCH: the kernel will not execute {}", key, s.name, fn));
    }
  }
}

void check_names_and_numbers(const ParamList& l, const ChannelConfig& c, Diagnostics& d) {
  std::set<std::string> names;
  std::set<std::uint32_t> path_nrs, spindle_nrs;
  for (std::size_t j = 0; j < c.axes.size(); ++j) {
    auto where = l.loc_prefix(fmt::format("gruppe[0].achse[{}].", j));
    if (!c.axes[j].name.empty() && !names.insert(c.axes[j].name).second)
      d.add(ErrorId::ConfigDuplicateName, where, fmt::format("axis name '{}' is used twice", c.axes[j].name));
    if (c.axes[j].log_axis_nr != 0 && !path_nrs.insert(c.axes[j].log_axis_nr).second)
      d.add(ErrorId::ConfigAxisNrDuplicate, l.loc(fmt::format("gruppe[0].achse[{}].log_achs_nr", j)), fmt::format("logical axis number {} is used twice", c.axes[j].log_axis_nr));
  }
  for (std::size_t i = 0; i < c.spindles.size(); ++i) {
    const auto& s = c.spindles[i];
    auto where = l.loc_prefix(fmt::format("spindel[{}].", i));
    if (!s.name.empty() && !names.insert(s.name).second)
      d.add(ErrorId::ConfigDuplicateName, where, fmt::format("name '{}' is used twice in the channel", s.name));
    if (s.log_axis_nr == 0) continue;
    where = l.loc(fmt::format("spindel[{}].log_achs_nr", i));
    if (path_nrs.contains(s.log_axis_nr))
      d.add(ErrorId::ConfigAxisNrPathAndSpindle, where,
            fmt::format("logical axis number {} is both a path axis and spindle {}", s.log_axis_nr, s.name));
    else if (!spindle_nrs.insert(s.log_axis_nr).second)
      d.add(ErrorId::ConfigAxisNrDuplicate, where, fmt::format("logical axis number {} is used by two spindles", s.log_axis_nr));
  }
  if (!c.default_ax_name_of_spindle.empty()) {
    auto where = l.loc("default_ax_name_of_spindle");
    if (!valid_path_axis_name(c.default_ax_name_of_spindle))
      d.add(ErrorId::ConfigAxisName, where, fmt::format("default_ax_name_of_spindle {}", kNameRule));
    else if (names.contains(c.default_ax_name_of_spindle))
      d.add(ErrorId::ConfigDuplicateName, where,
            fmt::format("default_ax_name_of_spindle '{}' clashes with a channel axis", c.default_ax_name_of_spindle));
  }
}

// P-CHAN-00253: A1..A32 are alias names only; an axis named so switches
// the alias names off (TF5200 warning 22016, start-up goes on).
void check_alias_names(const ParamList& l, ChannelConfig& c, Diagnostics& d) {
  if (!c.use_alias_names) return;
  for (std::size_t j = 0; j < c.axes.size(); ++j) {
    const std::string& n = c.axes[j].name;
    if (!is_alias_axis_name(n)) continue;
    d.add(ErrorId::ConfigAliasNameAsAxisName, l.loc(fmt::format("gruppe[0].achse[{}].bezeichnung", j)),
          fmt::format("axis name '{}' is one of the alias names A1..A32 while use_alias_name_in_ax_list is 1; "
                      "use_alias_name_in_ax_list is taken as 0",
                      n));
    c.use_alias_names = false;
    return;
  }
}

// P-CHAN-00148 is evaluated only with P-CHAN-00116: alone it is taken as 0
// (TF5200 warning 21404, start-up goes on).
void check_multi_axes(const ParamList& l, ChannelConfig& c, Diagnostics& d) {
  if (!c.multi_axes_in_block || c.multi_dimension_in_block) return;
  d.add(ErrorId::ConfigMultiAxesWithoutMultiDimension, l.loc("multi_axes_in_block"),
        "multi_axes_in_block 1 needs multi_dimension_in_block 1; multi_axes_in_block is taken as 0, so an axis "
        "programmed twice in a block stays error 20203");
  c.multi_axes_in_block = false;
}

void check_main_spindle(const ParamList& l, const ChannelConfig& c, Diagnostics& d) {
  if (l.has("spdl_anzahl") && l.u32("spdl_anzahl", 0) != c.spindles.size())
    d.add(ErrorId::ConfigSpindleCount, l.loc("spdl_anzahl"),
          fmt::format("spdl_anzahl is {} but the list has {} spindel[i] entries", l.u32("spdl_anzahl", 0),
                      c.spindles.size()));
  if (!c.main_spindle_name.starts_with('S'))
    d.add(ErrorId::ConfigSpindleName, l.loc("main_spindle_name"),
          fmt::format("main_spindle_name '{}' must start with S", c.main_spindle_name));
  bool found = std::any_of(c.spindles.begin(), c.spindles.end(),
                           [&](const ChannelSpindle& s) { return s.log_axis_nr == c.main_spindle_ax_nr; });
  if (c.spindles.empty() && c.main_spindle_ax_nr == 0) return;
  if (!found)
    d.add(ErrorId::ConfigMainSpindle, l.has("main_spindle_ax_nr") ? l.loc("main_spindle_ax_nr") : l.loc_prefix("spindel["),
          c.main_spindle_ax_nr == 0
              ? std::string("main_spindle_ax_nr is not set; the main spindle must be configured even with one spindle")
              : fmt::format("main_spindle_ax_nr {} is no spindel[i].log_achs_nr of this channel", c.main_spindle_ax_nr));
}

void read_links(const ParamList& l, ChannelConfig& c, Diagnostics& d) {
  for (auto j : l.indices("synchro_data.koppel_gruppe[0].paar[", 1)) {
    auto k = [j](std::string_view r) { return fmt::format("synchro_data.koppel_gruppe[0].paar[{}].{}", j, r); };
    LinkPair p;
    p.slave_nr = l.u32(k("log_achs_nr_slave"), 0);
    p.master_nr = l.u32(k("log_achs_nr_master"), 0);
    p.mode = l.u32(k("mode"), 0);
    auto name_of = [&](std::uint32_t nr, bool spindle) -> std::string {
      if (spindle) {
        for (const auto& s : c.spindles)
          if (s.log_axis_nr == nr) return s.name;
      } else {
        for (const auto& a : c.axes)
          if (a.log_axis_nr == nr) return a.name;
      }
      return {};
    };
    p.slave = name_of(p.slave_nr, p.mode == 1);
    p.master = name_of(p.master_nr, p.mode == 1);
    if (p.slave.empty() || p.master.empty())
      d.add(ErrorId::ConfigLinkPair, l.loc_prefix(k("")),
            fmt::format("coupling pair {}: axes {} / {} are not both {} of this channel", j, p.slave_nr, p.master_nr,
                        p.mode == 1 ? "spindles" : "path axes"));
    c.default_link_group.pairs.push_back(std::move(p));
  }
}

void read_dist_ctrl(const ParamList& l, DistCtrlConfig& x) {
  auto k = [](std::string_view r) { return fmt::format("dist_ctrl[0].{}", r); };
  x.given = l.any_with_prefix("dist_ctrl[0].");
  x.n_cycles = l.u32(k("n_cycles"), x.n_cycles);
  x.max_deviation_mm = l.num(k("max_deviation"), x.max_deviation_mm);
  x.v_max_mm_s = l.num(k("v_max"), x.v_max_mm_s);
  x.a_max_mm_s2 = l.num(k("a_max"), x.a_max_mm_s2);
  x.max_act_value_change_mm_s = l.num(k("max_act_value_change"), x.max_act_value_change_mm_s);
  x.ref_offset_mm = l.num(k("ref_offset"), x.ref_offset_mm);
  x.max_pos_mm = l.num(k("max_pos"), x.max_pos_mm);
  x.min_pos_mm = l.num(k("min_pos"), x.min_pos_mm);
  x.tolerance_mm = l.num(k("tolerance"), x.tolerance_mm);
  x.check_sw_limit_switch = l.flag(k("check_sw_limit_switch"), false);
  x.mode_dist_use_both_encoder = l.flag(k("mode_dist_use_both_encoder"), false);
  x.use_adaptive_acceleration = l.flag(k("use_adaptive_acceleration"), false);
  x.a_min_mm_s2 = l.num(k("a_min"), x.a_min_mm_s2);
  x.dist_error_a_min_mm = l.num(k("dist_error_a_min"), x.dist_error_a_min_mm);
  x.dist_error_a_max_mm = l.num(k("dist_error_a_max"), x.dist_error_a_max_mm);
  x.low_pass_filter_enable = l.flag(k("low_pass_filter_enable"), false);
  x.low_pass_filter_order = l.u32(k("low_pass_filter_order"), x.low_pass_filter_order);
  x.low_pass_filter_fg_f0_hz = l.num(k("low_pass_filter_fg_f0"), x.low_pass_filter_fg_f0_hz);
  x.optimized_scheduling = l.flag(k("optimized_scheduling"), false);
  x.v_weight_down = l.num(k("v_weight_down"), 0);
  x.a_weight_down = l.num(k("a_weight_down"), 0);
  x.kp = l.num(k("kp"), x.kp);
  x.i_tn_s = l.num(k("i_tn"), x.i_tn_s);
  x.d_tv_s = l.num(k("d_tv"), x.d_tv_s);
  x.kalman_max_dist_change = l.num(k("kalman_max_dist_change"), x.kalman_max_dist_change);
  x.kalman_sigma = l.num(k("kalman_sigma"), x.kalman_sigma);
  x.smoothing_factor = l.num(k("smoothing_factor"), x.smoothing_factor);
  static constexpr std::pair<std::string_view, DistFilter> kFilters[] = {
      {"MOVING_AVERAGE", DistFilter::moving_average}, {"LOWPASS", DistFilter::lowpass},
      {"KALMAN_MA", DistFilter::kalman_ma},           {"EXPO_MEAN", DistFilter::expo_mean},
      {"KALMAN_EXPO", DistFilter::kalman_expo},       {"KALMAN_DYN", DistFilter::kalman_dyn}};
  auto f = l.text(k("filter_type"), "DEFAULT");
  for (auto [name, v] : kFilters)
    if (f == name) x.filter_type = v;
}

void check_dist_ctrl(const ParamList& l, const ChannelConfig& c, Diagnostics& d) {
  const auto& x = c.dist_ctrl;
  auto k = [](std::string_view r) { return fmt::format("dist_ctrl[0].{}", r); };
  if (c.dist_ctrl_possible() && x.a_max_mm_s2 <= 0)
    d.add(ErrorId::ConfigDistCtrlAMaxMissing,
          l.has(k("a_max")) ? l.loc(k("a_max")) : l.loc("configuration.decoder.function"),
          "FCT_3D_DIST_CTRL is enabled but dist_ctrl[0].a_max is not set (> 0)");
  cross_check(l, k("min_pos"), k("max_pos"), x.min_pos_mm < x.max_pos_mm,
              "dist_ctrl[0].min_pos must be below dist_ctrl[0].max_pos", d);
  cross_check(l, k("dist_error_a_min"), k("dist_error_a_max"), x.dist_error_a_min_mm <= x.dist_error_a_max_mm,
              "dist_ctrl[0].dist_error_a_min must not exceed dist_error_a_max", d);
  if (x.use_adaptive_acceleration)
    cross_check(l, k("a_min"), k("a_max"), x.a_min_mm_s2 <= x.a_max_mm_s2,
                "dist_ctrl[0].a_min must not exceed dist_ctrl[0].a_max", d);
}

void read_switches(const ParamList& l, ChannelConfig& c) {
  c.main_spindle_name = l.text("main_spindle_name", c.main_spindle_name);
  c.main_spindle_ax_nr = l.u32("main_spindle_ax_nr", 0);
  c.main_spindle_gear_change = l.flag("main_spindle_gear_change", false);
  c.default_ax_name_of_spindle = l.text("default_ax_name_of_spindle", "");
  c.use_alias_names = l.flag("use_alias_name_in_ax_list", false);
  c.multi_dimension_in_block = l.flag("multi_dimension_in_block", false);
  c.multi_axes_in_block = l.flag("multi_axes_in_block", false);
  c.cax_face_id = l.u32("cax_face_id", 0);
  for (std::size_t i = 0; i < c.trafo_ids.size(); ++i) c.trafo_ids[i] = l.u32(fmt::format("trafo[{}].id", i), 0);
  c.move_tool_offsets_directly = l.flag("move_tool_offsets_directly", false);
  c.exact_stop_after_g00 = l.flag("exact_stop_after_g00", false);
  c.slope_profile = slope_from_number(l.u32("prog_start.slope.profile", 0)).value_or(SlopeProfile::step);
  c.single_step_mode = static_cast<std::int8_t>(l.num("einzelschrittmodus", 0));
  c.rapid_override_mode = rapid_override_mode_from(l.text("g00_override_mode", "0")).value_or(RapidOverrideMode::not_used);
  c.lookahead_blocks = l.u32("configuration.interpolator.number_blocks_lah", c.lookahead_blocks);
  c.m_synch.fill(sync::NOT_VALID);  // P-CHAN-00041 default: an M function the list does not name is unknown
  for (auto n : l.indices("m_synch[")) c.m_synch[n] = l.u32(fmt::format("m_synch[{}]", n), 0);
  c.decoder_function = l.u32("configuration.decoder.function", 0);
  c.max_cache_number = l.u32("configuration.decoder.max_cache_number", 4);
  c.max_cache_size_kb = l.u32("configuration.decoder.max_cache_size", 4096);
  for (std::size_t i = 0; i < 2; ++i) {
    c.decoder_fct_enable[i] = l.u32(fmt::format("configuration.decoder.fct_enable[{}]", i), 0);
    c.decoder_fct_condition[i] = l.text(fmt::format("configuration.decoder.fct_condition[{}]", i), "ISG_STANDARD");
  }
  c.preserve_coupling_after_prog_end = l.flag("synchro_data.preserve_coupling_after_prog_end", false);
  c.einrechnen_mit_t = l.flag("einrechnen_mit_t", false);
  c.mass_einh_inch = l.u32("mass_einh", 0) == 1;
  c.messtyp = l.u32("messtyp", 1);
  c.versch_im_durchm = l.flag("versch_im_durchm", false);
  c.spindle_m_fct_free = l.flag("spindle_m_fct_free", false);
  c.modal_i_j_k_for_circle = l.flag("modal_i_j_k_for_circle", false);
  c.display_diameter_pos = l.flag("display_diameter_pos", false);
  c.thread_ignore_override = l.flag("thread_cutting.ignore_override", false);
  c.thread_chain = l.flag("thread_cutting.thread_chain", false);
  c.rotation_mode_fixed = l.flag("coordinate_system.rotation_mode_fixed", false);
  c.rotation_sequence = l.text("coordinate_system.rotation_sequence", "ZYX");
}

}  // namespace

ChannelConfig build_channel(const ParamList& l, std::uint32_t number, Diagnostics& d) {
  ChannelConfig c;
  c.source = SourceRef{l.file(), 0};
  c.number = number;
  read_switches(l, c);
  read_axes(l, c, d);
  read_spindles(l, c, d);
  read_links(l, c, d);
  read_dist_ctrl(l, c.dist_ctrl);
  check_names_and_numbers(l, c, d);
  check_main_spindle(l, c, d);
  check_alias_names(l, c, d);
  check_multi_axes(l, c, d);
  warn_no_synch(l, c, d);
  check_dist_ctrl(l, c, d);
  return c;
}

}  // namespace nck::config::detail
