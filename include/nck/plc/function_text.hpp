#pragma once
// How a technology function and its synchronisation read in outputs:
// "M3", "T5", "S"; "MVS_SVS|PLC_INFO", "NO_SYNCH".
#include <cstdint>
#include <string>

#include "nck/plc/hli.hpp"

namespace nck::plc {

std::string function_name(TechKind fn, std::int32_t number);
std::string sync_name(std::uint32_t sync_bits);

}  // namespace nck::plc
