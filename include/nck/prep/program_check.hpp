#pragma once
// The pre-flight check of one channel's program (`nck check MACHINE
// PROGRAM...`): the program goes through the same stages as in a run —
// decoder, tool radius compensation, planner, look-ahead window — but no
// kernel runs it, and an error does not end it. Each error and warning is
// recorded with the ID, file and line the run would raise it with, and
// decoding and planning go on with the next block:
//  - the decoder runs in lint mode (DecoderConfig::continue_after_error): a
//    block with an error is dropped whole, nothing of it takes effect;
//  - a block the planner or the compensation rejects becomes no command: the
//    planner's position stays where the last good block left it;
//  - what execution would feed back (G100's measurement, #CAX's spindle
//    position, #GET MANUAL OFFSETS) is taken as "nothing changed": the probe
//    switched at the end of the G100 run, C at 0, no handwheel offsets.
// The spindle speed limits, which the kernel's spindle applies, are followed
// through the planned spindle actions (spindle_limit_check.hpp).
// Only what ends decoding for good ends the check early: a main program that
// cannot be read, an unclosed structure, a nesting or reading limit.
// Setup side: allocates, never throws on bad input.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "nck/config/machine.hpp"
#include "nck/core/diagnostic.hpp"

namespace nck::prep {

class PathPreview;

struct ProgramCheckOptions {
  std::uint32_t clamp_index = 0;  // clamp-offset group at program start (--clamp-index)
  // Set by the caller to stop the check within one block read (SIGINT,
  // SIGTERM, --max-wall). Not owned.
  const std::atomic<bool>* stop = nullptr;
  // Set by the caller: every planned motion goes into it; the check ends
  // when it is full (an operator's preview, not a lint). Not owned.
  PathPreview* preview = nullptr;
};

struct ProgramCheckResult {
  // In the order found; each (ID, file, line) once, however often a loop or
  // a subroutine call meets it again.
  std::vector<Diagnostic> diagnostics;
  std::size_t blocks = 0;  // blocks decoded
  bool stopped = false;    // ProgramCheckOptions::stop ended the check early
};

// Checks channel ch's (0-based) program on machine m.
ProgramCheckResult check_program(const config::Machine& m, std::size_t ch, const std::filesystem::path& program,
                                 const ProgramCheckOptions& options);

}  // namespace nck::prep
