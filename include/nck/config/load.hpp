#pragma once
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "nck/config/machine.hpp"
#include "nck/config/parameter_registry.hpp"
#include "nck/core/diagnostic.hpp"

namespace nck::config {

struct LoadResult {
  std::optional<Machine> machine;  // set unless a fatal error stopped loading
  Diagnostics diagnostics;         // every warning and error, with file:line
  bool ok() const { return machine.has_value() && !diagnostics.has_errors(); }
};

struct LoadOptions {
  KeyPolicy keys = KeyPolicy::lenient;  // --strict: every unknown key is an error (910032)
  // `nck check`: also warn of what the machine cannot do whatever a program
  // asks, e.g. a spindle that cannot position or home (70252). The run
  // reports such a thing when a program asks for it.
  bool capability_warnings = false;
  // Where the lists' text comes from: empty reads the files; set, the
  // loader asks it for each list by its path (nullopt: not there) and
  // touches no file. The HAL module loads a machine that nck-hal packed
  // into shared memory this way (docs/hal.md, docs/decisions.md).
  std::function<std::optional<std::string>(const std::filesystem::path&)> read_text = nullptr;
};

// Reads startup.lis in `folder` and every list it names, converts units,
// runs all plausibility checks (docs/errors.md). Never throws on bad input.
LoadResult load_machine(const std::filesystem::path& folder, const LoadOptions& options = {});

}  // namespace nck::config
