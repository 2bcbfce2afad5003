#pragma once
#include "nck/config/machine.hpp"
#include "nck/nc/decoder.hpp"

namespace nck::kernel {
// The decoder configuration of channel ch (0-based): axis and spindle names,
// main spindle, file cache. setup
nc::DecoderConfig decoder_config(const config::Machine& m, std::size_t ch);
}  // namespace nck::kernel
