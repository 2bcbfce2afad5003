// `nck run --report`, issue 17's later points through the binary: program
// coordinates (each block's program -> machine map), the programmed contour
// beside the tool-centre path under G41/G42, override marks and feedhold
// spans from the PLC scenario. Expected numbers worked out by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "cli_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;
using nlohmann::json;

json report_of(const std::string& name, const std::string& args) {
  const auto dir = temp_dir(name);
  const CliResult r = run_nck("run " + args + " --no-progress --report " + (dir / "r.html").string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  const std::string html = read_file(dir / "r.html");
  const std::string open = "<script id=\"nck-data\" type=\"application/json\">";
  const std::size_t a = html.find(open);
  if (a == std::string::npos) return json();
  return json::parse(html.substr(a + open.size(), html.find("</script>", a) - a - open.size()));
}

// The points of one contour run as (x, y) pairs, machine or program coordinates.
std::vector<std::pair<double, double>> xy(const json& run, bool pcs) {
  std::vector<std::pair<double, double>> out;
  for (std::size_t k = 0; k < run["x"].size(); ++k)
    out.emplace_back(run[pcs ? "px" : "x"][k].get<double>(), run[pcs ? "py" : "y"][k].get<double>());
  return out;
}

TEST(ReportFrames, ProgramCoordinatesUndoG54AndARotation) {
  const auto dir = temp_dir("report_frames_src");
  std::ofstream(dir / "p.nc") << "N10 G17 G90 G54 G0 X0 Y0 Z5\nN20 #ROTATION ON [ANGLE=90]\nN30 G1 X40 Y0 F3000\n"
                                 "N40 Y20\nN50 X0\nN60 Y0\nN70 #ROTATION OFF\nN80 G0 Z20\nN90 M30\n";
  const json d = report_of("report_frames", root() + "/examples/mill " + (dir / "p.nc").string());
  const json& ch = d["channels"][0];
  // two maps: G54 alone (X100 Y50 Z-150, zero.lis) and G54 with the rotation by 90 deg about Z
  ASSERT_EQ(ch["frames"].size(), 2u);  // G54; G54 + rotation (after #ROTATION OFF the first again)
  EXPECT_EQ(ch["frames"][0]["r"], json::array({1, 0, 0, 0, 1, 0, 0, 0, 1}));
  EXPECT_EQ(ch["frames"][0]["s"], json::array({100, 50, -150}));
  EXPECT_EQ(ch["frames"][1]["r"], json::array({0, -1, 0, 1, 0, 0, 0, 0, 1}));
  EXPECT_EQ(ch["frames"][1]["s"], json::array({100, 50, -150}));
  // every point of N30..N60 is in map 1: machine = r * program + s, program X0..40 Y0..20
  int rotated = 0;
  for (std::size_t i = 0; i < ch["x"].size(); ++i) {
    const int line = ch["line"][i];
    if (line < 3 || line > 6) continue;
    ++rotated;
    EXPECT_EQ(ch["frame"][i], 1);
    const double px = ch["y"][i].get<double>() - 50, py = -(ch["x"][i].get<double>() - 100);
    EXPECT_TRUE(px > -1e-3 && px < 40 + 1e-3 && py > -1e-3 && py < 20 + 1e-3) << px << " " << py;
  }
  EXPECT_GE(rotated, 4);
  EXPECT_EQ(ch["frame"].back(), 0);  // N80 G0 Z20: G54 alone again
  // N40 Y20 ends at program X40 Y20: machine X 100 - 20 = 80, Y 50 + 40 = 90
  bool corner = false;
  for (std::size_t i = 0; i < ch["x"].size(); ++i)
    corner = corner || (ch["line"][i] == 4 && std::abs(ch["x"][i].get<double>() - 80) < 1e-3 &&
                        std::abs(ch["y"][i].get<double>() - 90) < 1e-3);
  EXPECT_TRUE(corner);
}

// G54 selected under G91 acts on each axis when it is next programmed
// absolutely (the G91 rule): a block that programs no offset still gets a
// new map (the report's maps are computed again only after a change).
TEST(ReportFrames, AnOffsetDeferredByG91GivesANewMapAtEachAxisProgrammedAbsolutely) {
  const auto dir = temp_dir("report_frames_g91_src");
  std::ofstream(dir / "p.nc") << "N10 G17 G90 G0 X0 Y0 Z5\nN20 G91 G54 G1 X10 F3000\nN30 G90 X20\nN40 Y10\n"
                                 "N50 Z10\nN60 M30\n";
  const json d = report_of("report_frames_g91", root() + "/examples/mill " + (dir / "p.nc").string());
  const json& ch = d["channels"][0];
  ASSERT_EQ(ch["frames"].size(), 4u);  // none; then G54's X (100), Y (50), Z (-150) one by one
  EXPECT_EQ(ch["frames"][0]["s"], json::array({0, 0, 0}));
  EXPECT_EQ(ch["frames"][1]["s"], json::array({100, 0, 0}));
  EXPECT_EQ(ch["frames"][2]["s"], json::array({100, 50, 0}));
  EXPECT_EQ(ch["frames"][3]["s"], json::array({100, 50, -150}));
  for (std::size_t i = 0; i < ch["line"].size(); ++i) {  // N20 (line 2) still without G54; N30..N50 one map each
    const int line = ch["line"][i];
    if (line < 2 || line > 5) continue;
    EXPECT_EQ(ch["frame"][i], std::max(0, line - 2)) << "line " << line;
  }
}

TEST(ReportFrames, TrcShowsTheProgrammedContourBesideTheToolCentre) {
  const std::string ex = root() + "/examples/mill";
  const json d = report_of("report_trc", ex + " " + ex + "/contour_trc.nc");
  const json& runs = d["channels"][0]["contour"];
  ASSERT_EQ(runs.size(), 3u);  // N40..N90, N110..N200, N310..N370
  // 1: from the start -20/-20 round the rectangle as programmed and back (X and Y: MCS = PCS)
  const std::vector<std::pair<double, double>> want = {{-20, -20}, {0, 0}, {0, 40}, {60, 40}, {60, 0}, {0, 0}, {-20, -20}};
  const auto got = xy(runs[0], false);
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t k = 0; k < want.size(); ++k) {
    EXPECT_NEAR(got[k].first, want[k].first, 1e-4) << k;
    EXPECT_NEAR(got[k].second, want[k].second, 1e-4) << k;
  }
  EXPECT_EQ(xy(runs[0], true), got);
  EXPECT_EQ(runs[0]["lines"], json::array({17, 22}));  // N40 .. N90
  // Z-2 in program coordinates; the machine's Z carries the tool length of D1 (100 mm)
  for (const json& z : runs[0]["pz"]) EXPECT_NEAR(z.get<double>(), -2, 1e-4);
  for (const json& z : runs[0]["z"]) EXPECT_NEAR(z.get<double>(), 98, 1e-4);
  // 2: the R8 corners as arcs (chords of at most 5 deg): every point between (0,32) and (8,40) on the
  // circle about (8,32), N130 G2 X8 Y40 R8
  int on_arc = 0;
  for (const auto& [x, y] : xy(runs[1], false))
    if (x > 1e-6 && x < 8 - 1e-6 && y > 32 + 1e-6) {
      ++on_arc;
      EXPECT_NEAR(std::hypot(x - 8, y - 32), 8, 1e-3);
    }
  EXPECT_EQ(on_arc, 17);  // 90 deg in 18 chords of 5 deg
  // 3: the pocket from its start 30/20, corners as programmed
  const auto pocket = xy(runs[2], false);
  ASSERT_GE(pocket.size(), 7u);
  EXPECT_NEAR(pocket[0].first, 30, 1e-4);
  EXPECT_NEAR(pocket[0].second, 20, 1e-4);
  EXPECT_NEAR(pocket[2].first, 60, 1e-4);
  EXPECT_NEAR(pocket[2].second, 0, 1e-4);
  // the tool centre stays 5 mm inside the pocket's wall X60: at most X55 while Z is down
  const json& ch = d["channels"][0];
  double x_max = -1e9;
  for (std::size_t i = 0; i < ch["x"].size(); ++i)
    if (ch["line"][i] >= 37 && ch["line"][i] <= 43) x_max = std::max(x_max, ch["x"][i].get<double>());
  EXPECT_NEAR(x_max, 55, 1e-3);
}

TEST(ReportFrames, OverrideMarksAndFeedholdSpansFromThePlcScenario) {
  const auto dir = temp_dir("report_hold_src");
  std::ofstream(dir / "p.nc") << "N10 G17 G90 G0 X0 Y0 Z0\nN20 G1 X100 F3000\nN30 M30\n";
  std::ofstream(dir / "p.plc") << "0.5 feedhold on\n1.3 feedhold off\n1.5 feed_override 50\n";
  const std::string ex = root() + "/examples/mill";
  const json d = report_of("report_hold", ex + " " + (dir / "p.nc").string() + " --plc " + (dir / "p.plc").string());
  int holds = 0;
  for (const json& w : d["waits"])
    if (w["reason"] == "feedhold") {
      ++holds;
      EXPECT_EQ(w["ch"], 1);
      EXPECT_EQ(w["line"], 2);  // N20
      EXPECT_NEAR(w["t0"].get<double>(), 0.5, 1e-6);
      EXPECT_NEAR(w["t1"].get<double>(), 1.3, 1e-6);
    }
  EXPECT_EQ(holds, 1);
  int overrides = 0;
  for (const json& m : d["marks"])
    if (m["kind"] == "override") {
      ++overrides;
      EXPECT_EQ(m["ch"], 1);
      EXPECT_NEAR(m["t"].get<double>(), 1.5, 1e-6);
      EXPECT_EQ(m["text"], "feed override 50 %");
    }
  EXPECT_EQ(overrides, 1);
  // 100 mm at 50 mm/s, 0.8 s held, after 1.5 s at half speed: the run takes longer than 2.8 s
  EXPECT_GT(d["meta"]["end_s"].get<double>(), 2.8);
  // spindle.plc: S1's override 50 % from the start, one mark at 0 s on S1
  const json s = report_of("report_spdl_ovr", ex + " " + ex + "/spindle.nc --plc " + ex + "/spindle.plc");
  int s1 = 0;
  for (const json& m : s["marks"])
    if (m["kind"] == "override") {
      ++s1;
      EXPECT_EQ(m["spindle"], 0);
      EXPECT_EQ(m["ch"], 0);
      EXPECT_NEAR(m["t"].get<double>(), 0, 1e-9);
      EXPECT_EQ(m["text"], "spindle override 50 %");
    }
  EXPECT_EQ(s1, 1);
  // a spindle feedhold is shaded on that spindle's plot (no channel)
  const auto dir2 = temp_dir("report_spdl_hold_src");
  std::ofstream(dir2 / "p.plc") << "0.0 override S1 50\n1.0 spindle_feedhold S1 on\n1.5 spindle_feedhold S1 off\n";
  const json h = report_of("report_spdl_hold", ex + " " + ex + "/spindle.nc --plc " + (dir2 / "p.plc").string());
  int spindle_holds = 0;
  for (const json& w : h["waits"])
    if (w["reason"] == "feedhold") {
      ++spindle_holds;
      EXPECT_EQ(w["ch"], 0);
      EXPECT_EQ(w["spindle"], "S1");
      EXPECT_NEAR(w["t0"].get<double>(), 1.0, 1e-6);
      EXPECT_NEAR(w["t1"].get<double>(), 1.5, 1e-6);
    }
  EXPECT_EQ(spindle_holds, 1);
}

}  // namespace
}  // namespace nck::app
