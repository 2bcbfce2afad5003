#pragma once
#include "nck/run/run_options.hpp"

namespace nck::app {

// Exit codes (README): 0 program end reached, 1 aborted by an NC error or a
// limit, 2 bad usage, machine data or an output that cannot be written,
// 130/143 interrupted by SIGINT/SIGTERM (every output file complete).
int run_simulation(const RunOptions& opt);

}  // namespace nck::app
