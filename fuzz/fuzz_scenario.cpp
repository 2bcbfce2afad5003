// libFuzzer target: any bytes as a --plc scenario file, the whole path of
// `nck run --plc`: parsed, then its spindle and axis names resolved against
// the milling example's machine (loaded once).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "mill_machine.hpp"
#include "nck/plc/hli.hpp"
#include "nck/sim/scenario.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  nck::Diagnostics diags;
  nck::sim::Scenario sc =
      nck::sim::parse_scenario(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.plc", diags);
  if (const nck::config::Machine* m = nck::fuzz::mill_machine())
    nck::sim::resolve_spindles(sc, *m, nck::plc::build_spindle_map(*m), diags);
  return 0;
}
