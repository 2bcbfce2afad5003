#pragma once
// Preparation speaks the kernel's language: it produces the commands and
// spindle actions the channel executes. These names are used unqualified in
// the prep layer.
#include "nck/kernel/command.hpp"
#include "nck/kernel/spindle_action.hpp"

namespace nck::prep {

using kernel::Command;
using kernel::CommandKind;
using kernel::EndReason;
using kernel::FeedLink;
using kernel::FeedLinkKind;
using kernel::FunctionKind;
using kernel::kNoMessage;
using kernel::Output;
using kernel::SpindleAction;
using kernel::SpindleOp;
using kernel::SpindleWait;
using kernel::SyncPoint;
using kernel::sync_point;

}  // namespace nck::prep
