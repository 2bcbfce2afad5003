#pragma once
// An offset changed with a block: preparation attaches it to the block's
// command, the channel reports it as an `offset` event when the block
// starts. The offset's kind and values stay in the plan store (PlanStore::
// offsets, text outside the real-time path); the event carries the index.
#include <cstdint>

#include "nck/core/event_head.hpp"
#include "nck/core/shown_number.hpp"

namespace nck::frames {

struct OffsetEvent {
  std::uint32_t index = 0;  // PlanStore::offsets
};

template <class Json, class Names>
void write_json(Json& j, const OffsetEvent& e, const EventHead& h, const Names& names) {
  const auto& offset = names.offset(e.index);
  j["kind"] = offset.kind;
  Json values = Json::object();
  for (const auto& [axis, v] : offset.values) values[axis] = written(v);
  j["values"] = values;
  j["line"] = h.at.line;
}

}  // namespace nck::frames
