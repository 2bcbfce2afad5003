#pragma once
// Synchronous operation (#ENABLE / #DISABLE AX LINK, ax_link.hpp): enabling
// and disabling coupling groups, keeping other channels off linked
// spindles, and moving path-axis slaves with their master every cycle. The
// spindle slaves got their own actions from preparation. This unit reads a
// command's `link`.
#include <array>
#include <cstdint>

#include "nck/kernel/ax_link.hpp"
#include "cycle.hpp"

namespace nck::kernel {

// Does a coupling group of another channel than `channel` hold spindle u? rt
inline bool linked_to_other_channel(const SpindleUnit& u, std::uint8_t channel) noexcept {
  return u.link_channel != 0 && u.link_channel != channel;
}

class AxisLinkUnit {
 public:
  // setup: P-CHAN-00105, enabled couplings survive M30 / M2.
  void set_preserve(bool on) noexcept { preserve_ = on; }
  // At a block's start: groups off, then the group on (path-axis slaves keep
  // their distance from pos_mm). rt
  Fault start(const LinkCommand& c, const motion::AxisVector& pos_mm, Cycle& cy) noexcept;
  // Each cycle: path-axis slaves follow their master in pos_mm. rt
  void follow(motion::AxisVector& pos_mm) const noexcept {
    if (!links_.empty()) follow_links(pos_mm);  // inline: most programs link nothing
  }
  // Program end dissolves the links unless P-CHAN-00105; abort and reset always. rt
  void end(EndReason end, Cycle& cy) noexcept;
  // The enabled coupling groups' plan-store payloads, in enabling order.
  template <class F>
  void for_each(F&& f) const {
    for (const ActiveLink& l : links_) f(l.cmd.payload);
  }

 private:
  void follow_links(motion::AxisVector& pos_mm) const noexcept;
  struct ActiveLink {
    LinkCommand cmd{};
    std::array<double, kMaxLinkPairs> base_slave_mm{}, base_master_mm{};  // path-axis pairs
  };
  bool linked_elsewhere(std::int8_t spindle, const Cycle& cy) const noexcept;
  void dissolve(std::size_t i, LinkReason why, Cycle& cy) noexcept;
  void emit(const ActiveLink& l, bool on, LinkReason why, Cycle& cy) const noexcept;

  FixedVector<ActiveLink, kMaxLinkGroupNr + 1> links_;
  bool preserve_ = false;
};

}  // namespace nck::kernel
