#pragma once
// The dry run's home cams: each path axis whose G74 searches a cam on a
// real drive (config::HomingMethod::cam) has one, mounted at its reference
// point: the cam is on where the drive stands at or beyond pos_refpkt in
// the search direction (kenngr.ref_richt). A dry run's drive starts in the
// machine's coordinates, so its search ends where the list says.
#include <array>
#include <cstdint>
#include <vector>

#include "nck/config/machine.hpp"
#include "nck/kernel/tick_io.hpp"

namespace nck::sim {

class HomeCams {
 public:
  explicit HomeCams(const config::Machine& m);
  // After a cycle: each cam's switch, from where the cycle left its drive. rt
  void watch(const kernel::TickOutput& out, std::array<kernel::AxisSwitches, drives::kMaxDrives>& axes) const noexcept;

 private:
  struct Cam {
    std::uint8_t channel = 0;  // 0-based
    std::uint8_t axis = 0;     // channel axis
    std::uint8_t list = 0;     // machine axis list
    std::int8_t towards = -1;  // the search direction
    double edge_mm = 0;        // pos_refpkt, in drive coordinates
  };
  std::vector<Cam> cams_;
};

}  // namespace nck::sim
