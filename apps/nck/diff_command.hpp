#pragma once
// `nck diff A.json B.json`: two final states (nck run --final) compared —
// cycle time, time by cause per cause, tool, subroutine and block.
// `nck diff --run MACHINE_A PROG_A MACHINE_B PROG_B`: runs both in this
// process first and also compares their paths; `--report FILE` writes run
// A's report with run B as a ghost beside it (docs/cli.md).
#include <cstddef>
#include <string>
#include <vector>

namespace nck::app {

struct DiffOptions {
  std::vector<std::string> inputs;  // A.json B.json, or with run: MACHINE_A PROG_A MACHINE_B PROG_B
  bool run = false;
  bool json = false;        // the comparison as JSON on stdout
  std::string report;       // with run: run A's report, run B its ghost
  std::string plc_a, plc_b; // with run: each run's --plc scenario
  std::size_t rows = 10;    // rows per table on stdout
  double max_time_s = 86400;
};

// Exit codes: 0 compared, 1 compared but a run ended with an error or a
// limit, 2 bad usage or an input that is no final state (ID 940100-940103).
int diff_command(const DiffOptions& opt);

}  // namespace nck::app
