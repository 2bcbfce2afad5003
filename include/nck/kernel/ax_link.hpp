#pragma once
// Synchronous operation (#SET AX LINK / #ENABLE AX LINK, spindle_link seed,
// FCT-S1 2.8.3): what the kernel needs of a coupling group, as fixed-size data.
// Preparation checks the rules and resolves names; a command enables one
// group or disables several. Spindle pairs: preparation already commands the
// slaves in parallel with their master; the kernel only keeps other
// channels off the linked spindles. Path-axis pairs: the channel moves the
// slave with its master every cycle.
#include <cstdint>

#include <string_view>

#include "nck/core/event_head.hpp"
#include "nck/core/packed_list.hpp"

namespace nck::kernel {

// Documented maxima (docs/decisions.md, "Synchronous operation (AX LINK)"):
// groups 0..kMaxLinkGroupNr, at most kMaxLinkPairs pairs per group
// (P-CHAN-00037/38: paar[0..14]).
inline constexpr std::size_t kMaxLinkPairs = 15;
inline constexpr int kMaxLinkGroupNr = 31;

enum class LinkReason : std::uint8_t { program, abort, program_end, reset };

constexpr const char* link_reason_name(LinkReason r) noexcept {
  switch (r) {
    case LinkReason::program: return "program";
    case LinkReason::abort: return "abort";
    case LinkReason::program_end: return "program_end";
    case LinkReason::reset: return "reset";
  }
  return "program";
}

struct AxLinkPair {
  bool spindle = false;   // mode 1: kernel spindle indices; mode 0: channel axis indices
  std::int8_t slave = -1;
  std::int8_t master = -1;
  bool gantry = false;
  double ratio = 1.0;     // numerator / denominator (scaled or mirrored pairs)
};

struct LinkCommand {
  // enable: `group` with its pairs; `payload` indexes the names for events
  bool enable = false;
  std::int8_t group = -1;
  std::uint32_t payload = 0;
  PackedList<AxLinkPair, kMaxLinkPairs> pairs;
  // disable: bit g = group g off (with the reason "program")
  std::uint32_t disable_mask = 0;
  bool any() const noexcept { return enable || disable_mask != 0; }
};

// A coupling group was enabled or dissolved (a `link` event).
struct LinkEvent {
  std::int8_t group = -1;
  bool on = false;
  LinkReason reason = LinkReason::program;
  std::uint32_t payload = 0;  // PlanStore::links: the pairs' names
};

template <class Json, class Names>
void write_json(Json& j, const LinkEvent& e, const EventHead& h, const Names& names) {
  j["group"] = e.group;
  Json pairs = Json::array();
  for (const auto& [slave, master] : names.link(e.payload).pairs) pairs.push_back(Json::array({slave, master}));
  j["pairs"] = pairs;
  j["on"] = e.on;
  j["reason"] = link_reason_name(e.reason);
  j["line"] = h.at.line;
}

}  // namespace nck::kernel
