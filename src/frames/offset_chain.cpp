// OffsetChain: the operations that select and deselect offsets. The mapping
// PCS <-> MCS and the listing are in offset_chain_map.cpp.
#include "nck/frames/offset_chain.hpp"

#include <cmath>

namespace nck::frames {
namespace {

std::unexpected<FrameError> fail(ErrorId id, int axis = -1, int detail = 0) {
  return std::unexpected(FrameError{id, axis, detail});
}

}  // namespace

OffsetChain::OffsetChain(const ChainConfig& config) : config_(config) {
  if (config_.axis_count > kMaxAxes) config_.axis_count = kMaxAxes;
  reset();
}

void OffsetChain::reset() {
  convention_ = config_.rotation;
  plane_ = Plane::g17;
  trc_active_ = false;
  rtcp_active_ = false;
  state_ = State{};
  saved_ = State{};
  mcs_active_ = false;
  mcs_ex_tool_ = false;
}

OffsetChain::Result OffsetChain::check_axis(int axis, double value) const {
  if (axis < 0 || static_cast<std::size_t>(axis) >= config_.axis_count)
    return fail(ErrorId::FrAxisOutOfRange, axis);
  if (!std::isfinite(value)) return fail(ErrorId::FrValueNotFinite, axis);
  return {};
}

// Shared rule of every CS switch: not inside #MCS (seed §2.2.6), not with
// tool radius compensation active (20802).
OffsetChain::Result OffsetChain::check_cs_change(CsFamily) const {
  if (mcs_active_) return fail(ErrorId::FrNotAllowedInMcs);
  if (trc_active_) return fail(ErrorId::FrCsChangeWithTrc);
  return {};
}

std::optional<FrameError> OffsetChain::set_plane(Plane p) {
  if (p == plane_) return std::nullopt;
  plane_ = p;
  // The tool length follows the new tool axis; it moves there under the G91 rule.
  apply_tool(state_, false);
  apply_tlc(state_);
  if (mcs_active_) {
    apply_tool(saved_, false);
    apply_tlc(saved_);
  }
  if (!state_.rotation.active) return std::nullopt;
  state_.rotation = RotationState{};
  return FrameError{ErrorId::FrRotationOffByPlaneChange};
}

// --- coordinate systems ------------------------------------------------------

OffsetChain::Result OffsetChain::rotation_on(double angle_deg, double center1_mm,
                                             double center2_mm) {
  if (!std::isfinite(angle_deg) || !std::isfinite(center1_mm) || !std::isfinite(center2_mm))
    return fail(ErrorId::FrValueNotFinite);
  state_.rotation = RotationState{true, angle_deg, center1_mm, center2_mm};
  return {};
}

void OffsetChain::rotation_off() { state_.rotation = RotationState{}; }

void OffsetChain::push_scope(CsFamily f) {
  auto& scopes = f == CsFamily::cs ? state_.cs_scopes : state_.acs_scopes;
  scopes.push_back(Scope{state_.zero, state_.g92, state_.zero_index});
}

// Zero and G92 offsets programmed inside a CS last only until it is
// deselected: put back what was there when it was switched on.
void OffsetChain::pop_scope(CsFamily f, bool all) {
  auto& scopes = f == CsFamily::cs ? state_.cs_scopes : state_.acs_scopes;
  if (scopes.empty()) return;
  const Scope s = all ? scopes[0] : scopes.back();
  state_.zero = s.zero;
  state_.g92 = s.g92;
  state_.zero_index = s.zero_index;
  if (all) {
    scopes.clear();
  } else {
    scopes.pop_back();
  }
}

OffsetChain::Result OffsetChain::cs_define(CsFamily f, std::optional<int> id, const CsValues& v) {
  // Definitions made inside #MCS would vanish with its temporary state.
  if (mcs_active_) return fail(ErrorId::FrNotAllowedInMcs);
  return store(f).define(id, v, convention_, false);
}

OffsetChain::Result OffsetChain::cs_on(CsFamily f, std::optional<int> id,
                                       const std::optional<CsValues>& v) {
  if (auto ok = check_cs_change(f); !ok) return ok;
  auto r = v ? store(f).define(id, *v, convention_, true) : store(f).activate(id);
  if (r) push_scope(f);
  return r;
}

OffsetChain::Result OffsetChain::cs_off(CsFamily f) {
  if (auto ok = check_cs_change(f); !ok) return ok;
  if (!store(f).deactivate()) return fail(ErrorId::FrCsOffWithoutCs);
  pop_scope(f, false);
  return {};
}

OffsetChain::Result OffsetChain::cs_off_all(CsFamily f) {
  if (auto ok = check_cs_change(f); !ok) return ok;
  if (store(f).deactivate_all() > 0) pop_scope(f, true);
  return {};
}

OffsetChain::Result OffsetChain::cs_add(std::string_view name, const CsValues& v) {
  if (auto ok = check_cs_change(CsFamily::cs); !ok) return ok;
  auto r = state_.cs.add(name, v, convention_);
  if (r) push_scope(CsFamily::cs);
  return r;
}

OffsetChain::Result OffsetChain::cs_select(std::string_view name) {
  if (auto ok = check_cs_change(CsFamily::cs); !ok) return ok;
  return state_.cs.select(name);
}

void OffsetChain::cs_mode_on(const CsModeChange& change) {
  if (change.sequence) convention_.sequence = *change.sequence;
  if (change.mode) convention_.mode = *change.mode;
}

void OffsetChain::cs_mode_off() { convention_ = config_.rotation; }

OffsetChain::Result OffsetChain::ecs_on(const RigidFrame& effector) {
  if (mcs_active_) return fail(ErrorId::FrNotAllowedInMcs);
  if (state_.cs.depth() > 0 || state_.acs.depth() > 0 || state_.ecs_active)
    return fail(ErrorId::FrEcsWithOtherCs);
  state_.ecs_active = true;
  state_.ecs = effector;
  return {};
}

OffsetChain::Result OffsetChain::ecs_off() {
  if (!state_.ecs_active) return fail(ErrorId::FrCsOffWithoutCs);
  state_.ecs_active = false;
  state_.ecs = RigidFrame{};
  return {};
}

// #MCS ON: the whole state is parked and an empty one takes over, so every
// offset is off at once and whatever is programmed inside is temporary.
OffsetChain::Result OffsetChain::mcs_on(bool ex_tool) {
  if (trc_active_) return fail(ErrorId::FrCsChangeWithTrc);
  if (mcs_active_) return fail(ErrorId::FrMcsAlreadyActive);
  saved_ = state_;
  state_ = State{};
  mcs_active_ = true;
  mcs_ex_tool_ = ex_tool;
  return {};
}

OffsetChain::Result OffsetChain::mcs_off() {
  if (trc_active_) return fail(ErrorId::FrCsChangeWithTrc);
  if (!mcs_active_) return fail(ErrorId::FrCsOffWithoutCs);
  state_ = saved_;
  saved_ = State{};
  mcs_active_ = false;
  mcs_ex_tool_ = false;
  return {};
}

// --- translation offsets -------------------------------------------------------

OffsetChain::Result OffsetChain::select_zero_offset(const ZeroOffsetTable& table, int index) {
  auto values = table.resolve(index);
  if (!values) return std::unexpected(values.error());
  for (std::size_t j = config_.axis_count; j < kMaxAxes; ++j) (*values)[j] = 0;
  state_.zero.selected = *values;
  state_.zero_index = index;
  return {};
}

OffsetChain::Result OffsetChain::set_g92(int axis, double value_mm, bool incremental) {
  if (auto ok = check_axis(axis, value_mm); !ok) return ok;
  double& sel = state_.g92.selected[static_cast<std::size_t>(axis)];
  sel = incremental ? sel + value_mm : value_mm;  // G91 adds, G90 sets
  return {};
}

OffsetChain::Result OffsetChain::pset(int axis, double value_mm, const McsPoint& actual) {
  if (auto ok = check_axis(axis, value_mm); !ok) return ok;
  auto j = static_cast<std::size_t>(axis);
  if (!std::isfinite(actual.pos_mm[j])) return fail(ErrorId::FrValueNotFinite, axis);
  // The program position of the actual point shall read value_mm on `axis`.
  // Read it through the whole chain without a preset (so tool lengths in
  // machining directions, #CS and #ROTATION count too), put value_mm in, map
  // that point back: the preset is what separates it from the actual point.
  constexpr SuppressMask kWithoutPreset{SuppressMask::kPset};
  PcsPoint wanted = to_pcs(actual, kWithoutPreset);
  wanted.pos_mm[j] = value_mm;
  state_.pset.selected[j] = actual.pos_mm[j] - to_mcs(wanted, kWithoutPreset).pos_mm[j];
  return {};
}

OffsetChain::Result OffsetChain::preset(std::optional<int> axis) {
  if (!axis) {
    state_.pset.selected = AxisValues{};
    return {};
  }
  if (auto ok = check_axis(*axis, 0); !ok) return ok;
  state_.pset.selected[static_cast<std::size_t>(*axis)] = 0;
  return {};
}

OffsetChain::Result OffsetChain::measure_apply(int axis, double factor,
                                               std::optional<double> measured_mm,
                                               double target_mm) {
  if (auto ok = check_axis(axis, factor); !ok) return ok;
  if (!measured_mm) return fail(ErrorId::FrNothingMeasured, axis);
  if (!std::isfinite(*measured_mm) || !std::isfinite(target_mm))
    return fail(ErrorId::FrValueNotFinite, axis);
  state_.measure.selected[static_cast<std::size_t>(axis)] = (*measured_mm - target_mm) * factor;
  return {};
}

OffsetChain::Result OffsetChain::measure_clear(std::optional<int> axis) {
  if (!axis) {
    state_.measure.selected = AxisValues{};
    return {};
  }
  if (auto ok = check_axis(*axis, 0); !ok) return ok;
  state_.measure.selected[static_cast<std::size_t>(*axis)] = 0;
  return {};
}

OffsetChain::Result OffsetChain::set_manual_offset(int axis, double value_mm) {
  if (auto ok = check_axis(axis, value_mm); !ok) return ok;
  state_.manual[static_cast<std::size_t>(axis)] = value_mm;
  return {};
}

OffsetChain::Result OffsetChain::set_clamp_offsets(const AxisValues& offset_mm) {
  AxisValues c{};
  for (std::size_t j = 0; j < config_.axis_count; ++j) {
    if (!std::isfinite(offset_mm[j])) return fail(ErrorId::FrValueNotFinite, static_cast<int>(j));
    c[j] = offset_mm[j];
  }
  state_.clamp = c;
  return {};
}

// Tool vector: length on the tool axis of the current plane plus the
// per-axis offsets; machine or machining directions per tool_fixed.
void OffsetChain::apply_tool(State& s, bool commit_now) const {
  AxisValues vec{};
  for (std::size_t j = 0; j < config_.axis_count; ++j) vec[j] = s.tool.axis_offset_mm[j];
  auto t = static_cast<std::size_t>(plane_axes(plane_).tool);
  if (t < config_.axis_count) vec[t] += s.tool.length_mm;
  s.tool_pcs.selected = s.tool.tool_fixed ? AxisValues{} : vec;
  s.tool_mcs.selected = s.tool.tool_fixed ? vec : AxisValues{};
  if (commit_now) {
    s.tool_pcs.commit_all();
    s.tool_mcs.commit_all();
  }
}

void OffsetChain::apply_tlc(State& s) const {
  s.tlc.selected = AxisValues{};
  auto t = static_cast<std::size_t>(plane_axes(plane_).tool);
  if (s.tlc_active && t < config_.axis_count) s.tlc.selected[t] = s.tlc_delta_mm;
}

OffsetChain::Result OffsetChain::select_tool(const ToolOffsets& tool) {
  if (!std::isfinite(tool.length_mm)) return fail(ErrorId::FrValueNotFinite);
  for (std::size_t j = 0; j < config_.axis_count; ++j)
    if (!std::isfinite(tool.axis_offset_mm[j])) return fail(ErrorId::FrValueNotFinite, static_cast<int>(j));
  // P-CHAN-00100 = 1 moves the offsets with the D word, except under a
  // kinematic transformation where the next absolute position decides.
  bool direct = config_.move_tool_offsets_directly && !rtcp_active_;
  if (mcs_active_) {
    // The new tool survives #MCS OFF; with EX TOOL it does not act inside.
    saved_.tool = tool;
    apply_tool(saved_, direct);
    if (mcs_ex_tool_) return {};
  }
  state_.tool = tool;
  apply_tool(state_, direct);
  return {};
}

OffsetChain::Result OffsetChain::tlc_on(double delta_mm) {
  if (mcs_active_) return fail(ErrorId::FrNotAllowedInMcs);
  if (rtcp_active_) return fail(ErrorId::FrTlcWithRtcp);
  if (trc_active_) return fail(ErrorId::FrTlcWithTrc);
  if (!std::isfinite(delta_mm)) return fail(ErrorId::FrValueNotFinite);
  state_.tlc_active = true;
  state_.tlc_delta_mm = delta_mm;
  apply_tlc(state_);
  return {};
}

OffsetChain::Result OffsetChain::tlc_off() {
  state_.tlc_active = false;
  state_.tlc_delta_mm = 0;
  apply_tlc(state_);
  return {};
}

// --- G91 rule -------------------------------------------------------------------

void OffsetChain::commit_axis(std::size_t j) {
  if (j >= kMaxAxes) return;
  for (Deferred* d : {&state_.zero, &state_.g92, &state_.pset, &state_.measure,
                      &state_.tool_pcs, &state_.tool_mcs, &state_.tlc})
    d->commit(j);
}

void OffsetChain::commit_all() {
  for (std::size_t j = 0; j < kMaxAxes; ++j) commit_axis(j);
}

bool OffsetChain::is_pending(std::size_t j) const {
  if (j >= kMaxAxes) return false;
  for (const Deferred* d : {&state_.zero, &state_.g92, &state_.pset, &state_.measure,
                            &state_.tool_pcs, &state_.tool_mcs, &state_.tlc})
    if (d->pending(j)) return true;
  return false;
}

std::uint32_t OffsetChain::pending_axes() const {
  std::uint32_t m = 0;
  for (std::size_t j = 0; j < kMaxAxes; ++j)
    if (is_pending(j)) m |= 1u << j;
  return m;
}

OffsetChain::Result OffsetChain::check_suppress(bool incremental) {
  if (incremental) return fail(ErrorId::FrSuppressInG91);
  return {};
}

}  // namespace nck::frames
