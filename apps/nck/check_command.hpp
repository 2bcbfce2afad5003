#pragma once
// `nck check MACHINE [PROGRAM...]`: the machine data's plausibility and, with
// programs, the pre-flight check of each channel's program (prep/program_check.hpp).
#include <cstdint>
#include <string>
#include <vector>

namespace nck::app {

struct CheckOptions {
  std::string machine;
  std::vector<std::string> programs;  // program i belongs to channel i+1
  bool json = false;                  // the diagnostics as a JSON array on stdout
  std::vector<std::string> cycles;    // --cycles DIR: searched after startup.lis cycle_path[i]
  std::uint32_t clamp_index = 0;      // clamp-offset group (pzv_grp) at program start
  double max_wall_s = 0;              // wall-clock seconds (0 = no limit)
  bool strict_keys = false;           // --strict: every unknown list key is an error (910032)
};

// Exit codes: 0 no errors (warnings allowed), 1 errors found (or --max-wall
// reached), 2 bad usage or machine data that cannot be used with programs,
// 130/143 stopped by SIGINT/SIGTERM.
int check_command(const CheckOptions& opt);

}  // namespace nck::app
