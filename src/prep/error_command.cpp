#include "nck/prep/error_command.hpp"

namespace nck::prep {

PlannedCommand error_command(const Diagnostic& d, std::uint16_t file_id, PlanStore& store) {
  PlannedCommand c;
  c.kind = CommandKind::error;
  c.step = kernel::Error{d.id, store.add_message(d.message)};
  c.head.file_id = file_id;
  c.head.line = d.loc.line;
  c.head.emit_block_event = false;
  return c;
}

}  // namespace nck::prep
