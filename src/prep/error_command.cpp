#include "nck/prep/error_command.hpp"

namespace nck::prep {

PlannedCommand error_command(const Diagnostic& d, std::uint16_t file_id, PlanStore& store) {
  PlannedCommand c;
  c.kind = CommandKind::error;
  c.error_id = d.id;
  c.file_id = file_id;
  c.line = d.loc.line;
  c.emit_block_event = false;
  c.message_index = store.add_message(d.message);
  return c;
}

}  // namespace nck::prep
