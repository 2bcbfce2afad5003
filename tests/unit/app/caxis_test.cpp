// C-axis machining end to end through the nck binary (#CAX, #FACE, #CYL;
// FCT-S1 §2.8.8): machine positions X / Z / C in the trace against values
// computed by hand, the spindle's axis mode, and the errors with their IDs.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "cli_helpers.hpp"

namespace nck::app::testing {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

// A trace with its columns by name; rows by time in ms.
struct Trace {
  std::map<std::string, std::size_t> col;
  std::vector<std::vector<double>> rows;
  double at(std::size_t row, const std::string& name) const { return rows.at(row).at(col.at(name)); }
};

Trace read_trace(const std::filesystem::path& file) {
  Trace t;
  const auto lines = split(read_file(file), '\n');
  const auto head = split(lines.at(0), ',');
  for (std::size_t i = 0; i < head.size(); ++i) t.col[head[i]] = i;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    std::vector<double> r;
    for (const std::string& v : split(lines[i], ',')) r.push_back(std::stod(v));
    t.rows.push_back(r);
  }
  return t;
}

// The trace row index at which block N starts (the cycle before it: where
// everything before it ended) and the row where it is over (next block's start).
std::map<long, std::size_t> block_rows(const std::filesystem::path& events) {
  std::map<long, std::size_t> out;
  for (const nlohmann::json& e : read_jsonl(events))
    if (e["ev"] == "block" && !e["n"].is_null()) {
      const long ms = std::lround(e["t"].get<double>() * 1000);
      out[e["n"].get<long>()] = ms == 0 ? 0 : static_cast<std::size_t>(ms - 1);
    }
  return out;
}

struct MillRun {
  CliResult r;
  Trace trace;
  std::map<long, std::size_t> start;  // N -> row before the block starts
  std::vector<nlohmann::json> events;
};

MillRun run_mill(const std::string& program, const std::string& name) {
  const auto dir = temp_dir(name);
  MillRun x;
  x.r = run_example("mill", program, dir);
  x.trace = read_trace(dir / "t.csv");
  x.start = block_rows(dir / "e.jsonl");
  x.events = read_jsonl(dir / "e.jsonl");
  return x;
}

// A program of its own on the mill (the example machine, unchanged).
CliResult run_program(const std::string& name, const std::string& text, const std::filesystem::path& dir,
                      const std::string& machine = "") {
  std::ofstream(dir / (name + ".nc")) << text;
  const std::string m = machine.empty() ? root() + "/examples/mill" : machine;
  return run_nck("run " + m + " " + (dir / (name + ".nc")).string() + " --events " + (dir / "e.jsonl").string() +
                 " --trace " + (dir / "t.csv").string() + " --final " + (dir / "f.json").string());
}

// A copy of the mill with `from` replaced by `to` in one list.
PatchedMachine replaced_in_example(const std::string& name, const std::string& file, const std::string& from,
                                   const std::string& to) {
  PatchedMachine m = patched_example("mill", name, file, "");
  std::string text = read_file(m.dir / file);
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  std::ofstream(m.dir / file) << text;
  return m;
}

nlohmann::json first_error(const std::filesystem::path& events) {
  for (const nlohmann::json& e : read_jsonl(events))
    if (e["ev"] == "error") return e;
  return {};
}

TEST(CAxis, MillExampleMachinePositionsOnTheFace) {
  const MillRun x = run_mill("caxis.nc", "cax_face");
  ASSERT_EQ(x.r.exit_code, 0) << x.r.output;
  const Trace& t = x.trace;
  ASSERT_TRUE(t.col.contains("C"));
  ASSERT_TRUE(t.col.contains("S1.pos"));
  // Where each block ended = the row before the next block starts.
  auto end_of = [&](long n) {
    const long next = std::next(x.start.find(n))->first;
    return x.start.at(next);
  };
  // C moves with S1's own gear-stage dynamics (cax_gear_stage 1): G0 C90
  // at rapid_mm_s 3000 deg/s and rapid_accel_mm_s2 20000 deg/s^2 never reaches full
  // speed (that takes 225 deg): 2 * sqrt(45 / (20000 / 2)) = 0.134 s.
  EXPECT_NEAR(static_cast<double>(x.start.at(50) - x.start.at(40)) * 1e-3, 2.0 * std::sqrt(45.0 / 10000.0), 0.003);
  // N50: C does not count for the path length: 20 mm of X at F600
  // (10 mm/s) take 2 s plus X's ramps (accel_mm_s2 2500: 4 ms).
  EXPECT_NEAR(static_cast<double>(x.start.at(60) - x.start.at(50)) * 1e-3, 2.004, 0.003);
  // N40 G0 C90; N50 G1 X20 C180 (C in degrees, the spindle follows).
  EXPECT_NEAR(t.at(end_of(40), "C"), 90.0, 1e-6);
  EXPECT_NEAR(t.at(end_of(40), "S1.pos"), 90.0, 1e-3);
  EXPECT_NEAR(t.at(end_of(50), "X"), 20.0, 1e-6);
  EXPECT_NEAR(t.at(end_of(50), "C"), 180.0, 1e-6);
  // N80 X10 C-10 on the face: radius 10*sqrt(2), angle -45 deg = 315 deg
  // reached from 180 turning +135 deg (the shorter way round the centre).
  const double r = 10.0 * std::numbers::sqrt2;
  EXPECT_NEAR(t.at(end_of(80), "X"), r, 1e-4);
  EXPECT_NEAR(t.at(end_of(80), "C"), 315.0, 1e-4);
  EXPECT_NEAR(t.at(end_of(80), "S1.pos"), 315.0, 1e-3);
  // The square: each side turns C by +90 deg, corners at the same radius.
  const double corners[] = {405, 495, 585, 675};
  for (int i = 0; i < 4; ++i) {
    const long n = 100 + 10 * i;
    EXPECT_NEAR(t.at(end_of(n), "X"), r, 1e-4) << "N" << n;
    EXPECT_NEAR(t.at(end_of(n), "C"), corners[i], 1e-4) << "N" << n;
    EXPECT_NEAR(t.at(end_of(n), "S1.pos"), std::fmod(corners[i], 360.0), 1e-3) << "N" << n;
  }
  // Mid-side the tool is nearest the centre: X = 10 on the side's normal
  // (N100 passes (10, 0): C = 360).
  double x_min = 1e9, c_there = 0;
  for (std::size_t i = end_of(90) + 1; i <= end_of(100); ++i)
    if (t.at(i, "X") < x_min) {
      x_min = t.at(i, "X");
      c_there = t.at(i, "C");
    }
  EXPECT_NEAR(x_min, 10.0, 1e-3);
  EXPECT_NEAR(c_there, 360.0, 0.1);
  // Every row on the face: the machine point is the programmed Cartesian
  // point, so X cos C / X sin C stay on the square's sides.
  for (std::size_t i = end_of(90) + 1; i <= end_of(130); ++i) {
    const double px = t.at(i, "X") * std::cos(t.at(i, "C") / kDegPerRad);
    const double py = t.at(i, "X") * std::sin(t.at(i, "C") / kDegPerRad);
    const double off_side = std::min(std::abs(std::abs(px) - 10.0), std::abs(std::abs(py) - 10.0));
    ASSERT_LT(off_side, 1e-6) << "row " << i;
    ASSERT_LE(std::max(std::abs(px), std::abs(py)), 10.0 + 1e-6) << "row " << i;
  }
  // N150 X-20 C0: (-20, 0), C 675 - 135 = 540; N160 through the centre: C
  // stays 540 all the way while X runs 20 -> -20.
  EXPECT_NEAR(t.at(end_of(150), "X"), 20.0, 1e-4);
  EXPECT_NEAR(t.at(end_of(150), "C"), 540.0, 1e-4);
  for (std::size_t i = end_of(150) + 1; i <= end_of(160); ++i) ASSERT_NEAR(t.at(i, "C"), 540.0, 1e-6) << "row " << i;
  EXPECT_NEAR(t.at(end_of(160), "X"), -20.0, 1e-6);
  // After #FACE OFF / #CAX OFF the machine stays where it was; outside
  // C-axis mode the C column shows the spindle's position (540 = 180).
  EXPECT_NEAR(t.rows.back()[t.col.at("X")], -20.0, 1e-6);
  EXPECT_NEAR(t.rows.back()[t.col.at("C")], 180.0, 1e-3);
  EXPECT_NEAR(t.rows.back()[t.col.at("S1.pos")], 180.0, 1e-3);
}

TEST(CAxis, SpindleReportsAxisModeAndBack) {
  const MillRun x = run_mill("caxis.nc", "cax_events");
  ASSERT_EQ(x.r.exit_code, 0) << x.r.output;
  std::vector<std::string> modes;
  for (const nlohmann::json& e : x.events)
    if (e["ev"] == "spindle" && e["spindle"] == "S1") modes.push_back(e["mode"]);
  ASSERT_GE(modes.size(), 2u);
  EXPECT_NE(std::find(modes.begin(), modes.end(), "axis"), modes.end());
  EXPECT_EQ(modes.back(), "stop");  // #CAX OFF: a spindle at standstill again
}

TEST(CAxis, FaceSpeedNearTheCentreKeepsCWithinItsDynamics) {
  // A line passing the centre at 0.05 mm: C turns 180 deg there, at
  // 1/0.05 rad = 1145.9 deg per mm of path. At F6000 (100 mm/s) C would
  // need 114592 deg/s, more than S1's max_speed_mm_s (72000 deg/s); the path slows
  // so that C turns at most 45 deg per 1 ms cycle (docs/decisions.md, "C axis"), and
  // the machine point stays on the programmed line.
  const auto dir = temp_dir("cax_near");
  const CliResult r = run_program("near", R"(N10 G90 G0 X0 Y0 Z50
N20 M5
N30 #CAX [S, C]
N40 #FACE [X, C]
N50 G0 X30 C0.05
N60 G1 X-30 C0.05 F6000
N70 #FACE OFF
N80 #CAX OFF
N90 M30
)", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Trace t = read_trace(dir / "t.csv");
  const auto rows = block_rows(dir / "e.jsonl");
  const std::size_t end = rows.at(70);  // N60 is over
  double max_step = 0;
  std::size_t rows_near = 0;
  for (std::size_t i = rows.at(60) + 1; i <= end; ++i) {
    const double x = t.at(i, "X"), c = t.at(i, "C");
    max_step = std::max(max_step, std::abs(c - t.at(i - 1, "C")));
    const double py = x * std::sin(c / kDegPerRad);
    {
      ASSERT_NEAR(py, 0.05, 1e-6) << "row " << i;
      ASSERT_GE(x, 0.05 - 1e-9) << "row " << i;  // X never changes sign on a near miss
    }
    if (std::abs(x) < 1.0) ++rows_near;
  }
  EXPECT_LE(max_step, 45.0 + 1e-6);
  EXPECT_GT(max_step, 1.0);  // it does turn fast there
  // The last 2 mm around the centre take more than 2 mm / 100 mm/s = 20 cycles.
  EXPECT_GT(rows_near, 20u);
  // End: (-30, 0.05) at 180 - atan2(0.05, 30) deg, X = hypot(30, 0.05).
  EXPECT_NEAR(t.at(end, "C"), 180.0 - std::atan2(0.05, 30.0) * kDegPerRad, 1e-6);
  EXPECT_NEAR(t.at(end, "X"), std::hypot(30.0, 0.05), 1e-6);
}

TEST(CAxis, MillExampleSlotAroundTheCylinder) {
  const MillRun x = run_mill("cylinder.nc", "cax_cyl");
  ASSERT_EQ(x.r.exit_code, 0) << x.r.output;
  const Trace& t = x.trace;
  auto end_of = [&](long n) { return x.start.at(std::next(x.start.find(n))->first); };
  // C(mm) * 180 / (pi * 60) deg.
  const double k = 180.0 / (std::numbers::pi * 60.0);
  EXPECT_NEAR(t.at(end_of(70), "X"), 58.0, 1e-6);
  EXPECT_NEAR(t.at(end_of(70), "C"), 0.0, 1e-6);
  EXPECT_NEAR(t.at(end_of(80), "C"), 100 * k, 1e-6);  // 95.4930
  EXPECT_NEAR(t.at(end_of(80), "C"), 95.49296585513720, 1e-6);
  EXPECT_NEAR(t.at(end_of(90), "Z"), 40.0, 1e-6);
  EXPECT_NEAR(t.at(end_of(90), "C"), 143.2394487827058, 1e-6);
  EXPECT_NEAR(t.at(end_of(100), "Z"), 10.0, 1e-6);
  EXPECT_NEAR(t.at(end_of(100), "C"), 47.74648292756860, 1e-6);
  EXPECT_NEAR(t.at(end_of(100), "S1.pos"), 47.7465, 1e-3);
  // On the diagonal N90 the developed slot is a straight line: C(mm) and Z
  // change in the ratio 50 : 30.
  for (std::size_t i = end_of(80) + 1; i <= end_of(90); ++i) {
    const double c_mm = t.at(i, "C") / k;
    ASSERT_NEAR(c_mm - 100.0, (t.at(i, "Z") - 10.0) * 50.0 / 30.0, 1e-5) << "row " << i;  // trace: 6 decimals
  }
}

TEST(CAxis, FaceCircleAroundTheCentreAndFinalStateInCartesian) {
  // G3 full circle of radius 15 about the face's centre: X stays 15, C runs
  // 0 -> 360. The program ends under #FACE at (10, 10): --final shows the
  // machine X 14.1421 / C 45 (405 until the program end left C-axis mode)
  // and the program (Cartesian) values 10 / 10.
  const auto dir = temp_dir("cax_circle");
  const CliResult r = run_program("circle", R"(N10 G90 G0 X0 Y0 Z50
N20 M5
N30 #CAX [S, C]
N40 #FACE [X, C]
N50 G0 X15 C0
N60 G3 X15 C0 I-15 J0 F600
N70 G1 X10 C10
N80 M30
)", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Trace t = read_trace(dir / "t.csv");
  const auto rows = block_rows(dir / "e.jsonl");
  EXPECT_NEAR(t.at(rows.at(60), "X"), 15.0, 1e-6);
  EXPECT_NEAR(t.at(rows.at(60), "C"), 0.0, 1e-6);
  double c_max = 0;
  for (std::size_t i = rows.at(60) + 1; i <= rows.at(70); ++i) {
    ASSERT_NEAR(t.at(i, "X"), 15.0, 1e-5) << "row " << i;
    ASSERT_GE(t.at(i, "C"), t.at(i - 1, "C") - 1e-9) << "row " << i;  // counter-clockwise only
    c_max = std::max(c_max, t.at(i, "C"));
  }
  EXPECT_NEAR(t.at(rows.at(70), "C"), 360.0, 1e-5);
  // From (15, 0) at C 360 to (10, 10): 45 deg further.
  EXPECT_NEAR(t.at(rows.at(80), "C"), 405.0, 1e-5);
  EXPECT_NEAR(t.at(rows.at(80), "X"), 10.0 * std::numbers::sqrt2, 1e-5);
  // The program end ends C-axis mode: C shows the spindle (405 = 45 deg).
  EXPECT_NEAR(t.rows.back()[t.col.at("C")], 45.0, 1e-4);
  const nlohmann::json f = nlohmann::json::parse(read_file(dir / "f.json"));
  const nlohmann::json& axes = f["channels"][0]["axes"];
  EXPECT_NEAR(axes["X"]["mcs"].get<double>(), 10.0 * std::numbers::sqrt2, 1e-6);
  EXPECT_NEAR(axes["C"]["mcs"].get<double>(), 45.0, 1e-4);
  EXPECT_NEAR(axes["X"]["pcs"].get<double>(), 10.0, 1e-6);
  EXPECT_NEAR(axes["C"]["pcs"].get<double>(), 10.0, 1e-6);
}

TEST(CAxis, CylinderSeedExampleHalfCircleOnTheDevelopedSurface) {
  // TF5200's #CYL example: #CYL [Z, C, X60], G01 C100, G02 Z100 R50. From
  // (Z0, C100 mm) the clockwise half circle about (Z50, C100) passes
  // C 150 mm = 2.5 rad = 143.2394 deg at Z50 and ends at Z100, C 95.4930 deg.
  const auto dir = temp_dir("cax_cyl_seed");
  const CliResult r = run_program("cyl", R"(N10 G90 G0 X80 Y0 Z0
N20 M5
N30 #CAX
N40 G0 C0
N50 #CYL [Z, C, X60]
N60 G01 C100 F500
N70 G02 Z100 R50
N80 #CYL OFF
N90 #CAX OFF
N100 M30
)", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Trace t = read_trace(dir / "t.csv");
  const auto rows = block_rows(dir / "e.jsonl");
  const double k = 180.0 / (std::numbers::pi * 60.0);
  EXPECT_NEAR(t.at(rows.at(70), "C"), 95.49296585513720, 1e-5);
  double c_max = 0, z_at_max = 0;
  for (std::size_t i = rows.at(70) + 1; i <= rows.at(80); ++i) {
    // On the developed circle: (Z - 50)^2 + (C_mm - 100)^2 = 50^2.
    const double dz = t.at(i, "Z") - 50.0, dc = t.at(i, "C") / k - 100.0;
    ASSERT_NEAR(std::hypot(dz, dc), 50.0, 1e-4) << "row " << i;
    if (t.at(i, "C") > c_max) {
      c_max = t.at(i, "C");
      z_at_max = t.at(i, "Z");
    }
  }
  EXPECT_NEAR(c_max, 143.2394487827058, 1e-3);
  EXPECT_NEAR(z_at_max, 50.0, 0.1);
  EXPECT_NEAR(t.at(rows.at(80), "Z"), 100.0, 1e-6);
  EXPECT_NEAR(t.at(rows.at(80), "C"), 95.49296585513720, 1e-5);
}

TEST(CAxis, ErrorsWithTheirIds) {
  struct Case {
    const char* name;
    const char* program;
    int id;
    int line;
  };
  const Case cases[] = {
      {"m3", "G0 X0\nM5\n#CAX [S, C]\nM3 S100\nM30\n", 930210, 4},
      {"m19", "M5\n#CAX\nM19 S.POS=10 S100\nM30\n", 930210, 3},
      {"c_without_cax", "G0 X0\nG1 C10 F100\nM30\n", 930211, 2},
      {"face_without_cax", "#FACE [X, C]\nM30\n", 20886, 1},
      {"cax_off_under_face", "M5\n#CAX\n#FACE [X, C]\n#CAX OFF\nM30\n", 20893, 4},
      {"cyl_off_missing", "M5\n#CAX\n#CYL [Z, C, X60]\n#CAX OFF\nM30\n", 20893, 4},
      {"face_wrong_axis", "M5\n#CAX\n#FACE [X, Y]\nM30\n", 930212, 3},
      {"face_default_name_after_other", "M5\n#CAX [S, Q]\n#FACE [X, C]\nM30\n", 930212, 3},
      {"cax_name_of_another_axis", "M5\n#CAX [S, Y]\nM30\n", 930212, 2},
      {"cax_no_axis_name", "M5\n#CAX [S, S2]\nM30\n", 930212, 2},
      {"not_main", "#CAX [S2, C]\nM30\n", 21175, 1},
      {"rotating", "M3 S500\nG4 X0.5\n#CAX\nM30\n", 950008, 3},
      {"plane", "M5\n#CAX\n#FACE [X, C]\nG18\nM30\n", 930214, 4},
  };
  for (const Case& c : cases) {
    const auto dir = temp_dir(std::string("cax_err_") + c.name);
    const CliResult r = run_program(c.name, c.program, dir);
    const nlohmann::json e = first_error(dir / "e.jsonl");
    ASSERT_FALSE(e.is_null()) << c.name << r.output;
    EXPECT_EQ(e["id"], c.id) << c.name << " " << e.dump();
    EXPECT_EQ(e["line"], c.line) << c.name;
    // The channel ends cleanly: an end event and a complete final state.
    bool ended = false;
    for (const nlohmann::json& x : read_jsonl(dir / "e.jsonl"))
      if (x["ev"] == "end") ended = x["reason"] == "error";
    EXPECT_TRUE(ended) << c.name;
    EXPECT_TRUE(nlohmann::json::accept(read_file(dir / "f.json"))) << c.name;
  }
}

TEST(CAxis, WrongAxisModeAndMissingTrafoId) {
  // Without axis_mode 0x0204 the spindle cannot become C: 21184.
  {
    const auto dir = temp_dir("cax_mode");
    const auto m = replaced_in_example("cax_mode_m", "s1.lis", "0x00000204", "0x00000004");
    const CliResult r = run_program("p", "M5\n#CAX [S, C]\nM30\n", dir, m.dir.string());
    const nlohmann::json e = first_error(dir / "e.jsonl");
    ASSERT_FALSE(e.is_null()) << r.output;
    EXPECT_EQ(e["id"], 21184);
    EXPECT_EQ(e["line"], 2);
  }
  // cax_face_id 2 needs trafo[i].id 14 for #FACE: 930213.
  {
    const auto dir = temp_dir("cax_trafo");
    const auto m = replaced_in_example("cax_trafo_m", "channel1.lis", "trafo[0].id                   14", "trafo[0].id                   15");
    const CliResult r = run_program("p", "M5\n#CAX [S, C]\n#FACE [X, C]\nM30\n", dir, m.dir.string());
    const nlohmann::json e = first_error(dir / "e.jsonl");
    ASSERT_FALSE(e.is_null()) << r.output;
    EXPECT_EQ(e["id"], 930213);
    EXPECT_EQ(e["line"], 3);
  }
  // The lathe variant: cax_face_id 1 with trafo[i].id 13 runs #FACE.
  {
    const auto dir = temp_dir("cax_lathe_face");
    const auto m = replaced_in_example("cax_lathe_m", "channel1.lis", "trafo[0].id                   14",
                                       "trafo[0].id                   13");
    std::string text = read_file(m.dir / "channel1.lis");
    const std::string from = "cax_face_id                   2";
    ASSERT_NE(text.find(from), std::string::npos);
    text.replace(text.find(from), from.size(), "cax_face_id                   1");
    std::ofstream(m.dir / "channel1.lis") << text;
    const CliResult r = run_program("p", R"(N10 M5
N20 #CAX [S, C]
N30 #FACE [X, C]
N40 G1 X0 C20 F600
N50 G1 X0 C-20
N60 #FACE OFF
N70 #CAX OFF
N80 M30
)", dir, m.dir.string());
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_TRUE(first_error(dir / "e.jsonl").is_null());
    const Trace t = read_trace(dir / "t.csv");
    const auto rows = block_rows(dir / "e.jsonl");
    // N40 leaves the centre towards +Y: C first turns 0 -> 90 with X at 0,
    // then X runs to 20: (0, 20) = X 20 at C 90.
    EXPECT_NEAR(t.at(rows.at(50), "X"), 20.0, 1e-6);
    EXPECT_NEAR(t.at(rows.at(50), "C"), 90.0, 1e-6);
    // N50 through the centre on a lathe: X never negative; at the centre C
    // turns half a turn (90 -> 270, the tie of both ways taken upwards)
    // while X is 0, then X runs out to 20 again.
    for (std::size_t i = 1; i <= rows.at(60); ++i) {
      ASSERT_GE(t.at(i, "X"), -1e-9) << "row " << i;
      if (t.at(i, "C") > 90.0 + 1e-6 && t.at(i, "C") < 270.0 - 1e-6) {
        ASSERT_NEAR(t.at(i, "X"), 0.0, 1e-9) << "row " << i;
      }
    }
    EXPECT_NEAR(t.at(rows.at(60), "X"), 20.0, 1e-6);
    EXPECT_NEAR(t.at(rows.at(60), "C"), 270.0, 1e-6);
    EXPECT_NEAR(t.at(rows.at(60), "S1.pos"), 270.0, 1e-3);
  }
}

}  // namespace
}  // namespace nck::app::testing
