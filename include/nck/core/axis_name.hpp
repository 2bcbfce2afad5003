#pragma once
// The rule for path-axis names (P-CHAN-00006, P-CHAN-00010, #CAX): the first
// letter A, B, C, U, V, W, X, Y, Z or Q, then letters, digits and _ only
// (TF5200's own example is X_ACHSE1); the first letter upper case, as the
// lists have always been read. Shared by the channel list checks and
// the decoder, so a name the list refuses is refused in a program too.
#include <string_view>

namespace nck {

inline constexpr std::string_view kPathAxisLetters = "ABCUVWXYZQ";

inline bool valid_path_axis_name(std::string_view name) {
  if (name.empty() || kPathAxisLetters.find(name.front()) == std::string_view::npos) return false;
  for (char c : name.substr(1))
    if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_')) return false;
  return true;
}

// P-CHAN-00253's alias names A1 .. A32 (P-AXIS-00297).
inline bool is_alias_axis_name(std::string_view n) {
  if (n.size() < 2 || n.size() > 3 || n[0] != 'A' || n[1] < '1' || n[1] > '9') return false;
  if (n.size() == 2) return true;
  return n[2] >= '0' && n[2] <= '9' && (n[1] - '0') * 10 + (n[2] - '0') <= 32;
}

}  // namespace nck
