// Time by cause (issue 31): constructed programs of a few blocks, each with
// a block whose time is >= 90 % one class; the classes add up to the run's
// time for every example; the report shows the tables.
#include <gtest/gtest.h>

#include <set>
#include <sstream>

#include "time_by_cause_helpers.hpp"

namespace nck::app::testing {
namespace {

using nlohmann::json;

TEST(TimeByCause, FeedLimitedLine) {
  expect_dominant(run_program("feed", "G90 G0 X0 Y0 Z0\nG1 X200 F1200\nM30\n"), 2, "feed");
}

// The mill with X slowed to 6 m/min (the ramps at 2.5 m/s^2 then take 2 % of the block).
std::string slow_x_mill() {
  namespace fs = std::filesystem;
  const auto dir = temp_dir("cause_slow_x");
  fs::copy(mill(), dir / "m", fs::copy_options::recursive);
  std::ifstream in(dir / "m" / "x.lis");
  std::string text, line;
  while (std::getline(in, line)) {
    if (line.starts_with("getriebe[0].dynamik.vb_max")) line = "getriebe[0].dynamik.vb_max 100000";
    if (line.starts_with("getriebe[0].vb_eilgang")) line = "getriebe[0].vb_eilgang 100000";
    text += line + "\n";
  }
  in.close();
  write(dir / "m" / "x.lis", text);
  return (dir / "m").string();
}

TEST(TimeByCause, AxisVelocityLimitedLineNamesTheAxis) {
  // 60 m/min asked, X can do 6 m/min, Y 30: X binds
  expect_dominant(run_program("axis_v", "G90 G0 X0 Y0 Z0\nG1 X400 Y40 F60000\nM30\n", "", slow_x_mill()), 2,
                  "axis_velocity X");
}

TEST(TimeByCause, ShortBlocksAreAccelerationLimitedNamingTheAxis) {
  // exact stop, 1 mm blocks at 100 mm/s: each is a ramp up and down in Y
  std::string p = "G90 G0 X0 Y0 Z0\nG360 F6000\n";
  for (int i = 1; i <= 5; ++i) p += "G1 Y" + std::to_string(i) + "\n";
  p += "M30\n";
  expect_dominant(run_program("accel", p), 4, "acceleration Y");
}

TEST(TimeByCause, FeedOverrideFifty) {
  expect_dominant(run_program("override", "G90 G0 X0 Y0 Z0\nG1 X100 F1200\nM30\n", "0 feed_override 50\n"), 2,
                  "override");
}

TEST(TimeByCause, RapidTraverse) {
  expect_dominant(run_program("rapid", "G90 G1 X0 Y0 Z0 F1000\nG0 X300 Y100\nM30\n"), 2, "rapid");
}

TEST(TimeByCause, Dwell) {
  expect_dominant(run_program("dwell", "G90 G0 X0 Y0 Z0\nG4 X2\nM30\n"), 2, "wait dwell");
}

TEST(TimeByCause, PlcAcknowledgeWait) {
  // M6 (tool change, MVS_SVS): the PLC acknowledges it after 1.5 s (sim.lis)
  expect_dominant(run_program("plc_ack", "G90 G0 X0 Y0 Z0\nM6\nM30\n"), 2, "wait plc_ack");
}

TEST(TimeByCause, SpindleSpeedWait) {
  // M3 of S1 is MVS_SVS: the motion waits until the spindle is at speed
  expect_dominant(run_program("speed", "G90 G0 X0 Y0 Z0\nM3 S8000\nM30\n"), 2, "wait speed_reached");
}

TEST(TimeByCause, Feedhold) {
  expect_dominant(run_program("feedhold", "G90 G0 X0 Y0 Z0\nG1 X10 F600\nM30\n",
                              "0.2 feedhold on\n30 feedhold off\n"),
                  2, "hold feedhold");
}

TEST(TimeByCause, Corner) {
  // a zigzag of 1 mm blocks that turn by 1.5 degrees: the corners allow
  // about 55 mm/s (half of a_max, 1.5 mm/s in a cycle, over Y's turn of
  // 0.026, less a braking step), and between them the path never reaches
  // F (100 mm/s)
  std::string p = "G90 G0 X0 Y0 Z0\nG1 F6000\n";
  for (int i = 1; i <= 40; ++i) p += "X" + std::to_string(i) + " Y" + (i % 2 ? "0.013" : "0") + "\n";
  p += "M30\n";
  expect_dominant(run_program("corner", p), 20, "corner");
}

// A square of 4 mm sides at 100 mm/s on the mill: each 90° corner lets no
// speed through, so the path stops there; braking into those stops and
// speeding up out of them is "corner" (issue 43), as for a corner passed
// at speed — not "acceleration", which an exact stop the program asks for
// stays (ShortBlocksAreAccelerationLimitedNamingTheAxis).
TEST(TimeByCause, StopAtASharpCornerIsCorner) {
  expect_dominant(run_program("corner_stop", "G90 G0 X0 Y0 Z0\nG1 X4 F6000\nY4\nX0\nY0\nM30\n"), 3, "corner");
}

// The classes of every channel add up to its time; the last one to end
// ran for the run's whole time.
void expect_sums(const json& final, const std::string& what) {
  ASSERT_TRUE(final.contains("time_by_cause")) << what;
  const json& t = final["time_by_cause"];
  const double cycle_s = t["cycle_s"].get<double>();
  double longest_s = 0;
  for (const json& ch : t["channels"]) {
    double sum_s = 0;
    for (const json& c : ch["causes"]) {
      sum_s += c["time_s"].get<double>();
      EXPECT_NE(c["cause"], "none") << what;
    }
    EXPECT_NEAR(sum_s, ch["time_s"].get<double>(), 1e-6) << what;
    longest_s = std::max(longest_s, ch["time_s"].get<double>());
  }
  EXPECT_NEAR(longest_s, final["time"].get<double>(), cycle_s * 1e-3) << what;
}

TEST(TimeByCause, ClassesAddUpToTheRunTimeForEveryExample) {
  namespace fs = std::filesystem;
  const std::vector<std::pair<std::string, std::string>> runs = {
      {"mill", "contour.nc"},      {"mill", "contour_blend.nc"}, {"mill", "contour_trc.nc"}, {"mill", "spindle.nc"},
      {"mill", "tools.nc"},        {"mill", "cycles.nc"},        {"mill", "jumps.nc"},       {"mill", "offsets.nc"},
      {"mill", "tapping.nc"},      {"mill", "coordinates.nc"},   {"mill", "caxis.nc"},       {"mill", "measure.nc"}};
  for (const auto& [machine, prog] : runs) {
    const auto dir = temp_dir("cause_ex");
    const std::string m = root() + "/examples/" + machine;
    const CliResult r = run_nck("run " + m + " " + m + "/" + prog + " --final " + (dir / "f.json").string());
    std::ifstream f(dir / "f.json");
    const json final = json::parse(f, nullptr, false);
    expect_sums(final, prog + "\n" + r.output);
  }
  for (const fs::path& machine : {fs::path(root()) / "examples/lathe", fs::path(root()) / "examples/twin-spindle",
                                  fs::path(root()) / "examples/cutter"})
    for (const auto& entry : fs::directory_iterator(machine)) {
      if (entry.path().extension() != ".nc") continue;
      const auto dir = temp_dir("cause_ex2");
      const CliResult r = run_nck("run " + machine.string() + " " + entry.path().string() + " --final " +
                                  (dir / "f.json").string());
      std::ifstream f(dir / "f.json");
      expect_sums(json::parse(f, nullptr, false), entry.path().string() + "\n" + r.output);
    }
  const std::string two = root() + "/examples/two-channel";
  const auto dir = temp_dir("cause_two");
  const CliResult r = run_nck("run " + two + " " + two + "/channel1.nc " + two + "/channel2.nc --final " +
                              (dir / "f.json").string());
  std::ifstream f(dir / "f.json");
  expect_sums(json::parse(f, nullptr, false), "two-channel\n" + r.output);
}

TEST(TimeByCause, ContourNamesAtLeastFourCauses) {
  const auto dir = temp_dir("cause_contour");
  const CliResult r = run_nck("run " + mill() + " " + mill() + "/contour.nc --final " + (dir / "f.json").string() +
                              " --report " + (dir / "r.html").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream f(dir / "f.json");
  const json final = json::parse(f, nullptr, false);
  expect_sums(final, "contour.nc");
  std::set<std::string> causes;
  for (const json& c : final["time_by_cause"]["channels"][0]["causes"]) causes.insert(c["cause"].get<std::string>());
  EXPECT_GE(causes.size(), 4u) << final["time_by_cause"]["channels"][0]["causes"].dump(1);
  // three lines on stderr name the top causes
  EXPECT_EQ(count(r.output, "nck: time by cause "), 3u) << r.output;
  // the report has the section and its tables
  std::ifstream h(dir / "r.html");
  const std::string html((std::istreambuf_iterator<char>(h)), std::istreambuf_iterator<char>());
  EXPECT_NE(html.find("Time by cause"), std::string::npos);
  EXPECT_NE(html.find("\"causes\":{\"cycle_s\""), std::string::npos);
}

// docs/outputs.md names every field of time_by_cause the binary writes.
void collect_keys(const json& j, std::set<std::string>& keys) {
  if (j.is_object())
    for (const auto& [k, v] : j.items()) {
      keys.insert(k);
      collect_keys(v, keys);
    }
  if (j.is_array())
    for (const json& v : j) collect_keys(v, keys);
}

TEST(TimeByCause, OutputsDocDescribesEveryField) {
  const CauseRun r = run_program("doc", "G90 G0 X0 Y0 Z0\nT1 D1\nM3 S1000\nG1 X20 F1200\nG4 X0.1\nM30\n");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::set<std::string> keys;
  collect_keys(r.final["time_by_cause"], keys);
  const std::string doc = read_file(root() + "/docs/outputs.md");
  for (const std::string& k : keys)
    EXPECT_NE(doc.find("\"" + k + "\""), std::string::npos) << k << " is not in docs/outputs.md";
}

}  // namespace
}  // namespace nck::app::testing

namespace nck::app::testing {
namespace {

// The lines of stderr that name the top causes.
std::vector<std::string> cause_lines(const std::string& output) {
  std::vector<std::string> lines;
  std::istringstream in(output);
  for (std::string line; std::getline(in, line);)
    if (line.starts_with("nck: time by cause")) lines.push_back(line);
  return lines;
}

// A plain run keeps only the channels' totals (no outputs show more): its
// top causes are those of a run with --final, word for word. With the
// spindle turning the C axis moves too, and must not be named for the
// path's ramps.
TEST(TimeByCause, PlainRunNamesTheSameTopCausesAsARunWithFinal) {
  std::string p = "G90 G0 X0 Y0 Z0\nM3 S1000\nG360 F6000\n";
  for (int i = 1; i <= 20; ++i) p += "G1 Y" + std::to_string(i) + " X" + std::to_string(i % 3) + "\n";
  p += "M30\n";
  const CauseRun with_final = run_program("plain_vs_final", p);
  const auto prog = write(temp_dir("cause_plain") / "prog.nc", p);
  const CliResult plain = run_nck("run " + mill() + " " + prog.string());
  ASSERT_EQ(with_final.exit_code, 0) << with_final.output;
  ASSERT_EQ(plain.exit_code, 0) << plain.output;
  const std::vector<std::string> lines = cause_lines(with_final.output);
  ASSERT_EQ(lines.size(), 3u) << with_final.output;
  EXPECT_EQ(cause_lines(plain.output), lines);
  for (const std::string& line : lines) EXPECT_EQ(line.find("acceleration C"), std::string::npos) << line;
}

}  // namespace
}  // namespace nck::app::testing
