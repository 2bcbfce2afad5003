#pragma once
// What events refer to by index, looked up outside the real-time path by
// the writers that name it (events, state document, report): the programs'
// file names, the spindles' designations, and the plan store's texts,
// payloads and block maps. A dry run has them (sim::DryRun), and so has
// nck-hal, whose kernel runs in another process (apps/hal/hal_records.hpp).
#include <cstdint>
#include <string>

#include "nck/config/machine.hpp"
#include "nck/nc/decoder.hpp"
#include "nck/prep/plan_store.hpp"

namespace nck::prep {

class RunRecords {
 public:
  virtual ~RunRecords() = default;

  // The machine the run was made with.
  virtual const config::Machine& config() const = 0;
  // Channel ch's decoder (its files' names); nullptr without one.
  virtual const nc::Decoder* decoder(std::size_t ch) const = 0;
  // A spindle's designation by its machine index; nullptr: no such spindle.
  virtual const std::string* spindle_name(std::size_t index) const = 0;

  // From the plan store (empty, or nullptr, for an index it does not hold).
  const std::string& message(std::uint32_t index) const;
  const OffsetPayload& offset(std::uint32_t index) const;
  const LinkPayload& link(std::uint32_t index) const;
  // A block event's program -> machine map (record_frames; nullptr: none).
  const kernel::AffineMap* frame(std::uint32_t index) const;
  // The modal state recorded with that map (record_modal; nullptr: none).
  const nc::ModalState* modal(std::uint32_t index) const;

 protected:
  virtual const PlanStore& store() const = 0;
};

}  // namespace nck::prep
