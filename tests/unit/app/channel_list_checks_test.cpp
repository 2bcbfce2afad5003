// Channel-list rules that `nck check` reports with ID, file and line: path
// axis names (P-CHAN-00006), alias names A1..A32 (P-CHAN-00253) and the
// range of dist_ctrl[0].max_pos (P-CHAN-00806).
#include <gtest/gtest.h>

#include <string>

#include "cli_helpers.hpp"

namespace nck::app::testing {
namespace {

// A copy of an example with the first `from` in one list replaced by `to`;
// the line of the replacement.
PatchedMachine replaced(const std::string& example, const std::string& name, const std::string& file,
                        const std::string& from, const std::string& to) {
  PatchedMachine m = patched_example(example, name, file, "");
  std::string text = read_file(m.dir / file);
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at == std::string::npos) return m;
  text.replace(at, from.size(), to);
  std::ofstream(m.dir / file) << text;
  m.line = static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n')) + 1;
  return m;
}

std::string at_line(const std::string& file, std::size_t line, const std::string& what) {
  return file + ":" + std::to_string(line) + ": " + what;
}

TEST(AxisNames, OnlyLettersDigitsAndUnderscoreAfterTheFirstLetter) {
  for (const std::string bad : {"Z-1", "Z.1", "Z=1"}) {
    const auto m = replaced("mill", "axis_name_bad", "channel1.lis", "achse[2].bezeichnung    Z",
                            "achse[2].bezeichnung    " + bad);
    const CliResult r = run_nck("check " + m.dir.string());
    EXPECT_EQ(r.exit_code, 1) << bad << "\n" << r.output;
    EXPECT_NE(r.output.find(at_line("channel1.lis", m.line, "error 910011")), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("'" + bad + "'"), std::string::npos) << r.output;
  }
}

TEST(AxisNames, TheManualsExampleNameIsAccepted) {
  // TF5200's own example X_ACHSE1; the program addresses it as X_ACHSE1=..
  const auto m = replaced("mill", "axis_name_ok", "channel1.lis", "achse[2].bezeichnung    Z",
                          "achse[2].bezeichnung    Z_ACHSE1");
  const CliResult r = run_nck("check " + m.dir.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  std::ofstream(m.dir / "p.nc") << "G0 Z_ACHSE1=5\nM30\n";
  const CliResult run = run_nck("run " + m.dir.string() + " " + (m.dir / "p.nc").string() + " --final " +
                                (m.dir / "f.json").string());
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NEAR(nlohmann::json::parse(read_file(m.dir / "f.json"))["channels"][0]["axes"]["Z_ACHSE1"]["mcs"].get<double>(),
              5.0, 1e-9);
}

TEST(AxisNames, ATooLongNameIsReportedOnceAtItsLine) {
  const auto m = replaced("mill", "axis_name_long", "channel1.lis", "achse[2].bezeichnung    Z",
                          "achse[2].bezeichnung    Z2345678901234567");  // 17 characters
  const CliResult r = run_nck("check " + m.dir.string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find(at_line("channel1.lis", m.line, "error 910004")), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("error 910011"), std::string::npos) << r.output;  // no follow-on error
  std::size_t errors = 0;
  for (std::size_t at = r.output.find(": error "); at != std::string::npos; at = r.output.find(": error ", at + 1))
    ++errors;
  EXPECT_EQ(errors, 1u) << r.output;
}

TEST(AliasNames, AnAxisNamedA1SwitchesAliasNamesOffWithWarning22016) {
  // Alias names on: A2 (y.lis, P-AXIS-00297) programs Y.
  auto alias_machine = [](const std::string& name, const std::string& z_name) {
    PatchedMachine m = replaced("mill", name, "channel1.lis", "achse[2].bezeichnung    Z",
                                "achse[2].bezeichnung    " + z_name + "\nuse_alias_name_in_ax_list 1");
    std::string y = read_file(m.dir / "y.lis");
    y.replace(y.find("kopf.log_achs_name                Y"), 35, "kopf.log_achs_name                A2");
    std::ofstream(m.dir / "y.lis") << y;
    std::ofstream(m.dir / "p.nc") << "G0 A2=7\nM30\n";
    return m;
  };
  const auto on = alias_machine("alias_on", "Z");
  const CliResult ok = run_nck("run " + on.dir.string() + " " + (on.dir / "p.nc").string() + " --final " +
                               (on.dir / "f.json").string());
  ASSERT_EQ(ok.exit_code, 0) << ok.output;
  EXPECT_NEAR(nlohmann::json::parse(read_file(on.dir / "f.json"))["channels"][0]["axes"]["Y"]["mcs"].get<double>(),
              7.0, 1e-9);

  const auto clash = alias_machine("alias_clash", "A1");
  const CliResult check = run_nck("check " + clash.dir.string());
  EXPECT_EQ(check.exit_code, 0) << check.output;  // a warning: start-up goes on
  EXPECT_NE(check.output.find(at_line("channel1.lis", clash.line, "warning 22016")), std::string::npos)
      << check.output;
  const CliResult refused = run_nck("run " + clash.dir.string() + " " + (clash.dir / "p.nc").string());
  EXPECT_EQ(refused.exit_code, 1) << refused.output;
  EXPECT_NE(refused.output.find("'A2' is not a configured axis"), std::string::npos) << refused.output;
}

TEST(DistCtrlList, MaxPosIsNotNegative) {
  const auto m = replaced("mill", "max_pos_neg", "channel1.lis", "dist_ctrl[0].max_pos              50000",
                          "dist_ctrl[0].max_pos              -1");
  const CliResult r = run_nck("check " + m.dir.string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find(at_line("channel1.lis", m.line, "error 910004")), std::string::npos) << r.output;
  // min_pos keeps its default -50000 although the seed's range starts at 0.
  const auto d = replaced("mill", "min_pos_default", "channel1.lis", "dist_ctrl[0].max_pos              50000",
                          "dist_ctrl[0].max_pos              0");
  const CliResult ok = run_nck("check " + d.dir.string());
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
}

}  // namespace
}  // namespace nck::app::testing
