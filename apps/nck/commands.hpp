#pragma once
#include <string>
#include <vector>

namespace nck::app {

struct ParseOptions {
  std::string program;
  bool json = false;
  std::string machine;   // optional: names from this machine
  std::size_t channel = 1;
  std::vector<std::string> cycles;  // --cycles DIR
  double max_wall_s = 0;            // wall-clock seconds (0 = no limit)
};
// nck parse PROGRAM: 0 without errors, 1 with errors or at --max-wall, 2 bad
// machine, 130/143 stopped by SIGINT/SIGTERM.
int parse_program(const ParseOptions& opt);

struct FitOptions {
  std::string type;  // hyperbola | polynomial
  double limit_speed_deg_s = 0;
  double const_accel_deg_s2 = 0;
  std::vector<std::string> points;  // "n,a"
};
// nck fit-curve: prints b1 b2 b3; 0 ok, 2 bad input.
int fit_curve(const FitOptions& opt);

struct InitOptions {
  std::string folder;
  bool lathe = false;  // else the milling machine
};
// nck init DIR: writes a working machine folder (the mill or lathe example's
// lists and one program); 0 ok, 2 when DIR is not new or empty or cannot be written.
int init_machine(const InitOptions& opt);

// docs/parameters.md / docs/errors.md, or only the table rows matching
// `lookup` (case-insensitive; exit 1 when none does).
int print_parameters(const std::string& lookup = "");
int print_errors(const std::string& lookup = "");

}  // namespace nck::app
