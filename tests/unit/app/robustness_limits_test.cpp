// Robustness, second pass (issue 26): string variables within a byte cap,
// diagnostics on stderr as UTF-8, lists of many unknown keys, and a PLC
// reset that says what happened. Each test drives the nck binary.
#include <gtest/gtest.h>

#include "cli_helpers.hpp"

namespace nck::app::testing {
namespace {

bool valid_utf8(const std::string& s) {
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
    if (n == 0 || i + n > s.size()) return false;
    for (std::size_t k = 1; k < n; ++k)
      if ((static_cast<unsigned char>(s[i + k]) >> 6) != 2) return false;
    i += n;
  }
  return true;
}

// Finding 6: string arrays are capped by their declared bytes, and a STRING
// length beyond nck's maximum (4,000 characters) is refused.
TEST(RobustnessLimits, StringVariablesHaveAByteCap) {
  const auto dir = temp_dir("string_cap");
  std::string arrays = "#VAR\n";
  for (int i = 0; i < 3; ++i) arrays += "V.P.S" + std::to_string(i) + "[100000] : STRING[4000]\n";
  arrays += "#ENDVAR\nM30\n";
  CliResult declared = run_nck("parse " + write(dir / "arrays.nc", arrays).string());
  EXPECT_EQ(declared.exit_code, 1);
  EXPECT_NE(declared.output.find("arrays.nc:2:"), std::string::npos) << declared.output;  // the first: 400 MB
  EXPECT_NE(declared.output.find("920085"), std::string::npos) << declared.output;

  CliResult huge = run_nck("parse " + write(dir / "huge.nc", "#VAR\nV.P.T : STRING[2000000000]\n#ENDVAR\nM30\n").string());
  EXPECT_EQ(huge.exit_code, 1);
  EXPECT_NE(huge.output.find("920025"), std::string::npos) << huge.output;

  // Texts assigned to strings declared without a length count as well.
  const std::string text(3900, 'x');
  const auto assigned = write(dir / "assigned.nc", "#VAR\nV.P.U[100000] : STRING\n#ENDVAR\n$FOR P1 = 0, 99999\n"
                                                   "V.P.U[P1] = \"" + text + "\"\n$ENDFOR\nM30\n");
  CliResult r = run_nck("parse " + assigned.string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("920085"), std::string::npos) << r.output.substr(0, 2000);
  EXPECT_NE(r.output.find("assigned.nc:5:"), std::string::npos) << r.output.substr(0, 2000);
}

// Finding 8: stderr gets the same UTF-8 as the JSON outputs (a Latin-1 list
// key, a Latin-1 file name in L).
TEST(RobustnessLimits, DiagnosticsOnStderrAreUtf8) {
  const auto m = patched_example("mill", "latin1_key", "channel1.lis", "gr\xf6\xdf" "e 1");
  CliResult check = run_nck("check " + m.dir.string());
  EXPECT_NE(check.output.find("gr\xc3\xb6\xc3\x9f" "e"), std::string::npos) << check.output;
  EXPECT_TRUE(valid_utf8(check.output));
  const auto dir = temp_dir("latin1_name");
  CliResult parse = run_nck("parse " + write(dir / "p.nc", "L unterprogramm_\xe4.nc\nM30\n").string());
  EXPECT_EQ(parse.exit_code, 1);
  EXPECT_NE(parse.output.find("unterprogramm_\xc3\xa4"), std::string::npos) << parse.output;
  EXPECT_TRUE(valid_utf8(parse.output));
}

// Finding 9: a list of 300,000 unknown keys lists the first 200 diagnostics
// and counts the rest, without a did-you-mean search for each.
TEST(RobustnessLimits, ManyUnknownKeysAreCountedNotSearched) {
  std::string lines;
  for (int i = 0; i < 300'000; ++i) lines += "unbekannter_schluessel_" + std::to_string(i) + " 1\n";
  const auto m = patched_example("mill", "unknown_keys", "channel1.lis", lines);
  CliResult check = run_nck("check " + m.dir.string());
  EXPECT_LE(count(check.output, "910002"), 201u);
  EXPECT_NE(check.output.find(" more unknown key(s)"), std::string::npos) << check.output.substr(0, 500);
}

// Finding 10 of issue 26 said what a --plc reset did with an ID (940007);
// issue 44 made a reset an operator's action: the run ends with reason
// reset, no error, exit 0.
TEST(RobustnessLimits, APlcResetSaysWhatHappened) {
  const auto dir = temp_dir("plc_reset");
  write(dir / "reset.plc", "0.5 reset\n");
  const auto p = write(dir / "p.nc", "N10 G4 X2\nN20 M30\n");
  CliResult r = run_nck("run " + mill() + " " + p.string() + " --plc " + (dir / "reset.plc").string() + " --final " +
                        (dir / "f.json").string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("940007"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("nck: reset after"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("0 error(s)"), std::string::npos) << r.output;
  const auto final_state = nlohmann::json::parse(read_file(dir / "f.json"));
  EXPECT_EQ(final_state["end"], "reset");
  EXPECT_TRUE(final_state["errors"].empty()) << final_state.dump();
}

}  // namespace
}  // namespace nck::app::testing
