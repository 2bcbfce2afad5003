#pragma once
// The channel's side of the offset chain (setup side, not real-time): owns
// the frames::OffsetChain, the zero-offset table and the tool list, maps
// channel axis indices to the chain's (X Y Z first), and executes the
// offset functions of a block (G54.., G92, D, #CS/#ACS/#ECS/#MCS,
// #ROTATION, #PSET/#PRESET, #TLC).
#include <array>
#include <expected>
#include <string>
#include <vector>

#include "nck/config/machine.hpp"
#include "nck/core/fixed_vector.hpp"
#include "nck/frames/offset_chain.hpp"
#include "nck/kernel/affine_map.hpp"
#include "nck/motion/axis_vector.hpp"
#include "nck/nc/block.hpp"

namespace nck::prep {

using kernel::AffineMap;

struct FrameChanges {
  FixedVector<frames::OffsetKind, 12> kinds;  // offset kinds the block changed
  std::vector<Diagnostic> warnings;
  bool coordinate_system_changed = false;   // CS/ACS/ECS/MCS/ROTATION
};

class ChannelFrames {
 public:
  ChannelFrames(const config::ChannelConfig& ch, const config::ChannelData& data,
                std::size_t n_axes, std::uint32_t clamp_index);

  // Executes the block's offset functions. `mcs_now` is where the axes are
  // when the block starts. An error names what is wrong (ID, message).
  std::expected<FrameChanges, Diagnostic> apply(const nc::Block& b, const motion::AxisVector& mcs_now);

  // The zero-offset list edited (nck serve): a G54..G59 / G159 selected
  // after this takes the new values, the one in force keeps its own.
  void set_zero_offsets(const config::ZeroOffsets& zero);
  // Axis j (channel index) is programmed absolutely: pending offsets act.
  void commit_axis(std::size_t j) {
    const int c = to_chain_[j];
    if (!chain_.is_pending(static_cast<std::size_t>(c))) return;
    ++changes_;
    chain_.commit_axis(static_cast<std::size_t>(c));
  }
  // G101 / G102 on channel axis j (nullopt: all axes); its error as a diagnostic.
  std::expected<void, Diagnostic> measure_apply(std::size_t j, double factor, std::optional<double> measured_mm,
                                                double target_mm, const nc::Block& b);
  std::expected<void, Diagnostic> measure_clear(std::optional<std::size_t> j, const nc::Block& b);
  // G74 homed axis j: its #PSET preset is cleared.
  void preset_axis(std::size_t j) {
    ++changes_;
    (void)chain_.preset(to_chain_[j]);
  }
  // Counts the calls that may have changed the offsets, at least one per
  // change: while it stays, so do the maps (a report asks for the map of
  // every block; most blocks change no offset).
  std::uint64_t changes() const { return changes_; }
  motion::AxisVector to_mcs(const motion::AxisVector& pcs, frames::SuppressMask m) const;
  motion::AxisVector to_pcs(const motion::AxisVector& mcs,
                            frames::SuppressMask m = frames::SuppressMask::none()) const;
  AffineMap affine(frames::SuppressMask m) const;
  // Per-axis values of one offset kind: as the program selected them (offset
  // events), or as they act now (final state; differs while the G91 rule defers).
  std::vector<std::pair<std::string, double>> values_of(frames::OffsetKind k, bool selected) const;
  frames::ActiveOffsets active() const { return chain_.active_offsets(); }
  // The zero-offset group in force (a CS's OFF may have put back another
  // than the program's last G53..G59).
  int zero_index() const { return chain_.zero_index(); }
  bool mcs_active() const { return chain_.mcs_active(); }
  // The tool record of the D in force (nullptr for D0).
  const config::ToolRecord* tool_in_force() const;
  int tool_number() const { return chain_.tool().d_number; }
  const std::string& axis_name(std::size_t j) const { return names_[j]; }
  // Chain index of channel axis j.
  int chain_index(std::size_t j) const { return to_chain_[j]; }

 private:
  frames::AxisValues to_chain_order(const AxisArray& v) const;
  frames::PcsPoint pcs_point(const motion::AxisVector& v) const;
  motion::AxisVector channel_order(const frames::AxisValues& v) const;
  std::expected<void, Diagnostic> apply_hash(const nc::HashCommand& h, const nc::Block& b,
                                             const motion::AxisVector& mcs_now, FrameChanges& out);
  std::expected<void, Diagnostic> apply_words(const nc::Block& b, FrameChanges& out);
  // The translation offsets a change of coordinate system can put back or
  // park, with their selected values (to report what such a change did).
  static constexpr std::array kTranslationKinds{frames::OffsetKind::zero, frames::OffsetKind::g92,
                                                frames::OffsetKind::pset, frames::OffsetKind::measure,
                                                frames::OffsetKind::tool, frames::OffsetKind::tlc};
  using OffsetValues = std::array<std::vector<std::pair<std::string, double>>, kTranslationKinds.size()>;
  OffsetValues translation_values() const;
  void note_changed_translations(const OffsetValues& before, FrameChanges& out) const;

  frames::OffsetChain chain_;
  frames::ZeroOffsetTable zero_table_;
  std::vector<config::ToolRecord> tools_;
  std::vector<std::string> names_;
  std::size_t n_axes_ = 0;
  int zero_modal_ = 0;  // the program's G53..G59/G159 state (not the default index)
  std::array<int, kMaxAxes> to_chain_{};    // channel j -> chain index
  std::array<int, kMaxAxes> to_channel_{};      // chain index -> channel j (-1)
  std::uint64_t changes_ = 0;
};

}  // namespace nck::prep
