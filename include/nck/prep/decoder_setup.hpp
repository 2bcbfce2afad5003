#pragma once
#include "nck/config/machine.hpp"
#include "nck/nc/decoder.hpp"

#include <string>
#include <utility>
#include <vector>

namespace nck::prep {
// The decoder configuration of channel ch (0-based): axis and spindle names,
// main spindle, file cache. setup
nc::DecoderConfig decoder_config(const config::Machine& m, std::size_t ch);

// The kernel variables a program of channel ch can read from its start:
// the zero-offset table (V.G.NP[i].V.<axis>) and the clamp position
// (V.G.AKT_PLATZ). setup
std::vector<std::pair<std::string, double>> initial_variables(const config::Machine& m, std::size_t ch,
                                                              std::uint32_t clamp_index);

// The kernel spindle index of each of channel ch's spindles (the kernel
// numbers spindles in the HLI map's order), as the planner takes them. setup
std::vector<std::int8_t> kernel_spindles(const config::Machine& m, std::size_t ch);
}  // namespace nck::prep
