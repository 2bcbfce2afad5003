#pragma once
// Tool radius compensation (G40 / G41 / G42) as it travels: the decoder's
// modal word, what preparation attaches to the block that changes it, and the
// `trc` event the channel reports when that block starts. The contour offset
// itself is computed in preparation (nck/prep/radius_comp.hpp).
#include <cstdint>

#include "nck/core/event_head.hpp"
#include "nck/core/shown_number.hpp"

namespace nck::trc {

enum class RadiusComp : std::uint8_t { g40 = 40, g41 = 41, g42 = 42 };

// The compensation changed with the block: the mode, the D in force and its tool radius.
struct TrcChange {
  RadiusComp mode = RadiusComp::g40;
  std::int32_t d = 0;
  double radius_mm = 0;
};

template <class Json, class Names>
void write_json(Json& j, const TrcChange& e, const EventHead& h, const Names& names) {
  j["state"] = e.mode == RadiusComp::g41 ? "G41" : e.mode == RadiusComp::g42 ? "G42" : "G40";
  j["d"] = e.d;
  j["radius_mm"] = written(e.radius_mm);
  j["line"] = h.at.line;
  j["file"] = names.file(h.channel_index(), h.at.file_id);
}

}  // namespace nck::trc
