#pragma once
// The one place where preparation turns a diagnostic into the error command
// the channel raises: every unit reports a failure as a Diagnostic
// (std::expected<T, Diagnostic>), the channel's preparation makes it a command.
#include <cstdint>

#include "nck/core/diagnostic.hpp"
#include "nck/prep/kernel_vocabulary.hpp"
#include "nck/prep/plan_store.hpp"

namespace nck::prep {

// d's ID and message, at d's line in file `file_id` (the decoder's number).
PlannedCommand error_command(const Diagnostic& d, std::uint16_t file_id, PlanStore& store);

}  // namespace nck::prep
