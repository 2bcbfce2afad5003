#pragma once
// One channel's tool path for the report's backplots and time cursor, kept
// small however long the run: of the set point of every cycle, the vertices
// between which linear interpolation in time gives every cycle's position
// within tol_mm() on each axis, and a vertex at the last cycle of every
// block (and of every G0 / feed and map change), so that the stretch from a
// vertex to the next one lies in the one block the later vertex names. The
// page's cursor (time -> block, DRO) and hover (point -> block) then agree
// with the events and the trace (issue 48 item 1; docs/decisions.md, "the
// report's path is timed").
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace nck::app {

// A set point: where the tool is at t_s (MCS, the backplot's X Y Z) and the
// block that moved it there.
struct TimedPoint {
  std::array<double, 3> pos{};
  double t_s = 0;
  std::uint32_t line = 0;   // the block in execution
  std::uint32_t frame = 0;  // the report's index of the block's program -> machine map
  std::uint16_t file = 0;   // index into the report's file list
  bool rapid = false;       // G0: drawn dashed
};

class TimedPath {
 public:
  // Within a tenth of the DRO's last digit (its 3 decimals) at every cycle.
  static constexpr double kTolMm = 1e-4;
  // Vertices kept while recording, as many as the page shows: beyond, they
  // are thinned again with a doubling tolerance to half as many (a block per
  // vertex in a 5-million-block program stays within some 3 MB).
  static constexpr std::size_t kMaxVertices = 60000;
  // Thinning tolerances beyond this let a segment span blocks (a page of
  // more blocks than points): the labels are then those of its end.
  static constexpr double kMaxBlockTolMm = 1.0;

  // The set point of the next cycle (t_s increasing).
  void add(const TimedPoint& p);
  // The recording ended: the newest set point becomes the last vertex.
  void close();
  // The vertices and the newest set point, thinned again until there are
  // at most max_points; error_mm: their bound against every cycle's
  // position, by_block: every segment lies in one block.
  // `points` views the path's own vertices when they need no thinning and
  // the path is closed (no copy of megabytes), else `thinned` (a move of
  // Vertices keeps that buffer, so the view stays valid).
  struct Vertices {
    std::span<const TimedPoint> points;
    std::vector<TimedPoint> thinned;
    double error_mm = 0;
    bool by_block = true;
  };
  Vertices vertices(std::size_t max_points) const;
  // Extents of every set point seen (not only of the vertices).
  const std::array<double, 3>& min() const { return min_; }
  const std::array<double, 3>& max() const { return max_; }
  bool empty() const { return points_.empty(); }
  double error_mm() const { return error_mm_; }

  // The slopes (mm/s per axis) from an anchor that keep every set point of
  // a run within tol of the line: a new point fits while its own slope lies
  // in all of them (one comparison per axis and cycle, no look-back).
  class Fit {
   public:
    void start(const TimedPoint& anchor, const TimedPoint& p, double tol);
    bool fits(const TimedPoint& anchor, const TimedPoint& p) const;
    void take(const TimedPoint& anchor, const TimedPoint& p, double tol);

   private:
    std::array<double, 3> lo_{}, hi_{};
  };

 private:
  static double thin_until(std::vector<TimedPoint>& points, std::size_t max_points, double last_tol_mm,
                           double& error_mm, bool& by_block);

  std::vector<TimedPoint> points_;  // vertices; the last one anchors the current run
  TimedPoint tip_;                   // the newest set point, not yet a vertex
  bool has_tip_ = false;
  Fit fit_;
  std::array<double, 3> min_{}, max_{};
  double error_mm_ = kTolMm;  // the vertices' bound: kTolMm and the re-thinnings' tolerances, summed
  double thin_tol_mm_ = 0;    // the tolerance of the last thinning while recording (0: none yet)
  bool by_block_ = true;
};

}  // namespace nck::app
