#pragma once
// Texts and values that events refer to by index: prepared while planning
// (setup side, may allocate) so the cyclic path only copies an index.
#include <string>
#include <utility>
#include <vector>

#include "nck/kernel/affine_map.hpp"

namespace nck::prep {

struct OffsetPayload {
  std::string kind;                                   // "zero", "g92", "cs" ...
  std::vector<std::pair<std::string, double>> values;  // per axis (and angles)
};

// A coupling group as events and --final name it: configured designations.
struct LinkPayload {
  int group = 0;
  std::vector<std::pair<std::string, std::string>> pairs;  // slave, master
};

struct PlanStore {
  std::vector<std::string> messages;
  std::vector<OffsetPayload> offsets;
  std::vector<LinkPayload> links;
  // Program -> machine maps of executed blocks (block events' message_index),
  // recorded only for a report (PrepOptions::record_frames).
  std::vector<kernel::AffineMap> frames;

  std::uint32_t add_message(std::string m) {
    messages.push_back(std::move(m));
    return static_cast<std::uint32_t>(messages.size() - 1);
  }
  std::uint32_t add_offset(OffsetPayload p) {
    offsets.push_back(std::move(p));
    return static_cast<std::uint32_t>(offsets.size() - 1);
  }
  std::uint32_t add_frame(const kernel::AffineMap& m) {
    frames.push_back(m);
    return static_cast<std::uint32_t>(frames.size() - 1);
  }
  std::uint32_t add_link(LinkPayload p) {
    links.push_back(std::move(p));
    return static_cast<std::uint32_t>(links.size() - 1);
  }
};

}  // namespace nck::prep
