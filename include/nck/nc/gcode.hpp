#pragma once
// G functions as an enum whose values are the G numbers (grblHAL style), and
// a fixed set of the non-modal ones a block may program. Only the decoder's
// word import reads G numbers as integers; every later stage (check, apply,
// planner, frames) compares enumerators.
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <iterator>

namespace nck::nc {

enum class GCode : std::uint16_t {
  // motion
  g0 = 0, g1 = 1, g2 = 2, g3 = 3, g33 = 33, g63 = 63, g331 = 331, g332 = 332,
  // plane, dimensions, feed, spindle speed, radius compensation, diameter, unit
  g17 = 17, g18 = 18, g19 = 19,
  g90 = 90, g91 = 91,
  g93 = 93, g94 = 94, g95 = 95, g194 = 194,
  g96 = 96, g97 = 97,
  g40 = 40, g41 = 41, g42 = 42,
  g25 = 25, g26 = 26,  // outside-corner transitions of radius compensation: lines / arcs
  g51 = 51, g52 = 52,
  g70 = 70, g71 = 71,
  // zero offsets (G159=<n> selects any entry), circle centre, manual mode
  g53 = 53, g54 = 54, g55 = 55, g56 = 56, g57 = 57, g58 = 58, g59 = 59, g159 = 159,
  g161 = 161, g162 = 162,
  g201 = 201, g202 = 202,
  g359 = 359, g360 = 360,  // exact stop off / on (modal)
  g260 = 260, g261 = 261,  // corner blending off / on (modal; G61 blends one corner)
  // non-modal: dwell, homing, G92 offset, measuring, spindle functions ...
  g4 = 4, g60 = 60, g61 = 61, g74 = 74, g92 = 92, g100 = 100, g101 = 101, g102 = 102, g106 = 106, g112 = 112,
  g130 = 130, g135 = 135, g136 = 136, g137 = 137, g167 = 167, g196 = 196, g200 = 200,
  // dynamic weightings of the path axes (modal state kept by preparation):
  // G131=/G133=/G134=/G233= carry their percentage, G130/G132 their axis words
  g131 = 131, g132 = 132, g133 = 133, g134 = 134, g233 = 233,
};

// The G number, for messages and the JSON output.
constexpr int g_number(GCode g) noexcept { return static_cast<int>(g); }

// The non-modal G functions programmed in one block, as a bit mask (no heap,
// copied with the block into the cyclic path). Iterates in ascending G
// number order.
class GCodeSet {
 public:
  using Bits = std::uint32_t;
  // Every G code the set can hold, ascending; bit i stands for kCodes[i].
  static constexpr std::array kCodes{GCode::g4,   GCode::g60,  GCode::g61,  GCode::g74,  GCode::g92,  GCode::g100, GCode::g101,
                                     GCode::g102, GCode::g106, GCode::g112, GCode::g130, GCode::g131,
                                     GCode::g132, GCode::g133, GCode::g134, GCode::g135, GCode::g136,
                                     GCode::g137, GCode::g167, GCode::g196, GCode::g200, GCode::g233};

  constexpr GCodeSet() = default;
  constexpr GCodeSet(std::initializer_list<GCode> codes) noexcept {
    for (GCode g : codes) add(g);
  }

  // Whether g is a non-modal code, i.e. one this set can hold.
  static constexpr bool is_nonmodal(GCode g) noexcept { return bit_of(g) != 0; }

  // Adds g; false (and no change) when g is modal.
  constexpr bool add(GCode g) noexcept {
    bits_ |= bit_of(g);
    return bit_of(g) != 0;
  }
  constexpr bool has(GCode g) const noexcept { return (bits_ & bit_of(g)) != 0; }
  constexpr bool has_any(GCodeSet other) const noexcept { return (bits_ & other.bits_) != 0; }
  constexpr bool empty() const noexcept { return bits_ == 0; }
  constexpr std::size_t size() const noexcept { return static_cast<std::size_t>(std::popcount(bits_)); }
  constexpr bool operator==(const GCodeSet&) const = default;

  class iterator {
   public:
    using value_type = GCode;
    using difference_type = std::ptrdiff_t;
    constexpr iterator() = default;
    constexpr explicit iterator(Bits rest) noexcept : rest_(rest) {}
    constexpr GCode operator*() const noexcept { return kCodes[static_cast<std::size_t>(std::countr_zero(rest_))]; }
    constexpr iterator& operator++() noexcept {
      rest_ &= rest_ - 1;  // clear the lowest set bit
      return *this;
    }
    constexpr iterator operator++(int) noexcept {
      iterator old = *this;
      ++*this;
      return old;
    }
    constexpr bool operator==(const iterator&) const = default;

   private:
    Bits rest_ = 0;
  };
  constexpr iterator begin() const noexcept { return iterator(bits_); }
  constexpr iterator end() const noexcept { return iterator(0); }

 private:
  static constexpr Bits bit_of(GCode g) noexcept {
    for (std::size_t i = 0; i < kCodes.size(); ++i)
      if (kCodes[i] == g) return Bits{1} << i;
    return 0;
  }

  Bits bits_ = 0;
};

static_assert(GCodeSet::kCodes.size() <= 32, "GCodeSet::Bits has one bit per non-modal code");
static_assert(std::forward_iterator<GCodeSet::iterator>);
static_assert(
    [] {
      for (std::size_t i = 1; i < GCodeSet::kCodes.size(); ++i)
        if (GCodeSet::kCodes[i - 1] >= GCodeSet::kCodes[i]) return false;
      return true;
    }(),
    "GCodeSet::kCodes must be ascending: the set iterates in bit order");

}  // namespace nck::nc
