#pragma once
// Private to the config layer: the two halves of the parameter table.
#include <limits>
#include <span>

#include "nck/config/parameter_registry.hpp"

namespace nck::config::detail {

inline constexpr double kU16 = 65535.0;
inline constexpr double kU32 = 4294967295.0;
inline constexpr double kS32 = 2147483647.0;
inline constexpr double kS32Min = -2147483648.0;
inline constexpr double kInf = std::numeric_limits<double>::infinity();

std::span<const ParamInfo> startup_channel_table();
std::span<const ParamInfo> axis_table();
std::span<const ParamInfo> tool_zero_clamp_sim_table();

}  // namespace nck::config::detail

#include <cstdint>
#include <string>
#include <string_view>

namespace nck::config::detail {

// A concrete key split into its pattern ("np_grp[].achse[].versch") and indices.
struct KeyParts {
  std::string pattern;
  std::array<std::uint32_t, 3> index{};
  std::uint8_t index_count = 0;
  bool ok = true;  // false: malformed brackets or more than three indices
};
KeyParts split_key(std::string_view key);
// The pattern with the indices put back: ("a[].b[]", {1,2}) -> "a[1].b[2]".
std::string join_key(std::string_view pattern, const std::array<std::uint32_t, 3>& index);

}  // namespace nck::config::detail
