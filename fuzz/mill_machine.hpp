#pragma once
// The milling example's machine, loaded once: the machine the fuzz targets
// that resolve names (scenario, API messages) check against.
#include "nck/config/load.hpp"

namespace nck::fuzz {

inline const config::Machine* mill_machine() {
  static const config::LoadResult loaded = config::load_machine(NCK_SOURCE_DIR "/examples/mill");
  return loaded.machine ? &*loaded.machine : nullptr;
}

}  // namespace nck::fuzz
