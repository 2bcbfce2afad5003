// libFuzzer target: any bytes as a --plc scenario file.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "nck/plc/scenario.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  nck::Diagnostics diags;
  (void)nck::plc::parse_scenario(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.plc", diags);
  return 0;
}
