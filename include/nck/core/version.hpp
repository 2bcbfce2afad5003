#pragma once
// The version of this build: CMake's project(VERSION) is the one place it
// is written (cmake/version.cpp.in); `nck --version`, nck.__version__,
// GET /api/v1/version, the report and the final state read it here.
#include <string_view>

namespace nck {

// "0.3.0"
std::string_view version() noexcept;
// The commit the build was configured from ("unknown" outside a git clone).
std::string_view git_hash() noexcept;

}  // namespace nck
