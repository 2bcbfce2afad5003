// The refusals by name (isg_refusals.hpp): ISG functions nck does not have
// and ISO/Fanuc words, each with what the message tells the programmer.
#include "isg_refusals.hpp"

#include <array>
#include <fmt/format.h>

#include "nck/nc/decoder.hpp"

namespace nck::nc {
namespace detail {
namespace {

// ISG G functions nck does not have: tangential TRC and its selection
// modes, acceleration/deceleration, TRC feeds, corner deceleration,
// mirroring (G20..G23), polynomial contouring, contour rotation, software
// limits, splines, arcs in space ...
constexpr int kIsgGCodes[] = {5,  8,   9,   10,  11,  12,  13,  20,  21,  22,  23,  66,  68,  69, 98,
                              99, 138, 139, 150, 151, 163, 164, 165, 236, 237, 238, 239, 303};
// ... and the implicit cycle calls.
constexpr std::pair<int, int> kIsgGRanges[] = {{80, 89}, {800, 839}};

// ISG # functions nck does not have, by their keywords; "#MC_..." by prefix.
constexpr std::array<std::string_view, 2> kIsgHashPhrases[] = {
    {"RT", "CYCLE"}, {"WAIT", "SYN"},  {"SIGNAL", "SYN"}, {"HSC", ""},     {"TRAFO", ""},   {"CHANNEL", "INIT"},
    {"FILE", "NAME"}, {"RETAIN", "CYCLE"}, {"TURN", ""},  {"TOOL", "ORI"}, {"BCS", ""},
    {"OTC", ""}};
constexpr std::string_view kMotionCommandPrefix = "MC_";
// ISG expression functions nck does not have.
constexpr std::string_view kIsgExpressionFunctions[] = {"IS_STRING"};

struct IsoRemedy {
  int code;
  std::string_view text;
};
constexpr IsoRemedy kIsoGRemedies[] = {
    {20, "G20 is mirroring in ISG, not inch input as in ISO/Fanuc: for inches write G70"},
    {21, "G21 is mirroring in ISG, not metric input as in ISO/Fanuc: for millimetres write G71"},
    {28, "G28 (the ISO/Fanuc return to the reference point) is not ISG: home the axes with G74"},
    {43, "G43 H.. (the ISO/Fanuc tool length compensation) is not ISG: select the tool's offsets with D<n>; "
         "H is an H function output to the PLC"},
};

std::string phrase_name(const std::array<std::string_view, 2>& p) {
  return p[1].empty() ? fmt::format("#{}", p[0]) : fmt::format("#{} {}", p[0], p[1]);
}

}  // namespace

bool isg_g_function(int code) {
  for (int c : kIsgGCodes)
    if (c == code) return true;
  for (auto [lo, hi] : kIsgGRanges)
    if (code >= lo && code <= hi) return true;
  return false;
}

bool isg_expression_function(std::string_view name_upper) {
  for (std::string_view f : kIsgExpressionFunctions)
    if (f == name_upper) return true;
  return false;
}

std::string unsupported_hash(Cursor c) {
  c.skip_spaces();
  if (c.match_prefix(kMotionCommandPrefix)) {
    c.pos -= kMotionCommandPrefix.size();
    return "#" + to_upper(c.read_ident());
  }
  for (const auto& p : kIsgHashPhrases) {
    Cursor k = c;
    if (!k.match_keyword(p[0])) continue;
    k.skip_spaces();
    if (!p[1].empty() && !k.match_keyword(p[1])) continue;
    return phrase_name(p);
  }
  return "";
}

std::optional<std::string_view> iso_g_remedy(int code) {
  for (const IsoRemedy& r : kIsoGRemedies)
    if (r.code == code) return r.text;
  return std::nullopt;
}

std::string iso_program_number(Cursor c) {
  const std::size_t from = c.pos++;  // the O
  while (is_digit(c.peek())) ++c.pos;
  return fmt::format("{} is an ISO/Fanuc program number, not ISG: name the program with a line %name before "
                     "its first block (or leave the number out)",
                     c.s.substr(from, c.pos - from));
}

}  // namespace detail

std::vector<std::string> refused_isg_functions() {
  std::vector<std::string> out;
  for (int c : detail::kIsgGCodes) out.push_back(fmt::format("G{}", c));
  for (auto [lo, hi] : detail::kIsgGRanges) out.push_back(fmt::format("G{} … G{}", lo, hi));
  for (const auto& p : detail::kIsgHashPhrases) out.push_back(detail::phrase_name(p));
  out.push_back(fmt::format("#{}…", detail::kMotionCommandPrefix));
  for (std::string_view f : detail::kIsgExpressionFunctions) out.emplace_back(f);
  return out;
}

}  // namespace nck::nc
