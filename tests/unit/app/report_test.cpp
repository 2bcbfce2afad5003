// `nck run --report`: the page is one offline file and carries the run's
// data; the numbers are checked against the programs, worked out by hand.
// (tests/browser/ checks the page itself in chromium.)
#include <gtest/gtest.h>

#include <map>

#include <fmt/format.h>
#include <numbers>

#include "cli_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;
using nlohmann::json;

// The JSON the page draws from (the <script id="nck-data"> element).
json report_data(const std::string& html) {
  const std::string open = "<script id=\"nck-data\" type=\"application/json\">";
  const std::size_t a = html.find(open);
  if (a == std::string::npos) return json();
  const std::size_t b = html.find("</script>", a);
  return json::parse(html.substr(a + open.size(), b - a - open.size()));
}

json run_report(const std::string& name, const std::string& args, int want_exit = 0) {
  const auto dir = temp_dir(name);
  const CliResult r = run_nck("run " + args + " --report " + (dir / "r.html").string());
  EXPECT_EQ(r.exit_code, want_exit) << r.output;
  const std::string html = read_file(dir / "r.html");
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("</html>"), std::string::npos);
  // offline: uPlot is inlined, nothing is loaded
  EXPECT_NE(html.find("uPlot"), std::string::npos);
  EXPECT_NE(html.find("window.NckView3d="), std::string::npos);  // the 3D view's bundle (three.js)
  EXPECT_NE(html.find("Three.js Authors"), std::string::npos);    // with three's licence notice
  EXPECT_EQ(html.find(" src="), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
  return report_data(html);
}

const json* series(const json& d, const std::string& name, std::size_t* index = nullptr) {
  for (std::size_t i = 0; i < d["series"].size(); ++i)
    if (d["series"][i]["name"] == name) {
      if (index) *index = i;
      return &d["series"][i];
    }
  return nullptr;
}

double series_max(const json& d, const std::string& name) {
  std::size_t i = 0;
  if (!series(d, name, &i)) return NAN;
  double m = -1e300;
  for (const json& v : d["ts"]["v"][i]) m = std::max(m, v.get<double>());
  return m;
}

double series_min(const json& d, const std::string& name) {
  std::size_t i = 0;
  if (!series(d, name, &i)) return NAN;
  double m = 1e300;
  for (const json& v : d["ts"]["v"][i]) m = std::min(m, v.get<double>());
  return m;
}

TEST(Report, SpindleRunShowsSetAndActualSpeedAndTheWaitsWithTheirReason) {
  const std::string ex = root() + "/examples/mill";
  const json d = run_report("report_spindle", ex + " " + ex + "/spindle.nc --plc " + ex + "/spindle.plc");
  ASSERT_TRUE(d.is_object());
  EXPECT_EQ(d["meta"]["machine"], ex);
  EXPECT_EQ(d["meta"]["plc"], ex + "/spindle.plc");
  EXPECT_EQ(d["meta"]["end"], "M30");
  ASSERT_NE(series(d, "S1 set"), nullptr);
  ASSERT_NE(series(d, "S1 actual"), nullptr);
  EXPECT_EQ((*series(d, "S1 set"))["unit"], "rpm");
  EXPECT_EQ((*series(d, "path velocity"))["unit"], "mm/min");
  // S1000 at 50 % override, then 1000 (G167), then S3000 at 50 %: 1500 rpm
  EXPECT_NEAR(series_max(d, "S1 set"), 1500, 1e-6);
  EXPECT_NEAR(series_max(d, "S1 actual"), 1500, 1.0);
  // N30 G1 X50 F3000 (line 10): between its block event and the next one
  // the path velocity reaches 3000 mm/min and no more (G0 N10 ran faster)
  double t_n30 = -1, t_n40 = -1;
  for (const json& e : d["events"])
    if (e["ev"] == "block") {
      if (e["line"] == 10) t_n30 = e["t"].get<double>();
      if (e["line"] == 11) t_n40 = e["t"].get<double>();
    }
  ASSERT_GT(t_n40, t_n30);
  std::size_t v = 0;
  ASSERT_NE(series(d, "path velocity", &v), nullptr);
  double v_max = 0;
  for (std::size_t i = 0; i < d["ts"]["t"].size(); ++i) {
    const double t = d["ts"]["t"][i].get<double>();
    if (t >= t_n30 && t < t_n40) v_max = std::max(v_max, d["ts"]["v"][v][i].get<double>());
  }
  EXPECT_NEAR(v_max, 3000, 0.5);
  EXPECT_GT(series_max(d, "path velocity"), 3000);
  // N20 S1000 M3 (line 9): the channel waits for S1's speed reached, MVS_SVS
  bool found = false;
  for (const json& w : d["waits"])
    if (w["reason"] == "speed_reached" && w["spindle"] == "S1" && w["line"] == 9) {
      found = true;
      EXPECT_GT(w["t1"].get<double>(), w["t0"].get<double>());
      EXPECT_NE(w["sync"].get<std::string>().find("MVS_SVS"), std::string::npos);
      EXPECT_EQ(d["lines"][fmt::format("{}:9", w["file"].get<int>())], "N20 S1000 M3                     ; S1 to 1000 rpm (500 at 50 %); the next motion waits");
    }
  EXPECT_TRUE(found) << d["waits"].dump();
  // backplot: X0..50, Y0..30, Z0..20 (start at the machine zero)
  const json& ch = d["channels"][0];
  EXPECT_EQ(ch["plane"], "XY");
  EXPECT_EQ(ch["min"], json::array({0, 0, 0}));
  EXPECT_EQ(ch["max"], json::array({50, 30, 20}));
}

TEST(Report, ContourBackplotHasTheProgramsExtentsRapidsAndLines) {
  const std::string ex = root() + "/examples/mill";
  const json d = run_report("report_contour", ex + " " + ex + "/contour.nc");
  const json& ch = d["channels"][0];
  // pocket X +-40, bolt circle r 30 at 60 deg steps: Y +-25.981; Z -3 .. 2 + 20
  EXPECT_NEAR(ch["min"][0].get<double>(), -40, 1e-3);
  EXPECT_NEAR(ch["max"][0].get<double>(), 40, 1e-3);
  EXPECT_NEAR(ch["min"][1].get<double>(), -30 * std::sin(std::numbers::pi / 3), 1e-3);
  EXPECT_NEAR(ch["max"][1].get<double>(), 30 * std::sin(std::numbers::pi / 3), 1e-3);
  EXPECT_NEAR(ch["min"][2].get<double>(), -3, 1e-3);
  EXPECT_NEAR(ch["max"][2].get<double>(), 22, 1e-3);
  // N170 G0 X15 Y0 (line 31) ends at X15 Y0 Z5 as a rapid move
  bool rapid_to_helix = false;
  for (std::size_t i = 0; i < ch["x"].size(); ++i)
    if (ch["line"][i] == 31 && std::abs(ch["x"][i].get<double>() - 15) < 1e-3 && std::abs(ch["y"][i].get<double>()) < 1e-3)
      rapid_to_helix = ch["rapid"][i] == 1;
  EXPECT_TRUE(rapid_to_helix);
  // every arc point of the helix (N190 G3, line 33) lies on the r 15 circle
  int helix_points = 0;
  for (std::size_t i = 0; i < ch["x"].size(); ++i)
    if (ch["line"][i] == 33) {
      ++helix_points;
      EXPECT_NEAR(std::hypot(ch["x"][i].get<double>(), ch["y"][i].get<double>()), 15, 1e-3);
      EXPECT_EQ(ch["rapid"][i], 0);
    }
  EXPECT_GE(helix_points, 40);  // drawn as an arc, not a chord
  // cycle time: the dwell G4 X0.2 (line 6) of HOLE runs six times, 0.2 s each
  bool dwell = false;
  for (const json& b : d["summary"]["blocks"])
    if (b["line"] == 6) {
      dwell = true;
      EXPECT_EQ(b["count"], 6);
      EXPECT_NEAR(b["time_s"].get<double>(), 1.2, 6 * 0.0011);
    }
  EXPECT_TRUE(dwell);
  double tools_s = 0;
  for (const json& t : d["summary"]["tools"]) tools_s += t["time_s"].get<double>();
  EXPECT_NEAR(tools_s, d["meta"]["end_s"].get<double>(), 0.0011);
  // no spindle turns in contour.nc
  EXPECT_DOUBLE_EQ(series_max(d, "S1 set"), 0);
}

// Two spindles waited for at once: each wait ends with its own spindle (S1
// at 0.326 s, S2 at 0.54 s, not at program end), and the time waited for
// speed counts once where they overlap: 0.54 s, not 0.54 + 0.316 s.
TEST(Report, WaitsForTwoSpindlesAtOnceArePairedPerSpindleAndCountedOnce) {
  const auto dir = temp_dir("report_two_waits");
  const auto p = write(dir / "p.nc", "N10 S1000 M3 S2[M4 REV3000]\nN20 G4 X0.1\nN30 M30\n");
  const CliResult r = run_nck("run " + mill() + " " + p.string() + " --report " + (dir / "r.html").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("speed_reached 0.540 s"), std::string::npos) << r.output;
  const json d = report_data(read_file(dir / "r.html"));
  std::map<std::string, double> ends;
  for (const json& w : d["waits"])
    if (w["reason"] == "speed_reached") ends[w["spindle"].get<std::string>()] = w["t1"].get<double>();
  EXPECT_NEAR(ends["S1"], 0.326, 1e-9) << d["waits"].dump();
  EXPECT_NEAR(ends["S2"], 0.54, 1e-9) << d["waits"].dump();
}

// The twin-spindle machine's channel has X, Y1, Z1 (no Y or Z): the
// backplot takes its first linear axes, so it is not empty.
TEST(Report, BackplotTakesTheFirstLinearAxesWithoutXyzNames) {
  const std::string twin = root() + "/examples/twin-spindle";
  const json d = run_report("report_twin", twin + " " + twin + "/twin.nc");
  const json& ch = d["channels"][0];
  EXPECT_EQ(ch["has"], json::array({true, true, true})) << ch.dump().substr(0, 400);
  EXPECT_GT(ch["x"].size(), 2u);
}

TEST(Report, LatheShowsTheZxPlaneAndTwoChannelsOneBackplotEach) {
  const std::string lathe = root() + "/examples/lathe";
  const json l = run_report("report_lathe", lathe + " " + lathe + "/turn.nc");
  EXPECT_EQ(l["channels"][0]["plane"], "XZ");  // G18
  EXPECT_EQ(l["channels"][0]["has"], json::array({true, false, true}));
  EXPECT_EQ(l["channels"][0]["min"][2], -45);
  EXPECT_EQ(l["channels"][0]["max"][0], 30);
  const std::string two = root() + "/examples/two-channel";
  const json t = run_report("report_two", two + " " + two + "/channel1.nc " + two + "/channel2.nc");
  ASSERT_EQ(t["channels"].size(), 2u);
  EXPECT_EQ(t["channels"][0]["max"], json::array({20, 20, 5}));
  EXPECT_EQ(t["channels"][1]["min"], json::array({-30, 0, -10}));
  EXPECT_NE(series(t, "2.path velocity"), nullptr);
}

// path.a and path.j are --trace-columns' PathDerivatives, sampled as min/max
// envelopes: their extremes are the trace's extremes over every cycle.
TEST(Report, PathAccelerationAndJerkHaveTheTracesExtremes) {
  const std::string ex = root() + "/examples/mill";
  const auto dir = temp_dir("report_slope");
  const CliResult r = run_nck("run " + ex + " " + ex + "/slope.nc --report " + (dir / "r.html").string() + " --trace " +
                              (dir / "t.csv").string() + " --trace-columns path.a,path.j");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const json d = report_data(read_file(dir / "r.html"));
  ASSERT_NE(series(d, "path.a"), nullptr);
  EXPECT_EQ((*series(d, "path.a"))["unit"], "mm/s²");
  EXPECT_EQ((*series(d, "path.j"))["unit"], "mm/s³");
  EXPECT_EQ((*series(d, "path.a"))["panel"], (*series(d, "path.j"))["panel"]);
  const auto lines = split(read_file(dir / "t.csv"), '\n');
  const auto head = split(lines[0], ',');
  const auto col_a = std::find(head.begin(), head.end(), "path.a") - head.begin();
  double a_min = 0, a_max = 0, j_min = 0, j_max = 0;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const auto c = split(lines[i], ',');
    const double a = std::stod(c[col_a]), j = std::stod(c[col_a + 1]);
    a_min = std::min(a_min, a), a_max = std::max(a_max, a), j_min = std::min(j_min, j), j_max = std::max(j_max, j);
  }
  EXPECT_GT(a_max, 1000);  // the mill accelerates at 2500 mm/s² (a_beschl)
  // the report keeps floats to 0.1 mm/s² and 1 mm/s³
  EXPECT_NEAR(series_max(d, "path.a"), a_max, 0.1 + 1e-6 * a_max);
  EXPECT_NEAR(series_min(d, "path.a"), a_min, 0.1 - 1e-6 * a_min);
  EXPECT_NEAR(series_max(d, "path.j"), j_max, 1 + 1e-6 * j_max);
  EXPECT_NEAR(series_min(d, "path.j"), j_min, 1 - 1e-6 * j_min);
}

// The 3D view's box: each channel's software limits of its backplot axes
// (x.lis, y.lis, z.lis: kenngr.swe_neg/swe_pos), null for an axis it lacks.
TEST(Report, ChannelsCarryTheSoftwareLimitsOfTheirBackplotAxes) {
  const std::string two = root() + "/examples/two-channel";
  const json t = run_report("report_limits", two + " " + two + "/channel1.nc " + two + "/channel2.nc");
  ASSERT_EQ(t["channels"].size(), 2u);
  EXPECT_EQ(t["channels"][0]["limits"], json::parse(R"({"min":[-500,-400,-400],"max":[500,400,200]})"));
  EXPECT_EQ(t["channels"][1]["limits"], json::parse(R"({"min":[-100,null,-500],"max":[300,null,50]})"));
}

TEST(Report, AbortedRunListsTheErrorWithItsLineText) {
  const auto dir = temp_dir("report_err_src");
  std::ofstream(dir / "bad.nc") << "%bad\nN10 G1 X20 F0\nN20 M30\n";
  const json d = run_report("report_err", root() + "/examples/mill " + (dir / "bad.nc").string(), 1);
  ASSERT_EQ(d["diagnostics"].size(), 1u);
  EXPECT_EQ(d["diagnostics"][0]["id"], 930002);
  EXPECT_EQ(d["diagnostics"][0]["line"], 2);
  EXPECT_EQ(d["meta"]["errors"], 1);
  EXPECT_EQ(d["meta"]["exit_code"], 1);
  EXPECT_EQ(d["lines"]["0:2"], "N10 G1 X20 F0");
}

}  // namespace
}  // namespace nck::app
