#include <gtest/gtest.h>

#include "cli_helpers.hpp"
#include "nck/commands.hpp"

namespace nck::app {
namespace {

using namespace testing;

TEST(CheckCommand, ExamplesAreClean) {
  for (const char* m : {"mill", "lathe", "two-channel"}) {
    CliResult r = run_nck("check " + root() + "/examples/" + m);
    EXPECT_EQ(r.exit_code, 0) << m << "\n" << r.output;
  }
}

TEST(CheckCommand, MissingFolderIsAnError) {
  CliResult r = run_nck("check /nonexistent/machine");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("910001"), std::string::npos) << r.output;
}

TEST(ParseCommand, GarbageExitsNonZeroWithADiagnostic) {
  const auto dir = temp_dir("garbage");
  const auto p = dir / "garbage.nc";
  {
    std::ofstream f(p, std::ios::binary);
    for (int i = 0; i < 4096; ++i) f.put(static_cast<char>((i * 7919) % 256));
  }
  CliResult r = run_nck("parse " + p.string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("garbage.nc:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("error"), std::string::npos);
}

TEST(ParseCommand, JsonPrintsOneObjectPerBlock) {
  CliResult r = run_nck("parse --json --machine " + root() + "/examples/lathe " + root() + "/examples/lathe/turn.nc");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  std::size_t objects = 0;
  for (const std::string& line : split(r.output, '\n'))
    if (!line.empty() && line[0] == '{') {
      EXPECT_TRUE(nlohmann::json::accept(line)) << line;
      ++objects;
    }
  EXPECT_EQ(objects, 12u);
}

TEST(Docs, ErrorsMarkdownIsUpToDate) {
  EXPECT_EQ(read_file(root() + "/docs/errors.md"), errors_markdown())
      << "regenerate with: nck errors > docs/errors.md";
}

TEST(Docs, ParametersMarkdownIsUpToDate) {
  CliResult r = run_nck("params");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(read_file(root() + "/docs/parameters.md"), r.output)
      << "regenerate with: nck params > docs/parameters.md";
}

}  // namespace
}  // namespace nck::app
