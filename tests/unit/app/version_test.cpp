// One version, written once (issue 47, item 2): CMake's project(VERSION)
// is what `nck --version` prints and what the final state and the report
// carry.
#include <gtest/gtest.h>

#include <regex>

#include "cli_helpers.hpp"
#include "nck/core/version.hpp"

namespace nck::app::testing {
namespace {

std::string cmake_version() {
  std::smatch m;
  const std::string text = read_file(std::filesystem::path(root()) / "CMakeLists.txt");
  return std::regex_search(text, m, std::regex(R"(project\(nck VERSION ([0-9.]+))")) ? m[1].str() : "";
}

TEST(Version, TheCommandLineSaysWhatCMakeSays) {
  ASSERT_FALSE(cmake_version().empty());
  EXPECT_EQ(nck::version(), cmake_version());
  const CliResult r = run_nck("--version");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.output.find("nck " + cmake_version() + " (git "), std::string::npos) << r.output;
}

TEST(Version, TheFinalStateAndTheReportNameTheBuild) {
  const auto dir = temp_dir("version_final");
  const CliResult r = run_nck("run " + root() + "/examples/mill " + root() + "/examples/mill/contour.nc --final " +
                              (dir / "f.json").string() + " --report " + (dir / "r.html").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(nlohmann::json::parse(read_file(dir / "f.json"))["nck"], cmake_version());
  EXPECT_NE(read_file(dir / "r.html").find("\"nck\":\"" + cmake_version() + "\""), std::string::npos);
}

}  // namespace
}  // namespace nck::app::testing
