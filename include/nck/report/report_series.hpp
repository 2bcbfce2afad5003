#pragma once
// The report's data, kept small however long the run: time series as
// min/max envelopes over buckets of cycles, and the tool path as a polyline
// with the points a straight line passes within a tolerance left out.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace nck::app {

// Numbers as short JSON text: at most `decimals` places, trailing zeros cut.
void append_number(std::string& out, double v, int decimals);

// Per cycle, one value per series. A bucket spans `stride` cycles and keeps
// each series' minimum and maximum in the order they occurred; when there
// are kMaxBuckets, neighbours merge and the stride doubles. Drawing the two
// extremes of every bucket reproduces the plot of every cycle at any zoom
// down to one bucket (no aliasing, no solid bands from thinning).
class EnvelopeSeries {
 public:
  static constexpr std::size_t kMaxBuckets = 4096;
  void start(std::size_t series_count, double cycle_s);
  void add(std::uint64_t cycle, std::span<const double> values);
  // {"t":[...],"v":[[...],...]} — two points per bucket (one while stride is 1).
  std::string json(std::span<const int> decimals) const;
  std::size_t buckets() const { return count_; }
  std::uint64_t stride() const { return stride_; }

 private:
  struct Bucket {
    float min = 0, max = 0;
    bool min_first = true;
  };
  void merge_pairs();
  std::vector<Bucket> buckets_;  // bucket k's series s at k * n_ + s
  std::size_t n_ = 0, count_ = 0;
  std::uint64_t stride_ = 1, first_cycle_ = 0;
  std::uint64_t next_start_ = 0;  // the cycle (relative) where the next bucket starts
  bool started_ = false;
  double cycle_s_ = 0.001;
};

// One channel's tool path in machine coordinates (up to three axes).
struct PathPoint {
  std::array<float, 3> pos{};
  std::uint32_t line = 0;  // the block that moved to this point
  std::uint16_t file = 0;  // index into the report's file list
  bool rapid = false;      // G0: drawn dashed
  std::uint32_t frame = 0;  // the report's index of the block's program -> machine map
  double t_s = 0;           // when the tool reached it (the report's time cursor)
};

class PathRecorder {
 public:
  // A new set point: kept as a vertex where the path bends by more than
  // kRecordTolMm, and at every change of block, of G0 / feed or of the map.
  void add(const std::array<double, 3>& pos, std::uint32_t line, std::uint16_t file, bool rapid,
           std::uint32_t frame = 0, double t_s = 0);
  // The vertices, thinned again with the tolerance `tol_mm` (for drawing).
  std::vector<PathPoint> simplified(double tol_mm) const;
  // Extents of every set point seen (not only of the vertices).
  const std::array<double, 3>& min() const { return min_; }
  const std::array<double, 3>& max() const { return max_; }
  bool empty() const { return points_.empty(); }

  static constexpr double kRecordTolMm = 0.001;
  // Vertices kept: beyond, the path is thinned with a doubling tolerance to
  // half as many (a block per vertex in a 5-million-block program, or a
  // vertex per cycle of a crawling feed, stays bounded).
  static constexpr std::size_t kMaxVertices = 240000;
  // A step shorter than this moves the newest point without giving a
  // direction (F1e-300 steps underflow; their direction is noise).
  static constexpr double kMinStepMm = 1e-9;
  double thinned_tol_mm() const { return thin_tol_mm_; }

 private:
  void thin_in_place();

  std::vector<PathPoint> points_;  // vertices; the last one is the newest set point
  std::vector<PathPoint> scratch_;  // thin_in_place's second buffer
  std::array<double, 3> tip_{};    // the newest set point in full precision
  std::array<double, 3> anchor_{}, dir_{};  // the current run: its start and unit direction
  bool has_dir_ = false;
  std::array<double, 3> min_{}, max_{};
  double thin_tol_mm_ = 0;  // the tolerance of the last in-place thinning (0: none yet)
};

// Distance of p from the line through a and b (from a when a == b).
double distance_to_line(const std::array<float, 3>& p, const std::array<float, 3>& a, const std::array<float, 3>& b);

}  // namespace nck::app
