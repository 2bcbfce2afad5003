#include "nck/prep/run_records.hpp"

namespace nck::prep {

const std::string& RunRecords::message(std::uint32_t index) const {
  static const std::string none;
  return index < store().messages.size() ? store().messages[index] : none;
}

const OffsetPayload& RunRecords::offset(std::uint32_t index) const {
  static const OffsetPayload none;
  return index < store().offsets.size() ? store().offsets[index] : none;
}

const LinkPayload& RunRecords::link(std::uint32_t index) const {
  static const LinkPayload none;
  return index < store().links.size() ? store().links[index] : none;
}

const kernel::AffineMap* RunRecords::frame(std::uint32_t index) const {
  return index < store().frames.size() ? &store().frames[index] : nullptr;
}

const nc::ModalState* RunRecords::modal(std::uint32_t index) const {
  return index < store().frame_modals.size() ? &store().frame_modals[index] : nullptr;
}

}  // namespace nck::prep
