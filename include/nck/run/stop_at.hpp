#pragma once
// nck run --stop-at (docs/cli.md): the run ends where a block ends — the block
// numbered N<n>, the block on line:<L> of the main program, the K-th block
// (block:<K>), or the block that runs when the first event of a kind comes
// (event:<kind>, e.g. event:wait). The kernel holds at that block's end
// (where the path cannot stop there within a_max, at the first block end
// after it where it can); the run then ends with reason "stop_at".
#include <optional>
#include <string>
#include <string_view>

#include "nck/kernel/tick_io.hpp"
#include "nck/sim/dry_run.hpp"

namespace nck::app {

struct StopAt {
  kernel::StopMark mark{};                 // N / line / block marks the kernel matches itself
  std::optional<kernel::EventKind> event;  // event:<kind>: the caller marks the block that runs
};

// A mark's whole number: all of s, >= lowest (also --start-at's marks).
std::optional<std::int64_t> whole_number(std::string_view s, std::int64_t lowest);

// The --stop-at text, or nullopt when it is none of the forms above.
std::optional<StopAt> parse_stop_at(std::string_view text);

class StopAtWatch {
 public:
  // setup: hands the kernel's marks to every channel.
  StopAtWatch(const StopAt& stop_at, sim::DryRun& run);
  // After each cycle: marks the running block of a channel at the first
  // event of the kind asked for; true once a channel holds at its mark.
  bool reached(const kernel::TickOutput& out);

 private:
  StopAt stop_at_;
  sim::DryRun* run_;
};

}  // namespace nck::app
