#include "nck/prep/channel_frames.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <fmt/format.h>

namespace nck::prep {
namespace {

int main_index(const std::string& name) {
  if (name == "X") return 0;
  if (name == "Y") return 1;
  if (name == "Z") return 2;
  return -1;
}

}  // namespace


ChannelFrames::ChannelFrames(const config::ChannelConfig& ch, const config::ChannelData& data,
                             std::size_t n_axes, std::uint32_t clamp_index)
    : tools_(data.tools), n_axes_(n_axes) {
  to_channel_.fill(-1);
  int next = 3;
  for (std::size_t j = 0; j < n_axes_; ++j) {
    names_.push_back(ch.axes[j].name);
    const int m = main_index(ch.axes[j].name);
    to_chain_[j] = m >= 0 ? m : next++;
    to_channel_[static_cast<std::size_t>(to_chain_[j])] = static_cast<int>(j);
  }
  frames::ChainConfig cfg;
  cfg.axis_count = static_cast<std::size_t>(std::max(next, 3));
  cfg.rotation.sequence =
      frames::parse_rotation_sequence(ch.rotation_sequence).value_or(frames::RotationSequence::zyx);
  cfg.rotation.mode = ch.rotation_mode_fixed ? frames::RotationMode::extrinsic : frames::RotationMode::intrinsic;
  cfg.move_tool_offsets_directly = ch.move_tool_offsets_directly;
  chain_ = frames::OffsetChain(cfg);

  set_zero_offsets(data.zero);
  if (zero_table_.default_index != 0) (void)chain_.select_zero_offset(zero_table_, zero_table_.default_index);
  if (clamp_index < data.clamp.versatz.size())
    (void)chain_.set_clamp_offsets(to_chain_order(data.clamp.versatz[clamp_index]));
  chain_.commit_all();
}

// The table a G54..G59 / G159 selects from. An offset in force keeps the
// values it was selected with: a new value acts at the next selection.
void ChannelFrames::set_zero_offsets(const config::ZeroOffsets& zero) {
  zero_table_.g53_available = zero.g53_available;
  zero_table_.default_index = static_cast<int>(zero.default_index);
  if (zero_table_.groups.size() < zero.versch.size()) zero_table_.groups.resize(zero.versch.size());
  for (std::size_t i = 0; i < zero.versch.size(); ++i) {
    zero_table_.groups[i].offset_mm = to_chain_order(zero.versch[i]);
    zero_table_.groups[i].inactive_mask = 0;
    for (std::size_t j = 0; j < n_axes_; ++j)
      if (i < zero.inaktiv.size() && zero.inaktiv[i][j])
        zero_table_.groups[i].inactive_mask |= 1u << to_chain_[j];
  }
}

frames::AxisValues ChannelFrames::to_chain_order(
    const AxisArray& v) const {
  frames::AxisValues out{};
  for (std::size_t j = 0; j < n_axes_; ++j) out[static_cast<std::size_t>(to_chain_[j])] = v[j];
  return out;
}

frames::PcsPoint ChannelFrames::pcs_point(const motion::AxisVector& v) const {
  frames::PcsPoint p;
  for (std::size_t j = 0; j < n_axes_; ++j) p.pos_mm[static_cast<std::size_t>(to_chain_[j])] = v[j];
  return p;
}

motion::AxisVector ChannelFrames::channel_order(const frames::AxisValues& v) const {
  motion::AxisVector out{};
  for (std::size_t j = 0; j < n_axes_; ++j) out[j] = v[static_cast<std::size_t>(to_chain_[j])];
  return out;
}

const config::ToolRecord* ChannelFrames::tool_in_force() const {
  const auto d = static_cast<std::size_t>(chain_.tool().d_number);
  return d > 0 && d < tools_.size() ? &tools_[d] : nullptr;
}

motion::AxisVector ChannelFrames::to_mcs(const motion::AxisVector& pcs, frames::SuppressMask m) const {
  return channel_order(chain_.to_mcs(pcs_point(pcs), m).pos_mm);
}

motion::AxisVector ChannelFrames::to_pcs(const motion::AxisVector& mcs, frames::SuppressMask m) const {
  frames::McsPoint p;
  for (std::size_t j = 0; j < n_axes_; ++j) p.pos_mm[static_cast<std::size_t>(to_chain_[j])] = mcs[j];
  return channel_order(chain_.to_pcs(p, m).pos_mm);
}

AffineMap ChannelFrames::affine(frames::SuppressMask m) const {
  AffineMap a;
  for (std::size_t k = 0; k < 3; ++k) a.main[k] = to_channel_[k];
  a.shift = to_mcs(motion::AxisVector{}, m);
  // Without a rotation or coordinate system every axis is only shifted, each
  // by its own sums: one point with all three main axes at 1 then gives
  // each column's numbers bit for bit as a point per axis would (this runs
  // for every block while a report records the maps).
  std::optional<motion::AxisVector> all_columns;
  if (!chain_.turns()) {
    motion::AxisVector ones{};
    for (std::size_t k = 0; k < 3; ++k)
      if (a.main[k] >= 0) ones[static_cast<std::size_t>(a.main[k])] = 1.0;
    all_columns = to_mcs(ones, m);
  }
  for (std::size_t k = 0; k < 3; ++k) {
    if (a.main[k] < 0) continue;
    const auto axis = static_cast<std::size_t>(a.main[k]);
    motion::AxisVector col = a.shift;
    if (all_columns) {
      col[axis] = (*all_columns)[axis];
    } else {
      motion::AxisVector unit{};
      unit[axis] = 1.0;
      col = to_mcs(unit, m);
    }
    for (std::size_t r = 0; r < 3; ++r) {
      const double v = a.main[r] >= 0 ? col[static_cast<std::size_t>(a.main[r])] - a.shift[static_cast<std::size_t>(a.main[r])] : 0.0;
      a.rot[r][k] = v;
      if (std::abs(v - (r == k ? 1.0 : 0.0)) > 1e-12) a.pure_translation = false;
    }
  }
  return a;
}

// CS and ACS are stacks: every active entry is listed, the outermost with
// plain keys (X, angle1 ...), the next ones prefixed with their level
// ("2.X", "2.angle1" ...); "selected" tells how many act on programmed
// positions when #CS SELECT chose fewer than are stacked.
std::vector<std::pair<std::string, double>> ChannelFrames::values_of(frames::OffsetKind k,
                                                                     bool selected) const {
  const bool stacked = k == frames::OffsetKind::cs || k == frames::OffsetKind::acs;
  const bool has_angles = stacked || k == frames::OffsetKind::rotation;
  std::vector<std::pair<std::string, double>> out;
  std::size_t level = 0;
  for (const frames::OffsetEntry& e : chain_.active_offsets()) {
    if (e.kind != k) continue;
    const std::string prefix = ++level == 1 ? std::string() : fmt::format("{}.", level);
    for (std::size_t j = 0; j < n_axes_; ++j)
      out.emplace_back(prefix + names_[j],
                       (selected ? e.selected_mm : e.values_mm)[static_cast<std::size_t>(to_chain_[j])]);
    if (has_angles)
      for (std::size_t i = 0; i < 3; ++i) out.emplace_back(fmt::format("{}angle{}", prefix, i + 1), e.angle_deg[i]);
    if (!stacked) break;
  }
  if (out.empty())  // the kind was switched off: report zeros
    for (std::size_t j = 0; j < n_axes_; ++j) out.emplace_back(names_[j], 0.0);
  if (stacked) {
    const frames::CsStore& st = chain_.cs_store(k == frames::OffsetKind::cs ? frames::CsFamily::cs : frames::CsFamily::acs);
    if (st.effective_depth() != st.depth()) out.emplace_back("selected", static_cast<double>(st.effective_depth()));
  }
  return out;
}

}  // namespace nck::prep
