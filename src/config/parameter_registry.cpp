// Lookups over the parameter table: by key, by ID, nearest key and symbolic
// constants (the accepted other spellings: key_aliases.cpp).
#include <algorithm>
#include <cctype>
#include <vector>

#include "nck/core/edit_distance.hpp"
#include "nck/config/machine.hpp"
#include "registry_internal.hpp"

namespace nck::config {
namespace {

struct Symbol {
  std::string_view name;
  std::uint32_t value;
};

constexpr Symbol kSyncSymbols[] = {
    {"NO_SYNCH", sync::NO_SYNCH}, {"MOS", sync::MOS},           {"MVS_SVS", sync::MVS_SVS},
    {"MVS_SNS", sync::MVS_SNS},   {"MNS_SNS", sync::MNS_SNS},   {"MNE_SNS", sync::MNE_SNS},
    {"MVS_SLM", sync::MVS_SLM},   {"MVS_SLP", sync::MVS_SLP},   {"PLC_INFO", sync::PLC_INFO},
    {"MOS_TS", sync::MOS_TS},     {"MEP_MOS", sync::MEP_MOS},   {"MET_MOS", sync::MET_MOS},
    {"BWD_SYNCH", sync::BWD_SYNCH}, {"FWD_SYNCH", sync::FWD_SYNCH}, {"MEP_SVS", sync::MEP_SVS},
    {"MET_SVS", sync::MET_SVS},   {"FAW_SYNCH", sync::FAW_SYNCH}, {"NOT_VALID", sync::NOT_VALID},
};
constexpr Symbol kAchstypSymbols[] = {
    {"ACHSTYP_TRANSLATOR", 1}, {"ACHSTYP_ROTATOR", 2}, {"ACHSTYP_SPINDEL", 4}};
constexpr Symbol kFctSymbols[] = {
    {"FCT_DEFAULT", decoder_fct::FCT_DEFAULT},
    {"FCT_NO_DISPLAY", decoder_fct::FCT_NO_DISPLAY},
    {"FCT_USE_CACHED_FILES", decoder_fct::FCT_USE_CACHED_FILES},
    {"FCT_VOL_COMP_COMPUTATION", decoder_fct::FCT_VOL_COMP_COMPUTATION},
    {"FCT_3D_DIST_CTRL", decoder_fct::FCT_3D_DIST_CTRL},
    {"-", 0},
};

bool iequal(std::string_view a, std::string_view b) {
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) ==
                  std::tolower(static_cast<unsigned char>(y));
         });
}

const std::vector<ParamInfo>& table() {
  static const std::vector<ParamInfo> all = [] {
    std::vector<ParamInfo> v;
    for (auto part : {detail::startup_channel_table(), detail::axis_table(),
                      detail::tool_zero_clamp_sim_table()})
      v.insert(v.end(), part.begin(), part.end());
    return v;
  }();
  return all;
}

}  // namespace

std::span<const ParamInfo> all_parameters() { return table(); }

const ParamInfo* find_parameter(ListKind list, std::string_view pattern) {
  for (const auto& p : table())
    if (p.list == list && p.key == pattern) return &p;
  return nullptr;
}

const ParamInfo* find_parameter_by_id(ListKind list, std::string_view id) {
  for (const auto& p : table())
    if (p.list == list && iequal(p.id, id)) return &p;
  return nullptr;
}

std::string_view nearest_key(ListKind list, std::string_view pattern) {
  std::string_view best;
  std::size_t best_d = static_cast<std::size_t>(-1);
  for (const auto& p : table()) {
    if (p.list != list) continue;
    std::size_t d = edit_distance(pattern, p.key, best_d);
    if (d < best_d) best_d = d, best = p.key;
  }
  return best;
}

std::string_view list_name(ListKind list) {
  switch (list) {
    case ListKind::startup: return "startup";
    case ListKind::channel: return "channel";
    case ListKind::axis: return "axis";
    case ListKind::tool: return "tool";
    case ListKind::zero: return "zero";
    case ListKind::clamp: return "clamp";
    case ListKind::sim: return "sim";
  }
  return "?";
}

std::optional<std::uint32_t> symbol_value(ParamType type, std::string_view name) {
  std::span<const Symbol> set;
  if (type == ParamType::sync) set = kSyncSymbols;
  else if (type == ParamType::achstyp) set = kAchstypSymbols;
  else if (type == ParamType::decoder_fct) set = kFctSymbols;
  for (const auto& s : set)
    if (iequal(s.name, name)) return s.value;
  return std::nullopt;
}

namespace detail {

KeyParts split_key(std::string_view key) {
  KeyParts out;
  out.pattern.reserve(key.size());
  for (std::size_t i = 0; i < key.size(); ++i) {
    char c = key[i];
    if (c != '[') {
      out.pattern.push_back(c);
      continue;
    }
    std::size_t close = key.find(']', i);
    if (close == std::string_view::npos || close == i + 1 || close - i > 10 || out.index_count == 3) {
      out.ok = false;
      return out;
    }
    std::uint64_t v = 0;
    for (std::size_t j = i + 1; j < close; ++j) {
      if (key[j] < '0' || key[j] > '9') {
        out.ok = false;
        return out;
      }
      v = v * 10 + static_cast<std::uint64_t>(key[j] - '0');
    }
    out.index[out.index_count++] = static_cast<std::uint32_t>(std::min<std::uint64_t>(v, 0xffffffffu));
    out.pattern += "[]";
    i = close;
  }
  return out;
}

std::string join_key(std::string_view pattern, const std::array<std::uint32_t, 3>& index) {
  std::string out;
  std::size_t n = 0;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] == '[' && i + 1 < pattern.size() && pattern[i + 1] == ']') {
      out += '[' + std::to_string(n < 3 ? index[n] : 0) + ']';
      ++n;
      ++i;
    } else {
      out.push_back(pattern[i]);
    }
  }
  return out;
}

}  // namespace detail
}  // namespace nck::config
