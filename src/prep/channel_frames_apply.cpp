// Executing a block's offset functions on the channel's offset chain.
#include <algorithm>
#include <fmt/format.h>

#include "nck/prep/channel_frames.hpp"

namespace nck::prep {
namespace {

using Result = std::expected<void, Diagnostic>;

frames::CsValues cs_values(const nc::CoordSystem& c) {
  frames::CsValues v;
  for (std::size_t i = 0; i < 3; ++i) {
    v.shift_mm[i] = c.values[i];
    v.angle_deg[i] = c.values[i + 3];
  }
  return v;
}

}  // namespace

// A frames error as a diagnostic naming the channel axis.
static Diagnostic frame_diagnostic(const frames::FrameError& e, const nc::Block& b,
                                   const std::vector<std::string>& names, const int* to_channel) {
  const ErrorInfo* info = find_error(e.id);
  std::string msg = info ? std::string(info->text) : std::string("coordinate system error");
  if (e.axis >= 0 && to_channel[e.axis] >= 0)
    msg += fmt::format(" (axis {})", names[static_cast<std::size_t>(to_channel[e.axis])]);
  if (info) msg += fmt::format(": {}", info->remedy);
  return make_diagnostic(e.id, {"", b.line, 0}, std::move(msg));
}

std::expected<FrameChanges, Diagnostic> ChannelFrames::apply(const nc::Block& b,
                                                             const motion::AxisVector& mcs_now) {
  FrameChanges out;
  // Selected whenever the block programs it: after #CS/#ACS/#MCS OFF the
  // chain may hold another offset than the decoder's remembered modal code.
  const bool select_zero = b.zero_offset_programmed || b.modal.zero_offset != zero_modal_;
  // what below may change an offset (most blocks: none of it)
  if (b.modal.plane != chain_.plane() || select_zero || !b.kernel_writes.empty() ||
      b.g_nonmodal.has(nc::GCode::g92) || b.d || b.hash)
    ++changes_;
  auto check = [&](const frames::OffsetChain::Result& r, frames::OffsetKind k) -> Result {
    if (!r) {
      Diagnostic d = frame_diagnostic(r.error(), b, names_, to_channel_.data());
      if (d.severity == Severity::warning) {
        out.warnings.push_back(std::move(d));
      } else {
        return std::unexpected(std::move(d));
      }
    }
    (void)out.kinds.push_back(k);
    return {};
  };
  if (auto w = chain_.set_plane(b.modal.plane)) {
    out.warnings.push_back(frame_diagnostic(*w, b, names_, to_channel_.data()));
    (void)out.kinds.push_back(frames::OffsetKind::rotation);
  }
  if (select_zero) {
    zero_modal_ = b.modal.zero_offset;
    if (auto r = check(chain_.select_zero_offset(zero_table_, zero_modal_), frames::OffsetKind::zero); !r)
      return std::unexpected(r.error());
  }
  if (auto r = apply_words(b, out); !r) return std::unexpected(r.error());
  if (b.hash) {
    const OffsetValues before = translation_values();
    if (auto r = apply_hash(*b.hash, b, mcs_now, out); !r) return std::unexpected(r.error());
    // A CS's OFF puts back the zero and G92 offsets of before its ON; #MCS
    // ON/OFF parks and restores all of them: each change is an event too.
    if (out.coordinate_system_changed) note_changed_translations(before, out);
  }
  return out;
}

ChannelFrames::OffsetValues ChannelFrames::translation_values() const {
  OffsetValues v;
  for (std::size_t i = 0; i < kTranslationKinds.size(); ++i) v[i] = values_of(kTranslationKinds[i], true);
  return v;
}

void ChannelFrames::note_changed_translations(const OffsetValues& before, FrameChanges& out) const {
  const OffsetValues after = translation_values();
  for (std::size_t i = 0; i < kTranslationKinds.size(); ++i)
    if (after[i] != before[i]) (void)out.kinds.push_back(kTranslationKinds[i]);
}

std::expected<void, Diagnostic> ChannelFrames::measure_apply(std::size_t j, double factor,
                                                       std::optional<double> measured_mm,
                                                       double target_mm, const nc::Block& b) {
  ++changes_;
  auto r = chain_.measure_apply(to_chain_[j], factor, measured_mm, target_mm);
  if (r) return {};
  return std::unexpected(frame_diagnostic(r.error(), b, names_, to_channel_.data()));
}

std::expected<void, Diagnostic> ChannelFrames::measure_clear(std::optional<std::size_t> j, const nc::Block& b) {
  ++changes_;
  auto r = chain_.measure_clear(j ? std::optional<int>(to_chain_[*j]) : std::nullopt);
  if (r) return {};
  return std::unexpected(frame_diagnostic(r.error(), b, names_, to_channel_.data()));
}

Result ChannelFrames::apply_words(const nc::Block& b, FrameChanges& out) {
  for (const nc::VariableWrite& w : b.kernel_writes) {
    // V.G.NP[i].V.<axis>: a zero-offset table entry (mm).
    int group = -1;
    char axis[17] = {};
    if (std::sscanf(w.name.c_str(), "V.G.NP[%d].V.%16s", &group, axis) != 2 || group < 0)
      return std::unexpected(make_diagnostic(ErrorId::KernelNotYetSupported, {"", b.line, 0},
                                             fmt::format("writing {} is not executed yet", w.name)));
    auto it = std::find(names_.begin(), names_.end(), std::string(axis));
    if (it == names_.end())
      return std::unexpected(make_diagnostic(ErrorId::KernelNotYetSupported, {"", b.line, 0},
                                             fmt::format("{}: the channel has no axis {}", w.name, axis)));
    if (static_cast<std::size_t>(group) >= zero_table_.groups.size()) zero_table_.groups.resize(static_cast<std::size_t>(group) + 1);
    const int c = to_chain_[static_cast<std::size_t>(it - names_.begin())];
    zero_table_.groups[static_cast<std::size_t>(group)].offset_mm[static_cast<std::size_t>(c)] = w.value;
    if (group == chain_.zero_index()) {
      if (!chain_.select_zero_offset(zero_table_, group))
        return std::unexpected(make_diagnostic(ErrorId::KernelNotYetSupported, {"", b.line, 0}, w.name));
      (void)out.kinds.push_back(frames::OffsetKind::zero);
    }
  }
  if (b.g_nonmodal.has(nc::GCode::g92)) {
    for (std::size_t j = 0; j < n_axes_; ++j) {
      if (!b.axes[j]) continue;
      auto r = chain_.set_g92(to_chain_[j], *b.axes[j], !b.modal.absolute);
      if (!r) return std::unexpected(frame_diagnostic(r.error(), b, names_, to_channel_.data()));
    }
    (void)out.kinds.push_back(frames::OffsetKind::g92);
  }
  std::optional<std::int64_t> d = b.d;
  if (b.hash)
    if (const auto* td = std::get_if<nc::ToolData>(&*b.hash); td && !td->prep) d = td->fields[0];
  if (d) {
    frames::ToolOffsets t;
    t.d_number = static_cast<int>(*d);
    if (*d != 0) {
      if (*d < 0 || static_cast<std::size_t>(*d) >= tools_.size() || !tools_[static_cast<std::size_t>(*d)].given)
        return std::unexpected(make_diagnostic(ErrorId::KernelUnknownTool, {"", b.line, 0},
                                               fmt::format("D{} is not in the tool list", *d)));
      const config::ToolRecord& r = tools_[static_cast<std::size_t>(*d)];
      t.length_mm = r.length_mm;
      t.axis_offset_mm = to_chain_order(r.axis_offset_mm);
      t.tool_fixed = r.tool_fixed;
    }
    auto r = chain_.select_tool(t);
    if (!r) return std::unexpected(frame_diagnostic(r.error(), b, names_, to_channel_.data()));
    (void)out.kinds.push_back(frames::OffsetKind::tool);
  }
  return {};
}

Result ChannelFrames::apply_hash(const nc::HashCommand& h, const nc::Block& b,
                                 const motion::AxisVector& mcs_now, FrameChanges& out) {
  auto fail = [&](const frames::FrameError& e) -> Result {
    return std::unexpected(frame_diagnostic(e, b, names_, to_channel_.data()));
  };
  auto done = [&](const frames::OffsetChain::Result& r, frames::OffsetKind k, bool cs_change) -> Result {
    if (!r) {
      Diagnostic d = frame_diagnostic(r.error(), b, names_, to_channel_.data());
      if (d.severity == Severity::error) return std::unexpected(std::move(d));
      out.warnings.push_back(std::move(d));
    }
    (void)out.kinds.push_back(k);
    out.coordinate_system_changed = out.coordinate_system_changed || cs_change;
    return {};
  };
  if (const auto* c = std::get_if<nc::CoordSystem>(&h)) {
    const frames::CsFamily f = c->acs ? frames::CsFamily::acs : frames::CsFamily::cs;
    const frames::OffsetKind k = c->acs ? frames::OffsetKind::acs : frames::OffsetKind::cs;
    const frames::CsValues v = cs_values(*c);
    switch (c->op) {
      case nc::CsOp::def: return done(chain_.cs_define(f, c->id, v), k, false);
      case nc::CsOp::on:
        return done(chain_.cs_on(f, c->id, c->has_values ? std::optional(v) : std::nullopt), k, true);
      case nc::CsOp::off: return done(chain_.cs_off(f), k, true);
      case nc::CsOp::off_all: return done(chain_.cs_off_all(f), k, true);
      case nc::CsOp::add: return done(chain_.cs_add(c->name, v), k, true);
      case nc::CsOp::select: return done(chain_.cs_select(c->name), k, true);
      case nc::CsOp::mode_on: {
        auto m = frames::parse_cs_mode(c->mode_option);
        if (!m) return fail(m.error());
        chain_.cs_mode_on(*m);
        return {};
      }
      case nc::CsOp::mode_off: chain_.cs_mode_off(); return {};
    }
  }
  if (const auto* e = std::get_if<nc::Ecs>(&h))
    return done(e->on ? chain_.ecs_on() : chain_.ecs_off(), frames::OffsetKind::ecs, true);
  if (const auto* m = std::get_if<nc::Mcs>(&h))
    return done(m->on ? chain_.mcs_on(m->ex_tool) : chain_.mcs_off(), frames::OffsetKind::cs, true);
  if (const auto* r = std::get_if<nc::Rotation>(&h)) {
    if (!r->on) {
      chain_.rotation_off();
      return done({}, frames::OffsetKind::rotation, true);
    }
    return done(chain_.rotation_on(r->angle_deg.value_or(0), r->center1_mm.value_or(0),
                                   r->center2_mm.value_or(0)),
                frames::OffsetKind::rotation, true);
  }
  if (const auto* p = std::get_if<nc::PSet>(&h)) {
    frames::McsPoint actual;
    for (std::size_t j = 0; j < n_axes_; ++j) actual.pos_mm[static_cast<std::size_t>(to_chain_[j])] = mcs_now[j];
    for (const auto& [axis, value] : p->axes) {
      if (axis < 0 || static_cast<std::size_t>(axis) >= n_axes_) continue;
      if (auto r = chain_.pset(to_chain_[static_cast<std::size_t>(axis)], value, actual); !r) return fail(r.error());
    }
    return done({}, frames::OffsetKind::pset, false);
  }
  if (const auto* p = std::get_if<nc::PReset>(&h)) {
    if (p->axes.empty()) return done(chain_.preset(std::nullopt), frames::OffsetKind::pset, false);
    for (int axis : p->axes)
      if (axis >= 0 && static_cast<std::size_t>(axis) < n_axes_)
        if (auto r = chain_.preset(to_chain_[static_cast<std::size_t>(axis)]); !r) return fail(r.error());
    return done({}, frames::OffsetKind::pset, false);
  }
  if (const auto* t = std::get_if<nc::Tlc>(&h))
    return done(t->on ? chain_.tlc_on(t->delta_mm) : chain_.tlc_off(), frames::OffsetKind::tlc, false);
  return {};  // other # commands are not offsets
}

}  // namespace nck::prep
