#pragma once
// The pre-flight check of `nck check` as a library call: the machine data,
// then each channel's program without a kernel (prep/program_check.hpp).
// The command prints the findings, the Python module's nck.check returns
// them: one walk, so both give the same diagnostics.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "nck/core/diagnostic.hpp"

namespace nck::app {

struct PreflightOptions {
  std::string machine;
  std::vector<std::string> programs;  // program i belongs to channel i+1
  std::vector<std::string> cycles;    // --cycles DIR: searched after startup.lis cycle_path[i]
  std::uint32_t clamp_index = 0;      // clamp-offset group (pzv_grp) at program start
  bool strict_keys = false;           // --strict: every unknown list key is an error (910032)
  const std::atomic<bool>* stop = nullptr;  // set: the program's check stops within a block (not owned)
};

// A diagnostic and the channel whose program it belongs to (0: machine data).
struct PreflightFinding {
  Diagnostic d;
  std::size_t channel = 0;
};

// A program checked to its end: what the command's summary line counts.
struct PreflightProgram {
  std::string program;
  std::size_t blocks = 0, errors = 0, warnings = 0;
};

struct Preflight {
  std::vector<PreflightFinding> found;  // the machine data's, then each program's in channel order
  bool machine_loaded = false;          // false: the data cannot be used, no program was checked
  std::size_t machine_errors = 0;
  std::vector<PreflightProgram> programs;
  // A program that is no file, or more programs than channels: none was
  // checked (the command's bad usage, exit 2).
  std::optional<Diagnostic> bad_usage;
  // The stop flag ended a program's check: its findings so far are in
  // `found`, the program is not in `programs`, the later ones not checked.
  bool stopped = false;
  bool has_errors() const;
};

Preflight preflight(const PreflightOptions& opt);

// A finding as `nck check --json` lists it: the diagnostic's one shape
// (output/diagnostic_json.hpp; docs/cli.md).
nlohmann::ordered_json to_json(const PreflightFinding& f);

}  // namespace nck::app
