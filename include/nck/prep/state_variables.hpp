#pragma once
// Kernel state variables the decoder reads (nc::KernelStateReader): the
// tool, rotation, zero offset, measuring offset and position in force after
// every block planned so far, which is what the reading block sees.
#include <optional>
#include <string_view>

#include "nck/config/machine.hpp"
#include "nck/prep/channel_frames.hpp"

namespace nck::prep {

// V.G.WZ_AKT.*, V.G.ROT_*, V.G.NP_AKT.V.<axis>, V.A.ABS.<axis>, V.A.MEIN.<axis>;
// pcs: the planned program position; plane: the working plane in force
// (for the rotation's centre).
std::optional<double> read_state_variable(std::string_view key, const ChannelFrames& frames,
                                          const config::ChannelConfig& channel, const motion::AxisVector& pcs,
                                          std::size_t n_axes, Plane plane);

}  // namespace nck::prep
