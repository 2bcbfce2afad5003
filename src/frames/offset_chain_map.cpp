// OffsetChain: mapping between PCS and MCS (see the chain order in
// offset_chain.hpp) and the listing of what is active.
#include <cctype>
#include <string>

#include <fmt/format.h>

#include "nck/frames/offset_chain.hpp"

namespace nck::frames {
namespace {

Vec3 main_axes(const AxisValues& v) { return {v[0], v[1], v[2]}; }
void set_main_axes(AxisValues& v, const Vec3& q) {
  v[0] = q[0];
  v[1] = q[1];
  v[2] = q[2];
}

bool any_nonzero(const AxisValues& v) {
  for (double x : v)
    if (x != 0) return true;
  return false;
}

}  // namespace

// Sum of the WCS-level translations (zero, G92, PSET, G101, clamp).
AxisValues OffsetChain::wcs_sum(const State& s, SuppressMask m) const {
  AxisValues sum{};
  for (std::size_t j = 0; j < config_.axis_count; ++j) {
    if (!m.has(SuppressMask::kZero)) sum[j] += s.zero.effective[j];
    if (!m.has(SuppressMask::kAddZero)) sum[j] += s.g92.effective[j];
    if (!m.has(SuppressMask::kPset)) sum[j] += s.pset.effective[j];
    if (!m.has(SuppressMask::kMeasure)) sum[j] += s.measure.effective[j];
    if (!m.has(SuppressMask::kClamp)) sum[j] += s.clamp[j];
  }
  return sum;
}

void OffsetChain::add_pcs_level(AxisValues& v, SuppressMask m, double sign) const {
  const State& s = state_;
  bool tool = !m.has(SuppressMask::kTool);
  bool tlc_here = tool && !s.tool.tool_fixed;
  for (std::size_t j = 0; j < config_.axis_count; ++j) {
    double d = 0;
    if (!m.has(SuppressMask::kManual)) d += s.manual[j];
    if (tool) d += s.tool_pcs.effective[j];
    if (tlc_here) d += s.tlc.effective[j];
    v[j] += sign * d;
  }
}

void OffsetChain::add_mcs_level(AxisValues& v, SuppressMask m, double sign) const {
  const State& s = state_;
  AxisValues sum = wcs_sum(s, m);
  bool tool = !m.has(SuppressMask::kTool);
  bool tlc_here = tool && s.tool.tool_fixed;
  for (std::size_t j = 0; j < config_.axis_count; ++j) {
    double d = sum[j];
    if (tool) d += s.tool_mcs.effective[j];
    if (tlc_here) d += s.tlc.effective[j];
    v[j] += sign * d;
  }
}

McsPoint OffsetChain::to_mcs(const PcsPoint& p, SuppressMask m) const noexcept {
  const State& s = state_;
  AxisValues v = p.pos_mm;
  if (s.rotation.active) {
    PlaneAxes a = plane_axes(plane_);
    Vec3 c{};
    c[a.first] = s.rotation.center1_mm;
    c[a.second] = s.rotation.center2_mm;
    Vec3 q = main_axes(v);
    Vec3 d{q[0] - c[0], q[1] - c[1], q[2] - c[2]};
    Vec3 r = mul(plane_rotation(a.first, a.second, s.rotation.angle_deg), d);
    set_main_axes(v, {r[0] + c[0], r[1] + c[1], r[2] + c[2]});
  }
  add_pcs_level(v, m, +1.0);
  Vec3 q = main_axes(v);
  if (s.ecs_active) q = s.ecs.to_parent(q);
  for (std::size_t i = s.cs.effective_depth(); i-- > 0;) q = s.cs.active(i).frame.to_parent(q);
  for (std::size_t i = s.acs.effective_depth(); i-- > 0;) q = s.acs.active(i).frame.to_parent(q);
  set_main_axes(v, q);
  add_mcs_level(v, m, +1.0);
  return McsPoint{v};
}

PcsPoint OffsetChain::to_pcs(const McsPoint& p, SuppressMask m) const noexcept {
  const State& s = state_;
  AxisValues v = p.pos_mm;
  add_mcs_level(v, m, -1.0);
  Vec3 q = main_axes(v);
  for (std::size_t i = 0; i < s.acs.effective_depth(); ++i) q = s.acs.active(i).frame.to_child(q);
  for (std::size_t i = 0; i < s.cs.effective_depth(); ++i) q = s.cs.active(i).frame.to_child(q);
  if (s.ecs_active) q = s.ecs.to_child(q);
  set_main_axes(v, q);
  add_pcs_level(v, m, -1.0);
  if (s.rotation.active) {
    PlaneAxes a = plane_axes(plane_);
    Vec3 c{};
    c[a.first] = s.rotation.center1_mm;
    c[a.second] = s.rotation.center2_mm;
    Vec3 w = main_axes(v);
    Vec3 d{w[0] - c[0], w[1] - c[1], w[2] - c[2]};
    Vec3 r = mul(transpose(plane_rotation(a.first, a.second, s.rotation.angle_deg)), d);
    set_main_axes(v, {r[0] + c[0], r[1] + c[1], r[2] + c[2]});
  }
  return PcsPoint{v};
}

void OffsetChain::append_deferred(ActiveOffsets& out, OffsetKind k, const Deferred& d,
                                  int id) const {
  OffsetEntry e{k, id, d.effective, {}, 0, d.selected};
  for (std::size_t j = 0; j < config_.axis_count; ++j)
    if (d.pending(j)) e.pending_axes |= 1u << j;
  out.push_back(e);
}

ActiveOffsets OffsetChain::active_offsets() const {
  const State& s = state_;
  ActiveOffsets out;
  if (s.rotation.active) {
    OffsetEntry e{OffsetKind::rotation};
    PlaneAxes a = plane_axes(plane_);
    e.values_mm[static_cast<std::size_t>(a.first)] = s.rotation.center1_mm;
    e.values_mm[static_cast<std::size_t>(a.second)] = s.rotation.center2_mm;
    e.angle_deg[2] = s.rotation.angle_deg;
    e.selected_mm = e.values_mm;  // these act at once
    out.push_back(e);
  }
  if (s.ecs_active) {
    OffsetEntry e{OffsetKind::ecs};
    for (std::size_t j = 0; j < kMainAxes; ++j) e.values_mm[j] = s.ecs.shift_mm[j];
    e.selected_mm = e.values_mm;  // these act at once
    out.push_back(e);
  }
  for (auto [kind, st] : {std::pair{OffsetKind::cs, &s.cs}, std::pair{OffsetKind::acs, &s.acs}}) {
    for (std::size_t i = 0; i < st->depth(); ++i) {
      OffsetEntry e{kind, st->active(i).id};
      for (std::size_t j = 0; j < kMainAxes; ++j) e.values_mm[j] = st->active(i).values.shift_mm[j];
      e.angle_deg = st->active(i).values.angle_deg;
      e.selected_mm = e.values_mm;  // these act at once
    out.push_back(e);
    }
  }
  auto listed = [](const Deferred& d) { return any_nonzero(d.selected) || any_nonzero(d.effective); };
  if (listed(s.zero) || s.zero_index != 0) append_deferred(out, OffsetKind::zero, s.zero, s.zero_index);
  if (listed(s.g92)) append_deferred(out, OffsetKind::g92, s.g92, 0);
  if (listed(s.pset)) append_deferred(out, OffsetKind::pset, s.pset, 0);
  if (listed(s.measure)) append_deferred(out, OffsetKind::measure, s.measure, 0);
  if (any_nonzero(s.manual)) out.push_back(OffsetEntry{OffsetKind::manual, 0, s.manual, {}, 0, s.manual});
  if (any_nonzero(s.clamp)) out.push_back(OffsetEntry{OffsetKind::clamp, 0, s.clamp, {}, 0, s.clamp});
  if (s.tool.d_number != 0 || listed(s.tool_pcs) || listed(s.tool_mcs)) {
    Deferred both;
    for (std::size_t j = 0; j < kMaxAxes; ++j) {
      both.selected[j] = s.tool_pcs.selected[j] + s.tool_mcs.selected[j];
      both.effective[j] = s.tool_pcs.effective[j] + s.tool_mcs.effective[j];
    }
    append_deferred(out, OffsetKind::tool, both, s.tool.d_number);
  }
  if (s.tlc_active || listed(s.tlc)) append_deferred(out, OffsetKind::tlc, s.tlc, 0);
  return out;
}

std::string_view to_string(OffsetKind k) {
  switch (k) {
    case OffsetKind::rotation: return "rotation";
    case OffsetKind::ecs: return "ecs";
    case OffsetKind::cs: return "cs";
    case OffsetKind::acs: return "acs";
    case OffsetKind::zero: return "zero";
    case OffsetKind::g92: return "g92";
    case OffsetKind::pset: return "pset";
    case OffsetKind::measure: return "measure";
    case OffsetKind::manual: return "manual";
    case OffsetKind::clamp: return "clamp";
    case OffsetKind::tool: return "tool";
    case OffsetKind::tlc: return "tlc";
  }
  return "?";
}

std::expected<CsModeChange, FrameError> parse_cs_mode(std::string_view text) {
  std::string up(text);
  for (char& ch : up) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  // Skips blanks and one '=' after a keyword; returns the position after.
  auto skip = [&](std::size_t pos) {
    while (pos < up.size() && (up[pos] == ' ' || up[pos] == '\t' || up[pos] == '=')) ++pos;
    return pos;
  };
  CsModeChange c;
  constexpr std::string_view kSeq = "ROTATION_SEQUENCE", kFixed = "ROTATION_MODE_FIXED";
  if (auto p = up.find(kSeq); p != std::string::npos) {
    std::size_t at = skip(p + kSeq.size());
    auto seq = parse_rotation_sequence(std::string_view(up).substr(at, 3));
    if (!seq) return std::unexpected(FrameError{ErrorId::FrUnknownRotationSequence});
    c.sequence = seq;
  }
  if (auto p = up.find(kFixed); p != std::string::npos) {
    std::size_t at = skip(p + kFixed.size());
    bool fixed = !(at < up.size() && up[at] == '0');
    c.mode = fixed ? RotationMode::extrinsic : RotationMode::intrinsic;
  }
  if (!c.sequence && !c.mode) return std::unexpected(FrameError{ErrorId::FrUnknownRotationSequence});
  return c;
}

Diagnostic to_diagnostic(const FrameError& e, SourceLoc loc) {
  const ErrorInfo* info = find_error(e.id);
  std::string msg = info ? std::string(info->text) : std::string("coordinate system error");
  if (e.axis >= 0) msg += fmt::format(" (axis index {})", e.axis);
  if (e.detail != 0) msg += fmt::format(" (value {})", e.detail);
  if (info) msg += fmt::format("; {}", info->remedy);
  return make_diagnostic(e.id, std::move(loc), std::move(msg));
}

}  // namespace nck::frames
