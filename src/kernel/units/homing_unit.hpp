#pragma once
// Which path axes of a channel are homed, and the rule of P-AXIS-00277
// (kenngr.prog_move_requires_homing): a programmed motion that would move an
// axis that requires homing and is not homed is refused at its block's
// start, before anything moves. A G74 command (its HomeAxes attachment)
// marks its axes homed when it ends, at their home position. Jogging is
// manual mode and is not checked (docs/decisions.md "Homing and P-AXIS-00277").
#include <array>
#include <cstdint>
#include <optional>

#include "nck/core/axes.hpp"
#include "nck/kernel/attachment.hpp"
#include "nck/motion/segment.hpp"
#include "nck/kernel/channel_events.hpp"
#include "nck/kernel/command.hpp"

namespace nck::kernel {

class HomingUnit {
 public:
  // setup: channel axis j requires homing before a programmed motion; its
  // refusal names it through message `message` (Kernel::message index; none:
  // the ID's table text).
  void require(std::size_t j, std::optional<std::uint32_t> message) noexcept;
  // setup (or between runs): the axes that are homed (bit j = axis j).
  void set_homed(std::uint32_t mask) noexcept { homed_ = mask; }
  std::uint32_t homed() const noexcept { return homed_; }
  std::uint32_t required() const noexcept { return required_; }

  // A block starts: `home` is its G74 attachment (or none). A motion
  // (segment `seg`, mapped by `map` when a rotation acts) that moves an
  // unhomed axis that requires homing is refused: the error to raise
  // (930740 with the message naming the first such axis). rt
  std::optional<ev::Error> start(const Command& c, const HomeAxes* home, const motion::Segment& seg,
                                 const AffineMap* map) noexcept;
  // The block ended: the axes its G74 homed are homed now. rt
  void end_block() noexcept {
    homed_ |= pending_;
    pending_ = 0;
  }
  // The program ended early (error, reset): a G74 cut short homes nothing. rt
  void reset() noexcept { pending_ = 0; }

 private:
  std::uint32_t required_ = 0;  // P-AXIS-00277 per axis
  std::uint32_t homed_ = ~0u;   // all homed unless the caller says otherwise
  std::uint32_t pending_ = 0;   // the G74 that runs homes these at its end
  std::array<std::optional<std::uint32_t>, kMaxAxes> messages_{};
};

// The axes segment `seg` moves (bit j = axis j): those whose coordinate
// changes anywhere along it (a full circle's end equals its start), after
// `map` when a rotation maps it. rt
std::uint32_t moved_axes(const motion::Segment& seg, const AffineMap* map) noexcept;

}  // namespace nck::kernel
