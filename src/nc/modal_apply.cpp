// Stage 3 of a block: the checked words take effect: modal state,
// variables, and the output Block for the channel.
#include <cmath>
#include <fmt/format.h>

#include "block_words.hpp"

namespace nck::nc::detail {

namespace {

void apply_g(GCode code, double value, ModalState& m) {
  using enum GCode;
  switch (code) {
    case g0: m.motion = Motion::rapid; break;
    case g1: m.motion = Motion::linear; break;
    case g2: m.motion = Motion::cw; break;
    case g3: m.motion = Motion::ccw; break;
    case g33: m.motion = Motion::thread; break;
    case g63: m.motion = Motion::tap; break;
    case g331: m.motion = Motion::tap_rigid; break;
    case g332: m.motion = Motion::tap_retract; break;
    case g17: m.plane = Plane::g17; break;
    case g18: m.plane = Plane::g18; break;
    case g19: m.plane = Plane::g19; break;
    case g90: m.absolute = true; break;
    case g91: m.absolute = false; break;
    case g93: m.feed_mode = FeedMode::g93; break;
    case g194: m.feed_mode = FeedMode::g194; break;
    case g94: m.feed_mode = FeedMode::g94; break;
    case g95: m.feed_mode = FeedMode::g95; break;
    case g96: m.speed_mode = SpeedMode::g96; break;
    case g97: m.speed_mode = SpeedMode::g97; break;
    case g40: m.radius_comp = RadiusComp::g40; break;
    case g41: m.radius_comp = RadiusComp::g41; break;
    case g42: m.radius_comp = RadiusComp::g42; break;
    case g51: m.diameter = true; break;
    case g52: m.diameter = false; break;
    case g70: m.inch = true; break;
    case g71: m.inch = false; break;
    // G53 selects entry 0 of the zero-offset table, G54..G59 entries 1..6.
    case g53: case g54: case g55: case g56: case g57: case g58: case g59:
      m.zero_offset = g_number(code) - g_number(g53);
      break;
    case g159: m.zero_offset = static_cast<int>(std::lround(value)); break;
    case g161: m.circle_center_absolute = true; break;
    case g162: m.circle_center_absolute = false; break;
    case g201: m.manual_mode = true; break;
    case g202: m.manual_mode = false; break;
    case g359: m.exact_stop = false; break;
    case g25: m.trc_arc_corners = false; break;
    case g26: m.trc_arc_corners = true; break;
    case g360: m.exact_stop = true; break;
    case g260: m.contour = false; break;
    case g261: m.contour = true; break;
    default: break;  // non-modal codes leave the modal state alone
  }
}

std::optional<SpindleCommand> main_din(const Words& w, BlockCtx& b, const ModalState& m, Block& out) {
  SpindleCommand sc;
  bool any = false;
  sc.name = b.cfg.main_spindle_name;
  sc.target = b.main_target;
  sc.din = true;
  sc.column = w.din_spindle_pos;
  for (const auto& mw : w.m) {
    switch (mw.code) {
      case 3: case 4: case 5:
        if (sc.m == SpindleM::m19) sc.direction = static_cast<SpindleM>(mw.code);
        else sc.m = static_cast<SpindleM>(mw.code);
        any = true;
        break;
      case 19:
        if (sc.m != SpindleM::none) sc.direction = sc.m;
        sc.m = SpindleM::m19;
        any = true;
        break;
      case 40: case 41: case 42: case 43: case 44: case 45:
        sc.gear_stage = mw.code - 39;
        any = true;
        break;
      default: break;
    }
  }
  if (w.s_pos.v) { sc.pos_deg = w.s_pos.v; any = true; }
  if (w.s_pos_shift.v) { sc.pos_shift_deg = w.s_pos_shift.v; any = true; }
  if (w.s_offset.v) { sc.offset_deg = w.s_offset.v; any = true; }
  if (w.s.v) {
    double s = *w.s.v;
    any = true;
    if (w.has_g(GCode::g4)) { out.dwell_revs = s; any = sc.m != SpindleM::none; }
    else if (w.has_g(GCode::g196)) { any = sc.m != SpindleM::none || sc.gear_stage.has_value(); }
    else if (w.has_g(GCode::g74)) sc.g74 = true;
    else if (w.has_g(GCode::g112)) sc.g112_stage = static_cast<int>(std::lround(s));
    else if (w.has_g(GCode::g130)) sc.g130_pct = s;
    else if (w.has_g(GCode::g136)) sc.g136_pct = s;
    else if (w.has_g(GCode::g135)) sc.g135 = true;
    else if (w.has_g(GCode::g137)) sc.g137 = true;
    else if (m.speed_mode == SpeedMode::g96) any = sc.m != SpindleM::none || sc.gear_stage.has_value() || sc.pos_deg;
    else sc.rev_rpm = s;
  }
  if (w.has_g(GCode::g167) && w.s.v) sc.g167 = true;
  if (!any) return std::nullopt;
  return sc;
}

// The channel spindle `sc` addresses, as an index into cfg.spindle_names.
std::optional<std::uint8_t> spindle_index(const DecoderConfig& cfg, const SpindleCommand& sc) {
  const std::string& want = sc.target.empty() ? sc.name : sc.target;
  for (std::size_t i = 0; i < cfg.spindle_names.size() && i <= UINT8_MAX; ++i)
    if (iequals(cfg.spindle_names[i], want)) return static_cast<std::uint8_t>(i);
  return std::nullopt;
}

bool apply_assignments(Words& w, BlockCtx& b, Block& out) {
  for (auto& a : w.assigns) {
    if (a.is_string) {
      if (a.target.is_p)
        return b.x.err.fail(ErrorId::NcTypeMismatch, a.target.pos, "a P parameter cannot hold a string");
      VarStatus s = b.x.vars.write_string(a.target.key, a.str);
      if (s != VarStatus::ok) {
        if (s == VarStatus::not_string)
          return b.x.err.fail(ErrorId::NcTypeMismatch, a.target.pos,
                              fmt::format("{} is numeric; a string cannot be assigned", a.target.key));
        if (s == VarStatus::memory_cap)
          return b.x.err.fail(ErrorId::NcVariableMemory, a.target.pos,
                              fmt::format("the text assigned to {} would take the program's variables past "
                                          "their memory cap ({} MiB)",
                                          a.target.key, b.cfg.max_variable_bytes >> 20));
        return write_lvalue(a.target, b.x, 0);  // reports the error
      }
      continue;
    }
    if (!write_lvalue(a.target, b.x, a.value)) return false;
    if (!a.target.is_p && b.x.vars.is_kernel(a.target.key))
      out.kernel_writes.push_back(VariableWrite{a.target.key, a.value});
  }
  return true;
}

}  // namespace

ModalState preview_modal(const Words& w, const ModalState& m) {
  ModalState r = m;
  for (const auto& g : w.g) apply_g(g.code, g.value, r);
  return r;
}

bool apply_words(Words& w, BlockCtx& b, ModalState& modal, Block& out) {
  if (!apply_assignments(w, b, out)) return false;
  for (const auto& g : w.g) {
    apply_g(g.code, g.value, modal);
    out.g_nonmodal.add(g.code);  // ignores the modal ones
    if (g_group(g.code) == GGroup::manual) out.manual_g = g.code;
    if (g_group(g.code) == GGroup::zero) out.zero_offset_programmed = true;
    if (const auto gw = group_weight(g.code)) out.group_weight_pct[static_cast<std::size_t>(*gw)] = g.value;
  }
  resolve_repeated_axes(w, modal.absolute);
  if (modal.inch) {  // from here on every length is in mm
    words_to_mm(w, modal);
    kernel_writes_to_mm(out.kernel_writes);
  }
  if (w.n.v) out.n = *w.n.v;
  if (w.f.v) {
    out.f = w.f.v;
    switch (modal.feed_mode) {
      case FeedMode::g94: modal.feed_mm_min = *w.f.v; break;
      case FeedMode::g95: modal.feed_mm_rev = *w.f.v; break;
      case FeedMode::g93: modal.feed_time_s = *w.f.v; break;
      case FeedMode::g194: modal.feed_pct = *w.f.v; break;
    }
  }
  if (w.r.v) {
    out.r = w.r.v;
    modal.r = *w.r.v;
  } else if (modal.r != 0 && (modal.motion == Motion::cw || modal.motion == Motion::ccw) && !w.ijk[0].v &&
             !w.ijk[1].v && !w.ijk[2].v) {
    out.r = modal.r;  // R is modal (TF5200 "Radius programming"): a circle without I/J/K or R takes the last R
  }
  for (int i = 0; i < 3; ++i) out.ijk[i] = w.ijk[i].v;
  if (modal.motion == Motion::thread) {
    for (const auto& p : w.ijk)
      if (p.v) { modal.thread_pitch_mm = std::fabs(*p.v); break; }
  } else if (modal.motion == Motion::tap_rigid || modal.motion == Motion::tap_retract) {
    for (const auto& p : w.ijk)
      if (p.v) { modal.tap_pitch_mm = *p.v; break; }
  }
  if (w.t.v) out.t = static_cast<std::int64_t>(*w.t.v);
  if (w.d.v) { out.d = static_cast<std::int64_t>(*w.d.v); modal.d = *out.d; }
  if (w.s.v && !w.has_g(GCode::g4)) {
    if (w.has_g(GCode::g196)) modal.max_speed_rpm = *w.s.v;
    else if (modal.speed_mode == SpeedMode::g96 && !w.has_g(GCode::g74) && !w.has_g(GCode::g112)) modal.css_m_min = *w.s.v;
  }
  // Axis words: a G4 dwell axis and #PSET values are not motion.
  int dwell_axis = -1;
  if (w.has_g(GCode::g4)) {
    dwell_axis = kDwellAxis;
    if (w.dwell_direct.v) out.dwell_s = w.dwell_direct.v;
    else if (w.axes[dwell_axis]) out.dwell_s = w.axes[dwell_axis];
  }
  if (w.time_s.v) out.dwell_s = w.time_s.v;
  if (w.contour_dev.v) modal.contour_dev_mm = *w.contour_dev.v;
  if (w.slope.v) modal.slope = *w.slope.v;
  PSet* pset = w.hash ? std::get_if<PSet>(&*w.hash) : nullptr;
  PReset* preset = w.hash ? std::get_if<PReset>(&*w.hash) : nullptr;
  if (w.axis_count) {
    for (std::size_t i = 0; i < kMaxAxes; ++i) {
      if (!w.axes[i]) continue;
      if (w.has_g(GCode::g4)) continue;
      if (pset) pset->axes.emplace_back(static_cast<int>(i), *w.axes[i]);
      else if (preset) preset->axes.push_back(static_cast<int>(i));
      else out.axes[i] = w.axes[i];
    }
  }
  for (const auto& mw : w.m) {
    int c = mw.code;
    if (c == 17 || c == 29 || spindle_m_function(c)) continue;
    out.m.push_back(c);
    if (mw.value) out.m_values.push_back(FunctionValue{c, *mw.value});
    if (c == 0) out.stop = true;
    if (c == 1) out.optional_stop = true;
    if (c == 2 || c == 30) out.program_end = true;
  }
  for (const auto& hw : w.h) {
    out.h.push_back(hw.code);
    if (hw.value) out.h_values.push_back(FunctionValue{hw.code, *hw.value});
  }
  if (auto sc = main_din(w, b, modal, out)) out.spindles.push_back(std::move(*sc));
  for (auto& sc : w.brackets) out.spindles.push_back(std::move(sc));
  for (auto& sc : out.spindles) sc.spindle_index = spindle_index(b.cfg, sc);
  if (w.hash) {
    if (auto* ms = std::get_if<MainSpindle>(&*w.hash))
      b.main_target = ms->name ? *ms->name : b.cfg.main_spindle;
    if (auto* d = std::get_if<DistCtrl>(&*w.hash)) {
      if (d->set_pos_mm) b.dist_set_pos_known = true;
      if (d->op == DistCtrlOp::on) b.dist_state = d->const_dist ? 2 : 1;
      else if (d->op == DistCtrlOp::freeze) b.dist_state = 3;
      else if (d->op == DistCtrlOp::off) b.dist_state = 0;
    }
    out.hash = std::move(w.hash);
  }
  return true;
}

}  // namespace nck::nc::detail
