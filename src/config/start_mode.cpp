// P-CHAN-00507 / P-CHAN-00508: decoder functions that act only in one
// program-start mode. `nck run` is the standard start (ISG_STANDARD); a
// block search (SV) needs --start-at, any other mode is chosen with
// --start-mode (docs/cli.md). Only the functions of the run's mode act.
#include <algorithm>
#include <array>
#include <cctype>
#include <utility>

#include "nck/config/machine.hpp"

namespace nck::config {
namespace {

// Each mode with its synonym ("" = none), as P-CHAN-00508 lists them.
constexpr std::array<std::pair<std::string_view, std::string_view>, 9> kModes{{
    {"ISG_STANDARD", ""},
    {"SV", "BLOCK_SEARCH"},
    {"SOLLKON", "CONTOUR_VISU"},
    {"ON_LINE", ""},
    {"SYNCHCK", "SYNTAX_CHECK"},
    {"PROD_TIME", ""},
    {"ONLINE_PROD_TIME", ""},
    {"MACHINE_LOCK", "DRY_RUN"},
    {"SCENE", ""},
}};

}  // namespace

std::string canonical_start_mode(std::string_view name) {
  std::string up(name);
  std::transform(up.begin(), up.end(), up.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  for (const auto& [mode, synonym] : kModes)
    if (up == mode || (!synonym.empty() && up == synonym)) return std::string(mode);
  return {};
}

std::uint32_t ChannelConfig::decoder_functions() const {
  std::uint32_t bits = decoder_function;
  const std::string mode = canonical_start_mode(start_mode);
  for (std::size_t i = 0; i < decoder_fct_enable.size(); ++i)
    if (canonical_start_mode(decoder_fct_condition[i]) == mode) bits |= decoder_fct_enable[i];
  return bits;
}

}  // namespace nck::config
