#pragma once
// The path of channel 1 as `nck diff --run` compares it: the set points of
// its backplot axes (X, Y, Z by name, else the first linear axes, as the
// report takes them) with the arc length travelled and the NC line that
// moved there, recorded once per cycle in which the tool moved. Bounded:
// beyond kMaxPoints every other point goes and the spacing doubles.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "nck/config/machine.hpp"
#include "nck/kernel/tick_io.hpp"

namespace nck::app {

class PathTrack {
 public:
  static constexpr std::size_t kMaxPoints = 1'000'000;

  struct Point {
    std::array<double, 3> pos{};
    double s_mm = 0;  // arc length from the start
    double t_s = 0;
    std::uint32_t line = 0;
  };

  void start(const config::Machine& m);
  // Once per cycle, after the kernel's tick.
  void take(const kernel::TickOutput& out);
  const std::vector<Point>& points() const { return points_; }
  const std::array<std::string, 3>& axis_names() const { return names_; }
  // The points at most `max_points`, as the report's ghost: {"axes", "x", "y", "z", "line"}.
  nlohmann::ordered_json ghost_json(std::size_t max_points) const;

 private:
  std::array<int, 3> axis_{-1, -1, -1};
  std::array<std::string, 3> names_;
  std::vector<Point> points_;
  std::array<double, 3> last_{};
  double s_mm_ = 0, spacing_mm_ = 0.001;
  std::uint32_t line_ = 0;
  bool started_ = false;
};

// The largest position differences between two tracks (docs/decisions.md,
// "Run diff"): for each point of A, the nearest point of B's path, searched
// forward from the last match: the first valley of the distance along B,
// or a point further within a window of arc length that is clearly nearer;
// the `top` largest, at most one per NC line of A.
nlohmann::ordered_json compare_paths(const PathTrack& a, const PathTrack& b, std::size_t top);

}  // namespace nck::app
