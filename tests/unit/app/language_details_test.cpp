// Language details real ISG programs show, through the nck binary:
// #COMMENT BEGIN/END where the manual allows them, '\' continuation of #
// commands with bracket lists, and ISG functions nck does not have named
// as not supported.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "cli_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;
using nlohmann::json;

std::filesystem::path program_file(const std::string& name, const std::string& text) {
  const auto dir = temp_dir("lang-" + name);
  std::ofstream(dir / "main.nc") << text;
  return dir / "main.nc";
}

TEST(LanguageDetails, CommentBlocksInAndOutsideSectionsWithBlockNumbers) {
  // A commented-out "%L fake" is no section; "N20 #COMMENT BEGIN (note)"
  // with a block number and a ( ) comment opens, "N30 #COMMENT END ; done"
  // closes: X99 never runs, the local subroutine moves X to 5.
  const auto prog = program_file("comments",
                          "#COMMENT BEGIN\n%L fake\nG0 X77\nM17\n#COMMENT END\n"
                          "%L sub\nG0 X5\nM17\n"
                          "%main\nN10 G0 X0 Y0 Z0\nN20 #COMMENT BEGIN (note)\nG0 X99\nN30 #COMMENT END ; done\n"
                          "LL sub\nM30\n");
  const auto final_json = prog.parent_path() / "final.json";
  CliResult r = run_nck("run " + root() + "/examples/mill " + prog.string() + " --final " + final_json.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const json f = json::parse(read_file(final_json));
  EXPECT_NEAR(f["channels"][0]["axes"]["X"]["pcs"].get<double>(), 5, 1e-9);
}

TEST(LanguageDetails, CommentCommandsMustStandAlone) {
  CliResult r = run_nck("parse " + program_file("begin", "G0 X0\n#COMMENT BEGIN X100\n#COMMENT END\nM30\n").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("main.nc:2:16: error 20566"), std::string::npos) << r.output;
  r = run_nck("parse " + program_file("end", "G0 X0\n#COMMENT BEGIN\n#COMMENT END G1 X5\nM30\n").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("main.nc:3:14: error 20569"), std::string::npos) << r.output;
}

// An option written without its brackets is told the syntax, not that the
// # command must be alone in its block.
TEST(LanguageDetails, McsOnExToolWithoutBracketsNamesTheSyntax) {
  CliResult r = run_nck("parse " + program_file("mcs_ex_tool", "G0 X0\n#MCS ON EX TOOL\nM30\n").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("main.nc:2:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("error 920081"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("#MCS ON [EX TOOL]"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("920082"), std::string::npos) << r.output;
}

TEST(LanguageDetails, HashCommandBracketListsContinueOverLines) {
  // #CS DEF with its value list over three lines decodes like the one-line form.
  CliResult r = run_nck("parse --json " +
                        program_file("cs", "#CS DEF [1] [10, 20, \\\n  0, 0, \\\n  0, 90]\n#CS ON [1]\nG0 X0\nM30\n").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  CliResult one = run_nck("parse --json " + program_file("cs1", "#CS DEF [1] [10, 20, 0, 0, 0, 90]\n#CS ON [1]\nG0 X0\nM30\n").string());
  ASSERT_EQ(one.exit_code, 0) << one.output;
  const auto a = split(r.output, '\n');
  const auto b = split(one.output, '\n');
  ASSERT_FALSE(a.empty());
  ASSERT_EQ(a.size(), b.size());
  const json ja = json::parse(a[0]), jb = json::parse(b[0]);
  EXPECT_EQ(ja.at("hash"), jb.at("hash")) << a[0];
}

TEST(LanguageDetails, IsgFunctionsNckDoesNotHaveAreNamedNotSupported) {
  for (auto [text, name] : {std::pair{"#RT CYCLE [ID=1]", "#RT CYCLE"}, {"#MC_MOVEPATH SYN [..]", "#MC_MOVEPATH"},
                            {"#WAIT SYN [ID=1]", "#WAIT SYN"}, {"G23 X1", "G23"}, {"G81 X1", "G81"}}) {
    CliResult r = run_nck("parse " + program_file("unsupported", fmt::format("G0 X0\n{}\nM30\n", text)).string());
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find(fmt::format("main.nc:2:1: error 920052: {} is an ISG function nck does not support", name)),
              std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("920080"), std::string::npos) << r.output;  // never "unknown # command"
    EXPECT_EQ(r.output.find("920005"), std::string::npos) << r.output;  // never "unknown G code"
  }
}

}  // namespace
}  // namespace nck::app
