#pragma once
// The path the HMI draws, kept by the server so that a page loaded during
// a run (or reloaded) draws what ran before it (issue 48 item 6): per
// channel a point wherever the tool moved since the last state frame, as
// the page's own backplot takes them, with machine and program coordinates
// of X, Y, Z, G0 and the main program's line. Bounded: past kMaxPoints
// every second point goes (the older path coarser, never lost).
#include <array>
#include <span>
#include <cstdint>
#include <string>
#include <vector>

#include "nck/config/machine.hpp"
#include "nck/report/backplot_axes.hpp"  // the HMI's backplot draws the report's axes
#include "nck/run/state_document.hpp"

namespace nck::app::serve {

class LivePath {
 public:
  static constexpr std::size_t kMaxPoints = 50000;  // per channel

  // A new snapshot (its places: state_document's channel_places).
  void take(const LiveSnapshot& s, const config::Machine& m, std::span<const ChannelPlace> places);
  void clear();  // a new run
  // GET /api/v1/path: {"channel", "run", "points", "x", "y", "z", "px", "py", "pz", "rapid", "line"}.
  std::string json(std::size_t channel, std::uint64_t run) const;

 private:
  struct Point {
    std::array<double, 3> mcs{}, pcs{};
    std::uint32_t line = 0;
    bool rapid = false;
  };
  std::array<std::vector<Point>, config::kMaxChannels> channels_;
};

}  // namespace nck::app::serve
