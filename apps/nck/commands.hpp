#pragma once
#include <string>

namespace nck::app {

// nck check MACHINE: 0 without errors, 1 with errors.
int check_machine(const std::string& folder);

struct ParseOptions {
  std::string program;
  bool json = false;
  std::string machine;   // optional: names from this machine
  std::size_t channel = 1;
};
// nck parse PROGRAM: 0 without errors, 1 with errors, 2 bad machine.
int parse_program(const ParseOptions& opt);

int print_parameters();  // docs/parameters.md
int print_errors();      // docs/errors.md
std::string errors_markdown();

}  // namespace nck::app
