#pragma once
// The channel's technologies that live in a home of their own
// (docs/architecture.md, "Adding a technology"), listed in technologies.hpp.
// The channel calls them together at fixed points of the cycle, in the
// order of the list; a unit names the attachment it takes (each its own
// kind: a block's attachment of that kind is noted for it) and has only the
// hooks it needs:
//   using Takes = <its kernel::Attachment alternative>;
//   void setup(const config::ChannelConfig&, double dt_s)      setup
//   Fault start(const Takes&, Cycle&)                           a block carrying it starts
//   Fault follow(const motion::AxisVector& path_mm, bool channel_done, Cycle&)
//                                                               every cycle, after the path
//   void add_offset(motion::AxisVector& mcs, std::size_t n_axes) const
//                                                               its share of the machine set point
//   void output(ChannelOutput&, std::size_t n_axes) const       the cycle's outputs
//   bool wind_down()                                            program end: true while it still moves
//   void end(EndReason, Cycle&)                                 the program ended
// Every hook is called in the cyclic path (setup excepted): noexcept,
// allocation-free.
#include <tuple>
#include <type_traits>

#include "nck/config/machine.hpp"
#include "nck/kernel/attachment.hpp"
#include "nck/kernel/tick_io.hpp"
#include "units/cycle.hpp"

namespace nck::kernel {

template <class... Units>
class TechnologyUnits {
 public:
  // Does one of the units take attachment A?
  template <class A>
  static constexpr bool takes = (std::is_same_v<A, typename Units::Takes> || ...);

  template <class U>
  const U& get() const noexcept { return std::get<U>(units_); }

  void setup(const config::ChannelConfig& channel, double dt_s) {
    each([&](auto& u) {
      if constexpr (requires { u.setup(channel, dt_s); }) u.setup(channel, dt_s);
    });
  }
  // A block starts: its attachments are noted (pointers into the command
  // queue, valid while the block is its front), then start() hands them on.
  void begin_block() noexcept { taken_ = {}; }
  template <class A>
  void note(const A& a) noexcept { std::get<const A*>(taken_) = &a; }
  Fault start(Cycle& cy) noexcept {
    Fault f{};
    each([&](auto& u) {
      using U = std::remove_reference_t<decltype(u)>;
      if (const auto* a = std::get<const typename U::Takes*>(taken_); a && !f.any()) f = u.start(*a, cy);
    });
    return f;
  }
  Fault follow(const motion::AxisVector& path_mm, bool channel_done, Cycle& cy) noexcept {
    Fault f{};
    each([&](auto& u) {
      if constexpr (requires { u.follow(path_mm, channel_done, cy); })
        if (!f.any()) f = u.follow(path_mm, channel_done, cy);
    });
    return f;
  }
  void add_offset(motion::AxisVector& mcs, std::size_t n_axes) const noexcept {
    each([&](const auto& u) {
      if constexpr (requires { u.add_offset(mcs, n_axes); }) u.add_offset(mcs, n_axes);
    });
  }
  void output(ChannelOutput& out, std::size_t n_axes) const noexcept {
    each([&](const auto& u) {
      if constexpr (requires { u.output(out, n_axes); }) u.output(out, n_axes);
    });
  }
  // At the program end block: true while one of them still moves (the
  // block waits); every unit is told, none skipped.
  bool wind_down() noexcept {
    bool moving = false;
    each([&](auto& u) {
      if constexpr (requires { u.wind_down(); }) moving = u.wind_down() || moving;
    });
    return moving;
  }
  void end(EndReason reason, Cycle& cy) noexcept {
    each([&](auto& u) {
      if constexpr (requires { u.end(reason, cy); }) u.end(reason, cy);
    });
  }

 private:
  template <class F>
  void each(F&& f) { std::apply([&](auto&... u) { (f(u), ...); }, units_); }
  template <class F>
  void each(F&& f) const { std::apply([&](const auto&... u) { (f(u), ...); }, units_); }

  std::tuple<Units...> units_;
  std::tuple<const typename Units::Takes*...> taken_{};
};

}  // namespace nck::kernel
