// nck diff (issue 31 item 3): two final states compared per cause, tool,
// subroutine and block; two runs compared in-process, with their paths;
// run B as a ghost in run A's report; bad input gets an ID, never a crash.
#include <gtest/gtest.h>

#include "cli_helpers.hpp"

namespace nck::app::testing {
namespace {

using nlohmann::json;

// A run's --final of `program` on the mill, in `dir`.
std::string final_of(const std::filesystem::path& dir, const std::string& name, const std::string& program,
                     const std::string& plc = {}) {
  const auto prog = write(dir / (name + ".nc"), program);
  const std::string out = (dir / (name + ".json")).string();
  std::string args = "run " + mill() + " " + prog.string() + " --final " + out;
  if (!plc.empty()) args += " --plc " + write(dir / (name + ".plc"), plc).string();
  const CliResult r = run_nck(args);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return out;
}

// The row of `key` in one of the diff's tables of channel 1.
json row(const json& diff, const std::string& table, const std::string& key) {
  for (const json& r : diff["channels"][0][table])
    if (r["key"] == key) return r;
  return json::object();
}

const std::string kProgram = "G90 G0 X0 Y0 Z0\nT1 D1 M6\nG1 X100 F1200\nG1 Y50\nM30\n";

TEST(Diff, OverrideShowsAsOverrideTimeAndCycleTime) {
  const auto dir = temp_dir("diff_files");
  const std::string a = final_of(dir, "a", kProgram);
  const std::string b = final_of(dir, "b", kProgram, "0 feed_override 50\n");
  const CliResult r = run_nck_raw("diff " + a + " " + b + " --json 2>/dev/null");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const json d = json::parse(r.output, nullptr, false);
  ASSERT_TRUE(d.is_object()) << r.output;
  // 150 mm at 20 mm/s is 7.5 s; at 50 % 15 s: B takes about 7.5 s longer
  EXPECT_NEAR(d["delta_s"].get<double>(), 7.5, 0.3) << r.output;
  EXPECT_NEAR(d["delta_s"].get<double>(), d["time_b_s"].get<double>() - d["time_a_s"].get<double>(), 1e-6);
  // the time went from feed to override: the biggest change first
  const json& first = d["channels"][0]["causes"][0];
  EXPECT_TRUE(first["key"] == "override" || first["key"] == "feed") << first.dump();
  EXPECT_GT(row(d, "causes", "override")["delta_s"].get<double>(), 14) << d.dump(1);
  EXPECT_LT(row(d, "causes", "feed")["delta_s"].get<double>(), -7) << d.dump(1);
  // per tool (T1 did the cutting) and per block (line 3, by its text: 100 mm, 5 s -> 10 s)
  EXPECT_NEAR(row(d, "tools", "T1")["delta_s"].get<double>(), d["delta_s"].get<double>(), 0.05) << d.dump(1);
  EXPECT_NEAR(row(d, "blocks", "G1 X100 F1200")["a_s"].get<double>(), 5.0, 0.2) << d.dump(1);
  EXPECT_NEAR(row(d, "blocks", "G1 X100 F1200")["delta_s"].get<double>(), 5.0, 0.2) << d.dump(1);
  EXPECT_NEAR(row(d, "subroutines", "(main program)")["delta_s"].get<double>(), d["delta_s"].get<double>(), 1e-6);
}

TEST(Diff, TableOnStdout) {
  const auto dir = temp_dir("diff_table");
  const std::string a = final_of(dir, "a", kProgram);
  const std::string b = final_of(dir, "b", kProgram, "0 feed_override 50\n");
  const CliResult r = run_nck_raw("diff " + a + " " + b + " 2>/dev/null");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("cycle time: A "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("by cause"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("override"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("by tool"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("by block"), std::string::npos) << r.output;
}

TEST(Diff, BadInputGetsADiagnosticWithID) {
  const auto dir = temp_dir("diff_bad");
  const std::string good = final_of(dir, "a", kProgram);
  const auto expect = [&](const std::string& other, const std::string& id, const std::string& where) {
    const CliResult r = run_nck("diff " + good + " " + other);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("error " + id), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(where), std::string::npos) << r.output;
  };
  expect((dir / "missing.json").string(), "940100", "missing.json");
  expect(write(dir / "text.json", "{\"time\": 1,\n  oops}\n").string(), "940101", "text.json:2");
  expect(write(dir / "events.json", "[1, 2]\n").string(), "940101", "events.json");
  expect(write(dir / "old.json", "{\"time\": 1, \"channels\": []}\n").string(), "940102", "old.json");
  expect(write(dir / "v9.json", "{\"format\": 9, \"time\": 1, \"time_by_cause\": {\"channels\": []}}\n").string(),
         "940102", "v9.json");
  expect(write(dir / "nocause.json", "{\"format\": 2, \"time\": 1}\n").string(), "940101", "nocause.json");
  const CliResult one = run_nck("diff " + good);
  EXPECT_EQ(one.exit_code, 2) << one.output;
  EXPECT_NE(one.output.find("error 940001"), std::string::npos) << one.output;
  const CliResult report = run_nck("diff " + good + " " + good + " --report " + (dir / "r.html").string());
  EXPECT_EQ(report.exit_code, 2) << report.output;
  EXPECT_NE(report.output.find("belong to nck diff --run"), std::string::npos) << report.output;
}

// STEP against corner blending: B rounds the corner, so it is faster, and
// the largest position difference sits at a corner (lines 4, 5; both
// programs have the same line numbers).
TEST(Diff, RunComparesTimesAndPaths) {
  const auto dir = temp_dir("diff_run");
  const std::string program = "G90 G0 X0 Y0 Z0\n\nG1 F6000\nX100\nY100\nX0\nM30\n";
  const auto a = write(dir / "a.nc", program);
  const auto b = write(dir / "b.nc", "G90 G0 X0 Y0 Z0\n#CONTOUR MODE [DEV PATH_DEV=0.5]\nG261 G1 F6000\nX100\nY100\nX0\nM30\n");
  const std::string report = (dir / "r.html").string();
  const CliResult r = run_nck_raw("diff --run " + mill() + " " + a.string() + " " + mill() + " " + b.string() +
                                  " --json --report " + report + " 2>" + (dir / "err.txt").string());
  ASSERT_EQ(r.exit_code, 0) << r.output << read_file((dir / "err.txt").string());
  const json d = json::parse(r.output, nullptr, false);
  ASSERT_TRUE(d.is_object()) << r.output;
  EXPECT_LT(d["delta_s"].get<double>(), 0) << "blending is faster\n" << d.dump(1);
  const json& path = d["path"];
  EXPECT_NEAR(path["length_a_mm"].get<double>(), 300, 0.01) << path.dump(1);
  EXPECT_LT(path["length_b_mm"].get<double>(), 300) << path.dump(1);
  ASSERT_FALSE(path["largest"].empty()) << path.dump(1);
  const json& top = path["largest"][0];
  EXPECT_GT(top["distance_mm"].get<double>(), 0.05) << path.dump(1);
  EXPECT_LE(top["distance_mm"].get<double>(), 0.5 + 1e-3) << "within the blend's PATH_DEV\n" << path.dump(1);
  EXPECT_TRUE(top["line_a"] == 4 || top["line_a"] == 5) << path.dump(1);
  // the report shows B as a ghost
  const std::string html = read_file(report);
  EXPECT_NE(html.find("\"ghost\":{\"label\":\"B: "), std::string::npos);
}

TEST(Diff, RunOfAMissingProgramSaysWhich) {
  const auto dir = temp_dir("diff_run_bad");
  const auto a = write(dir / "a.nc", kProgram);
  const CliResult r = run_nck("diff --run " + mill() + " " + a.string() + " " + mill() + " " + (dir / "nope.nc").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("nope.nc"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("error 940103"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace nck::app::testing
