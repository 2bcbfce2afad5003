#include "nck/plc/function_text.hpp"

#include <fmt/format.h>

#include <utility>

#include "nck/config/machine.hpp"

namespace nck::plc {

std::string function_name(TechKind fn, std::int32_t number) {
  switch (fn) {
    case TechKind::m: return fmt::format("M{}", number);
    case TechKind::h: return fmt::format("H{}", number);
    case TechKind::t: return fmt::format("T{}", number);
    case TechKind::s: return "S";
    case TechKind::none: break;
  }
  return "";
}

std::string sync_name(std::uint32_t bits) {
  namespace s = config::sync;
  static constexpr std::pair<std::uint32_t, const char*> kNames[] = {
      {s::MOS, "MOS"},         {s::MVS_SVS, "MVS_SVS"}, {s::MVS_SNS, "MVS_SNS"},
      {s::MNS_SNS, "MNS_SNS"}, {s::MNE_SNS, "MNE_SNS"}, {s::MVS_SLM, "MVS_SLM"},
      {s::MVS_SLP, "MVS_SLP"}, {s::PLC_INFO, "PLC_INFO"}};
  std::string out;
  for (auto [bit, name] : kNames) {
    if (!(bits & bit)) continue;
    if (!out.empty()) out += '|';
    out += name;
  }
  return out.empty() ? "NO_SYNCH" : out;
}

}  // namespace nck::plc
