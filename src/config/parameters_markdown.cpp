// Renders the parameter registry as docs/parameters.md.
#include <cmath>
#include <fmt/format.h>

#include "registry_internal.hpp"

namespace nck::config {
namespace {

std::string number(double v) {
  if (std::isinf(v)) return v < 0 ? "−∞" : "∞";
  if (v == std::floor(v) && std::fabs(v) < 1e15) return fmt::format("{}", static_cast<long long>(v));
  return fmt::format("{}", v);
}

std::string range_text(const ParamInfo& p) {
  switch (p.type) {
    case ParamType::boolean: return "0/1";
    case ParamType::string: return fmt::format("name, ≤ {} chars", number(p.max));
    case ParamType::path: return "file path";
    case ParamType::choice: {
      std::string out;
      for (char c : p.choices) out += (c == ' ') ? std::string(", ") : std::string(1, c);
      return out;
    }
    case ParamType::sync: return "sync symbols (NO_SYNCH, MOS, MVS_SVS, ... PLC_INFO) or hex, OR-ed";
    case ParamType::achstyp: return "ACHSTYP_TRANSLATOR 1, ACHSTYP_ROTATOR 2, ACHSTYP_SPINDEL 4";
    case ParamType::decoder_fct: return "FCT_* symbols OR-ed, '-' = none";
    default: break;
  }
  if (std::isinf(p.min) && std::isinf(p.max)) return "any";
  if (p.min == 1e-9) return fmt::format("> 0 … {}", number(p.max));
  return fmt::format("{} … {}", number(p.min), number(p.max));
}

std::string index_text(const ParamInfo& p) {
  static constexpr char kLetters[] = {'i', 'j', 'k'};
  std::string out;
  for (std::size_t n = 0; n < p.index_count.size(); ++n)
    if (p.index_count[n] == 1)
      out += fmt::format("{}{} = 0", out.empty() ? "; " : ", ", kLetters[n]);
    else if (p.index_count[n] > 1)
      out += fmt::format("{}{} = 0…{}", out.empty() ? "; " : ", ", kLetters[n], p.index_count[n] - 1);
  return out;
}

std::string default_text(const ParamInfo& p) {
  if (!p.text_default.empty()) return std::string(p.text_default);
  if (p.type == ParamType::integer && p.key == "kenngr.achs_mode") return "0x1";
  return number(p.def);
}

std::string_view list_title(ListKind l) {
  switch (l) {
    case ListKind::startup: return "Startup list (`startup.lis`)";
    case ListKind::channel: return "Channel list (`sda_mds[i]`)";
    case ListKind::axis: return "Axis list (`achs_mds[i]`)";
    case ListKind::tool: return "Tool list (`werkz_data[i]`)";
    case ListKind::zero: return "Zero-offset list (`nullp_data[i]`)";
    case ListKind::clamp: return "Clamp-offset list (`pzv_data[i]`)";
    case ListKind::sim: return "Simulation list (`sim_data`, nck's own)";
  }
  return "";
}

}  // namespace

std::string display_key(std::string_view pattern) {
  static constexpr char kLetters[] = {'i', 'j', 'k'};
  std::string out;
  std::size_t n = 0;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    out.push_back(pattern[i]);
    if (pattern[i] == '[' && i + 1 < pattern.size() && pattern[i + 1] == ']')
      out.push_back(kLetters[n++ % 3]);
  }
  return out;
}

std::string parameters_markdown() {
  std::string out =
      "# Parameters\n\n"
      "Every key `nck` accepts in a list file. Generated from the parameter registry\n"
      "(`src/config/registry_table_*.cpp`, `nck params`); do not edit by hand.\n\n"
      "- Values are converted once at load: internal value = list value × scale\n"
      "  (0.1 µm → mm, 0.0001° → deg, µm/s → mm/s, 0.001°/s → deg/s, µs → s).\n"
      "- Where the list unit depends on the axis type it reads `translatory · rotary/spindle`.\n"
      "- Keys are matched case-insensitively; `i`, `j` are the `[n]` indices.\n"
      "- A misspelt key (within edit distance 2 of a key below or of its seed spelling) is error\n"
      "  910031; any other unknown key is warning 910002 and has no effect (error 910032 under\n"
      "  `--strict`). Wrong types give 910003, values out of range 910004.\n"
      "- Seed spellings accepted with warning 910005 (`nck params` finds a key by them too): " +
      alias_summary() +
      ".\n"
      "  Accepted silently: the `kenngr.*` keys without `kenngr.` (`achs_typ`, `antr_typ` …).\n"
      "- A value written as another parameter's ID (`P-AXIS-00212.0`) takes that parameter's\n"
      "  value from the same list and indices (its default when not given).\n"
      "- \"Accepted, no effect in simulation\": read and range-checked, but what it sets is a\n"
      "  drive or fieldbus matter the simulation does not model.\n";
  for (ListKind l : {ListKind::startup, ListKind::channel, ListKind::axis, ListKind::tool,
                     ListKind::zero, ListKind::clamp, ListKind::sim}) {
    out += fmt::format("\n## {}\n\n", list_title(l));
    out += "| Key | ID | List unit | Internal unit | Range | Default | Meaning |\n";
    out += "|---|---|---|---|---|---|---|\n";
    for (const auto& p : all_parameters()) {
      if (p.list != l) continue;
      out += fmt::format("| `{}` | {} | {} | {} | {}{} | {} | {} |\n", display_key(p.key), p.id,
                         p.list_unit, p.internal_unit, range_text(p), index_text(p),
                         default_text(p), p.meaning);
    }
  }
  return out;
}

}  // namespace nck::config
