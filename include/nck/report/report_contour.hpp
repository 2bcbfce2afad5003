#pragma once
// The programmed contour under tool radius compensation (G41/G42), for the
// report's backplot: the blocks as written, before the compensation moves
// them to the tool centre. Watches the channel's decoded blocks
// (prep::PrepObserver) and keeps, from each selection to its G40, the
// programmed points (arcs as short chords) in machine and program
// coordinates. Setup side, only while a report is written.
#include <array>
#include <cstdint>
#include <vector>

#include "nck/motion/axis_vector.hpp"
#include "nck/prep/prep_observer.hpp"

namespace nck::app {

struct ContourPoint {
  std::array<float, 3> mcs{}, pcs{};  // X Y Z (mm)
};

// One compensated stretch: from the selection block to the G40 block.
struct ContourRun {
  std::vector<ContourPoint> points;
  std::uint32_t first_line = 0, last_line = 0;  // of those blocks (in their files)
};

class ProgrammedContour : public prep::PrepObserver {
 public:
  // axis: channel index of X, Y, Z (-1: none).
  explicit ProgrammedContour(const std::array<int, 3>& axis) : axis_(axis) {}
  void decoded(const nc::Block& b, const prep::Planner& planner, bool trc_holding) override;
  const std::vector<ContourRun>& runs() const { return runs_; }

  static constexpr std::size_t kMaxPoints = 50000;  // per channel; beyond, the rest is not drawn
  static constexpr double kMaxChordDeg = 5;          // arcs drawn with chords of at most this angle

 private:
  void move(const nc::Block& b, const prep::Planner& planner);
  void arc_points(const nc::Block& b, const prep::Planner& planner, const motion::AxisVector& from);
  void add(const motion::AxisVector& pcs, const prep::Planner& planner);

  std::array<int, 3> axis_;
  std::vector<ContourRun> runs_;
  motion::AxisVector pos_{};  // programmed position (program coordinates, radius)
  bool tracking_ = false;
  std::size_t points_ = 0;
};

}  // namespace nck::app
