#pragma once
// Preparation speaks the kernel's language: it plans the commands and
// spindle actions the channel executes. These names are used unqualified in
// the prep layer.
#include "nck/kernel/spindle_action.hpp"
#include "nck/prep/planned_command.hpp"

namespace nck::prep {

using plc::TechKind;

using kernel::FeedLinkKind;
using kernel::kNoMessage;
using kernel::SpindleOp;
using kernel::SpindleWait;
using kernel::SyncPoint;
using kernel::sync_point;

}  // namespace nck::prep
