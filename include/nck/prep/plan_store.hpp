#pragma once
// Texts and values that events refer to by index: prepared while planning
// (setup side, may allocate) so the cyclic path only copies an index. The
// logs may be read while preparation appends (its own thread: AppendLog).
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "nck/core/append_log.hpp"
#include "nck/core/diagnostic.hpp"
#include "nck/kernel/affine_map.hpp"
#include "nck/nc/modal.hpp"
#include "nck/prep/planned_command.hpp"

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
  AppendLog<std::string> messages;
  AppendLog<OffsetPayload> offsets;
  AppendLog<LinkPayload> links;
  // Program -> machine maps of executed blocks (block events' message_index),
  // recorded only for a report (PrepOptions::record_frames).
  AppendLog<kernel::AffineMap> frames;
  // With PrepOptions::record_modal: the modal state after the block, at the
  // same index as its map (a live kernel's HMI shows it).
  AppendLog<nc::ModalState> frame_modals;

  std::uint32_t add_message(std::string m) { return static_cast<std::uint32_t>(messages.push_back(std::move(m))); }
  std::uint32_t add_offset(OffsetPayload p) { return static_cast<std::uint32_t>(offsets.push_back(std::move(p))); }
  std::uint32_t add_frame(const kernel::AffineMap& m) { return static_cast<std::uint32_t>(frames.push_back(m)); }
  std::uint32_t add_link(LinkPayload p) { return static_cast<std::uint32_t>(links.push_back(std::move(p))); }
};

// Puts warnings into c (raised when it starts). Beyond its capacity the last
// one says how many more there were and which came first.
void add_warnings(PlannedCommand& c, const std::vector<Diagnostic>& warnings, PlanStore& store);

}  // namespace nck::prep
