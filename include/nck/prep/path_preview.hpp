#pragma once
// The path a program will take, as the pre-flight check plans it: what an
// operator's station draws before cycle start (issue 48 item 6). Points in
// machine and program coordinates of the channel's X, Y and Z, each with
// the NC line that moves there and whether it is a G0; an arc as chords a
// few degrees long. Bounded: past kMaxPoints the check ends and the
// preview says it is cut. Setup side.
#include <array>
#include <cstdint>
#include <vector>

#include "nck/motion/segment.hpp"

namespace nck::prep {

struct PreviewPoint {
  std::array<double, 3> mcs{};
  std::array<double, 3> pcs{};
  std::uint32_t line = 0;
  std::uint16_t file = 0;
  bool rapid = false;
};

class PathPreview {
 public:
  static constexpr std::size_t kMaxPoints = 100000;

  // axes: the channel's axis index of X, Y and Z (-1: the channel has none).
  explicit PathPreview(std::array<int, 3> axes) : axes_(axes) {}

  // A planned motion: its start when the path does not stand there (the
  // first motion, a changed frame), then its chords. to_pcs maps a machine
  // position to program coordinates.
  template <class ToPcs>
  void add(const motion::Segment& s, std::uint16_t file, std::uint32_t line, bool rapid, ToPcs&& to_pcs) {
    motion::AxisVector p = s.start_point();
    if (points_.empty() || pick(p) != points_.back().mcs) push(p, to_pcs(p), file, line, rapid);
    const std::size_t n = chords(s);
    for (std::size_t i = 1; i <= n; ++i) {
      s.point_at(s.length() * static_cast<double>(i) / static_cast<double>(n), p);
      push(p, to_pcs(p), file, line, rapid);
    }
  }

  bool full() const { return points_.size() >= kMaxPoints; }
  const std::vector<PreviewPoint>& points() const { return points_; }

 private:
  static std::size_t chords(const motion::Segment& s);
  std::array<double, 3> pick(const motion::AxisVector& p) const;
  void push(const motion::AxisVector& mcs, const motion::AxisVector& pcs, std::uint16_t file, std::uint32_t line,
            bool rapid);

  std::array<int, 3> axes_;
  std::vector<PreviewPoint> points_;
};

}  // namespace nck::prep
