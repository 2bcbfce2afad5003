// nck init DIR [--mill|--lathe] writes a machine folder that checks clean and
// runs its program, and never overwrites a folder that has something in it.
#include <gtest/gtest.h>

#include "cli_helpers.hpp"

namespace nck::app::testing {
namespace {

TEST(Init, WritesAMachineFolderThatChecksAndRuns) {
  for (const std::string kind : {"mill", "lathe"}) {
    const auto dir = temp_dir("init_" + kind) / "machine";
    CliResult init = run_nck("init " + dir.string() + " --" + kind);
    ASSERT_EQ(init.exit_code, 0) << init.output;
    EXPECT_NE(init.output.find("nck check " + dir.string()), std::string::npos) << init.output;
    // The lists are the example machine's, byte for byte.
    for (const auto& f : std::filesystem::directory_iterator(root() + "/examples/" + kind)) {
      if (f.path().extension() != ".lis") continue;
      EXPECT_EQ(read_file(dir / f.path().filename()), read_file(f.path())) << f.path();
    }
    CliResult check = run_nck("check " + dir.string());
    EXPECT_EQ(check.exit_code, 0) << check.output;
    // The mill's S2 is sensorless: the check says it cannot position (70252).
    const std::string summary = kind == "mill" ? "0 error(s), 1 warning(s)" : "0 error(s), 0 warning(s)";
    EXPECT_NE(check.output.find(summary), std::string::npos) << check.output;
    EXPECT_EQ(check.output.find("warning 70252") != std::string::npos, kind == "mill") << check.output;
    const std::string program = (dir / (kind == "mill" ? "contour.nc" : "turn.nc")).string();
    CliResult run = run_nck("run " + dir.string() + " " + program);
    EXPECT_EQ(run.exit_code, 0) << run.output;
    EXPECT_NE(run.output.find("nck: program_end after"), std::string::npos) << run.output;
  }
}

TEST(Init, RefusesAFolderThatIsNotEmptyAndBothKinds) {
  const auto dir = temp_dir("init_refuse") / "machine";
  ASSERT_EQ(run_nck("init " + dir.string()).exit_code, 0);
  const std::string before = read_file(dir / "x.lis");
  CliResult again = run_nck("init " + dir.string() + " --lathe");
  EXPECT_EQ(again.exit_code, 2) << again.output;
  EXPECT_NE(again.output.find("940001"), std::string::npos) << again.output;
  EXPECT_NE(again.output.find("is not an empty folder"), std::string::npos) << again.output;
  EXPECT_EQ(read_file(dir / "x.lis"), before);
  EXPECT_EQ(run_nck("init " + (dir.parent_path() / "other").string() + " --mill --lathe").exit_code, 2);
}

}  // namespace
}  // namespace nck::app::testing

namespace nck::app::testing {
namespace {

// The minimal template of docs/machine-folder.md is a machine that checks
// clean: each "`name.lis`" line followed by a code block is one file.
TEST(Init, TheDocumentedMinimalTemplateChecksClean) {
  const std::string doc = read_file(root() + "/docs/machine-folder.md");
  const auto dir = temp_dir("doc_template");
  std::size_t files = 0;
  for (std::size_t at = doc.find("\n`"); at != std::string::npos; at = doc.find("\n`", at + 1)) {
    const std::size_t name_end = doc.find("`\n```\n", at + 2);
    if (name_end == std::string::npos || doc.find('\n', at + 1) != name_end + 1) continue;
    const std::string name = doc.substr(at + 2, name_end - at - 2);
    const std::size_t body = name_end + 6;
    std::ofstream(dir / name) << doc.substr(body, doc.find("```", body) - body);
    ++files;
  }
  EXPECT_EQ(files, 3u);
  CliResult check = run_nck("check " + dir.string());
  EXPECT_EQ(check.exit_code, 0) << check.output;
  EXPECT_NE(check.output.find("0 error(s), 0 warning(s)"), std::string::npos) << check.output;
  std::ofstream(dir / "p.nc") << "N10 G01 X100 F6000\nN20 G00 X0\nM30\n";
  EXPECT_EQ(run_nck("run " + dir.string() + " " + (dir / "p.nc").string()).exit_code, 0);
}

}  // namespace
}  // namespace nck::app::testing
