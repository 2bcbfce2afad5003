// Cycle calls through `nck run` / `nck parse`: the example program's pecks
// and helix at hand-computed positions (trace), and each @-parameter rule
// with its error ID, file and line.
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>

#include "cli_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;
using nlohmann::json;

struct Row {
  double x, y, z;
};

std::vector<Row> trace_rows(const std::filesystem::path& dir) {
  std::vector<Row> out;
  const auto lines = split(read_file(dir / "t.csv"), '\n');
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const auto c = split(lines[i], ',');
    out.push_back({std::stod(c[1]), std::stod(c[2]), std::stod(c[3])});
  }
  return out;
}

// The values where `v` turns around (flat stretches ignored), in order.
std::vector<double> reversals(const std::vector<double>& v) {
  std::vector<double> out;
  int dir = 0;
  for (std::size_t i = 1; i < v.size(); ++i) {
    const double d = v[i] - v[i - 1];
    if (std::fabs(d) < 1e-9) continue;
    const int s = d > 0 ? 1 : -1;
    if (dir != 0 && s != dir) out.push_back(v[i - 1]);
    dir = s;
  }
  return out;
}

void expect_values(const std::vector<double>& got, const std::vector<double>& want, double tol,
                   const std::string& what) {
  ASSERT_EQ(got.size(), want.size()) << what << ": " << ::testing::PrintToString(got);
  for (std::size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(got[i], want[i], tol) << what << " #" << i;
}

// The tool-axis values while the plane axes stand at (a, b).
std::vector<double> at_position(const std::vector<Row>& rows, double x, double y) {
  std::vector<double> z;
  for (const Row& row : rows)
    if (std::fabs(row.x - x) < 1e-6 && std::fabs(row.y - y) < 1e-6) z.push_back(row.z);
  return z;
}

TEST(CyclesRun, ExampleDrillsPecksAndMillsTheHelixWhereComputed) {
  const auto dir = temp_dir("cycles-example");
  CliResult r = run_example("mill", "cycles.nc", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto rows = trace_rows(dir);
  // drill_deep @P1=2 @P2=-20 @P3=6 @P4=0.5 @P5=2 @P7=1: pecks to -4, -10,
  // -16, -20; chip breaks (+0.5) after pecks 1 and 3; after peck 2 out to
  // the reference plane 2 and back in to -10 + 1 (no turn there: it goes on
  // down to -16). The modal call drills at the call (X20 Y20) and after the
  // two motion blocks N50 (X40) and N60 (Y40).
  const std::vector<double> pecks{-4, -3.5, -10, 2, -16, -15.5, -20};
  for (auto [x, y] : {std::pair{20.0, 20.0}, {40.0, 20.0}, {40.0, 40.0}}) {
    const auto z = at_position(rows, x, y);
    ASSERT_FALSE(z.empty()) << x << "," << y;
    expect_values(reversals(z), pecks, 1e-3, fmt::format("hole X{} Y{}", x, y));
    EXPECT_NEAR(z.back(), 2.0, 1e-6);  // left at the reference plane
  }
  // After #DISABLE MODAL CYCLE, N80's move drills nothing: only those three
  // holes reach the final depth -20.
  int deep_rows_elsewhere = 0;
  for (const Row& row : rows)
    if (row.z < -19.999 && !(std::fabs(row.x - 20) < 1e-6 || std::fabs(row.x - 40) < 1e-6)) ++deep_rows_elsewhere;
  EXPECT_EQ(deep_rows_elsewhere, 0);

  // pocket_circ at X80 Y30, @P1=2 @P2=-10 @P3=10 @P4=3 @P5=4: path radius 7,
  // 12 mm in 3 turns of 4 mm, then one flat circle at -10. On the helix Z
  // falls 4 mm per 360 degrees from 2 at the start point X87 Y30.
  double turned_deg = 0, last_deg = 0;
  bool on_helix = false;
  int helix_rows = 0, bottom_rows = 0;
  std::vector<double> z_at_quarter;  // Z where the tool passes X80 Y37: 90, 450, 810 degrees and the bottom circle
  for (const Row& row : rows) {
    const double dx = row.x - 80, dy = row.y - 30;
    const double radius = std::hypot(dx, dy);
    if (!on_helix) {  // the start point X87 Y30 (the corner may be passed at speed: within a cycle's travel)
      on_helix = std::fabs(radius - 7) < 1e-3 && std::fabs(dy) < 0.05 && dx > 0;
      if (!on_helix) continue;
    }
    if (std::fabs(radius - 7) > 1e-3) {
      if (turned_deg > 1) break;  // left the circle: back to the centre
      continue;
    }
    double deg = std::atan2(dy, dx) * 180 / M_PI;
    double step = deg - last_deg;
    if (step < -180) step += 360;
    if (step > 180) step -= 360;
    turned_deg += step;
    last_deg = deg;
    if (turned_deg <= 3 * 360) {
      EXPECT_NEAR(row.z, 2 - 4 * turned_deg / 360, 2e-3) << "at " << turned_deg << " deg";
      ++helix_rows;
      if (std::fabs(row.x - 80) < 0.02 && dy > 0) z_at_quarter.push_back(row.z);
    } else {
      EXPECT_NEAR(row.z, -10, 1e-6);
      ++bottom_rows;
    }
    if (turned_deg > 3 * 360 && std::fabs(row.x - 80) < 0.02 && dy > 0) z_at_quarter.push_back(row.z);
  }
  EXPECT_GT(helix_rows, 1000);
  EXPECT_GT(bottom_rows, 100);
  EXPECT_NEAR(turned_deg, 4 * 360, 1.0);  // three helix turns and the bottom circle
  ASSERT_FALSE(z_at_quarter.empty());
  std::vector<double> quarters;  // one value per pass (rows within 0.02 mm of X80)
  for (double z : z_at_quarter)
    if (quarters.empty() || std::fabs(z - quarters.back()) > 0.5) quarters.push_back(z);
  expect_values(quarters, {1, -3, -7, -10}, 0.01, "Z at the quarter turns");

  // In G18 the same drilling cycle runs along Y (the tool axis of G18) at
  // X60 Z-5: @P1=55 @P2=40 @P3=6 @P4=0.5 @P5=3: pecks to 49, 43, 40 with
  // chip breaks to 49.5 and 43.5, then out to 55 (N150 goes on up to 60).
  std::vector<double> y;
  for (const Row& row : rows)
    if (std::fabs(row.x - 60) < 1e-6 && std::fabs(row.z + 5) < 1e-6) y.push_back(row.y);
  expect_values(reversals(y), {49, 49.5, 43, 43.5, 40}, 1e-3, "G18 hole");
  EXPECT_NEAR(y.back(), 60, 1e-6);
}

// ---------------------------------------------------------------- the rules

struct Program {
  std::filesystem::path dir;
  std::filesystem::path main;
};

Program write_program(const std::string& name, const std::string& main_text,
                      const std::vector<std::pair<std::string, std::string>>& files = {}) {
  Program p{temp_dir("cyc-" + name), {}};
  p.main = p.dir / "main.nc";
  std::ofstream(p.main) << main_text;
  for (const auto& [file, text] : files) {
    std::filesystem::create_directories((p.dir / file).parent_path());
    std::ofstream(p.dir / file) << text;
  }
  return p;
}

CliResult run_program(const Program& p, const std::string& args = "") {
  return run_nck("run " + root() + "/examples/mill " + p.main.string() + " --final " +
                 (p.dir / "final.json").string() + " " + args);
}

double final_pcs(const Program& p, const std::string& axis) {
  const json f = json::parse(read_file(p.dir / "final.json"));
  return f["channels"][0]["axes"][axis]["pcs"].get<double>();
}

TEST(CyclesRun, TransferParametersArePassedReadAndWrittenInsideTheCycle) {
  // @P1 and @P2 arrive evaluated in the caller (V.L.), the cycle writes @P1
  // (allowed inside it) and moves @X (= X in G17) there: 10 + 5 = 15.
  Program p = write_program("rw",
                            "#VAR\n V.L.A = 10\n#ENDVAR\nG17 G90 G0 X0 Y0 Z0\n"
                            "L CYCLE [NAME=c.ecy @P1=V.L.A @P2=2.5*2]\nM30\n",
                            {{"c.ecy", "@P1 = @P1 + @P2\nG1 @X=@P1 @Y=@P2 F1000\nM17\n"}});
  CliResult r = run_program(p);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NEAR(final_pcs(p, "X"), 15, 1e-6);
  EXPECT_NEAR(final_pcs(p, "Y"), 5, 1e-6);
}

TEST(CyclesRun, AtAxesFollowThePlane) {
  // One cycle, three planes: @X @Y @Z are X Y Z in G17, Z X Y in G18, Y Z X in G19.
  const std::string cyc = "G90 G1 @X=@P1 @Y=@P2 @Z=@P3 F3000\nM17\n";
  for (auto [plane, x, y, z] : {std::tuple{17, 1.0, 2.0, 3.0}, {18, 2.0, 3.0, 1.0}, {19, 3.0, 1.0, 2.0}}) {
    Program p = write_program(fmt::format("plane{}", plane),
                              fmt::format("G{} G0 X0 Y0 Z0\nL CYCLE [NAME=c.ecy @P1=1 @P2=2 @P3=3]\nM30\n", plane),
                              {{"c.ecy", cyc}});
    CliResult r = run_program(p);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NEAR(final_pcs(p, "X"), x, 1e-6) << "G" << plane;
    EXPECT_NEAR(final_pcs(p, "Y"), y, 1e-6) << "G" << plane;
    EXPECT_NEAR(final_pcs(p, "Z"), z, 1e-6) << "G" << plane;
  }
}

TEST(CyclesRun, CentreWordsFollowThePlane) {
  // G18: @X = Z, @Y = X, @I = K (Z's centre). A half circle from Z0 X0
  // around Z5 X0 ends at Z10 X0; the X on the way peaks at the radius 5.
  Program p = write_program("ijk", "G18 G90 G0 X0 Y0 Z0\nL CYCLE [NAME=c.ecy]\nM30\n",
                            {{"c.ecy", "G2 @X10 @Y0 @I5 F3000\nM17\n"}});
  const auto dir = p.dir;
  CliResult r = run_nck("run " + root() + "/examples/mill " + p.main.string() + " --final " +
                        (dir / "final.json").string() + " --trace " + (dir / "t.csv").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NEAR(final_pcs(p, "Z"), 10, 1e-6);
  EXPECT_NEAR(final_pcs(p, "X"), 0, 1e-6);
  double max_abs_x = 0;
  for (const Row& row : trace_rows(dir)) max_abs_x = std::max(max_abs_x, std::fabs(row.x));
  EXPECT_NEAR(max_abs_x, 5, 1e-3);
}

TEST(CyclesRun, CallersModalStateComesBackAfterTheCycle) {
  // The cycle switches to G91 and F100; after it the caller's G90 holds:
  // X30 is absolute (not 5 + 30).
  Program p = write_program("restore", "G90 G0 X0 Y0 Z0\nL CYCLE [NAME=c.ecy]\nG0 X30\nM30\n",
                            {{"c.ecy", "G91 G1 X5 F100\nM17\n"}});
  CliResult r = run_program(p);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NEAR(final_pcs(p, "X"), 30, 1e-6);
}

TEST(CyclesRun, NestedCyclesKeepTheirOwnParameters) {
  // outer passes @P1*2 to inner; inner moves X there; outer then moves Y to
  // its own @P1 (unchanged by inner's @P1).
  Program p = write_program("nested", "G90 G0 X0 Y0 Z0\nL CYCLE [NAME=outer.ecy @P1=4]\nM30\n",
                            {{"outer.ecy", "L CYCLE [NAME=inner.ecy @P1=@P1*2]\nG1 @Y=@P1 F1000\nM17\n"},
                             {"inner.ecy", "@P1 = @P1 + 1\nG1 @X=@P1 F1000\nM17\n"}});
  CliResult r = run_program(p);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NEAR(final_pcs(p, "X"), 9, 1e-6);
  EXPECT_NEAR(final_pcs(p, "Y"), 4, 1e-6);
}

TEST(CyclesRun, ModalBlockRepeatsAfterEveryBlockModalMoveOnlyAfterMotion) {
  // The cycle adds 1 to the global V.P.COUNT each time it runs. MODAL_MOVE:
  // at the call and after the two motion blocks (not after M8). MODAL_BLOCK:
  // also after M8.
  for (auto [mode, want] : {std::pair{"MODAL_MOVE", 3}, {"MODAL_BLOCK", 4}}) {
    Program p = write_program(fmt::format("modal-{}", mode),
                              fmt::format("#VAR\n V.P.COUNT = 0\n#ENDVAR\nG90 G0 X0 Y0 Z0\n"
                                          "L CYCLE [NAME=c.ecy {}]\nG0 X1\nM8\nG0 X2\n"
                                          "#DISABLE MODAL CYCLE\nG0 X3\nG0 Y[V.P.COUNT]\nM30\n",
                                          mode),
                              {{"c.ecy", "V.P.COUNT = V.P.COUNT + 1\nM17\n"}});
    CliResult r = run_program(p);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NEAR(final_pcs(p, "Y"), want, 1e-6) << mode;
  }
}

TEST(CyclesRun, CycleSearchPathProgramFolderMachineKeyAndCommandLine) {
  // Not next to the program: found with --cycles (run and parse) ...
  Program p = write_program("path", "G90 G0 X0 Y0 Z0\nL CYCLE [NAME=far.cyc @P1=7]\nM30\n",
                            {{"lib/far.cyc", "G1 @X=@P1 F1000\nM17\n"}});
  CliResult r = run_program(p, "--cycles " + (p.dir / "lib").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NEAR(final_pcs(p, "X"), 7, 1e-6);
  EXPECT_EQ(run_nck("parse " + p.main.string() + " --cycles " + (p.dir / "lib").string()).exit_code, 0);
  // ... or through the machine's startup.lis cycle_path[i] (relative to the machine folder) ...
  PatchedMachine m = patched_example("mill", "cyc-path-machine", "startup.lis",
                                     "cycle_path[0] " + (p.dir / "lib").string());
  r = run_nck("run " + m.dir.string() + " " + p.main.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  // ... and without either it is 920110 naming every folder it looked in.
  r = run_program(p);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("920110"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find((p.dir / "far.cyc").string()), std::string::npos) << r.output;
  EXPECT_NE(r.output.find((std::filesystem::path(root()) / "examples/mill/cycles/far.cyc").lexically_normal().string()),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("main.nc:2"), std::string::npos) << r.output;
}

struct Bad {
  const char* what;
  std::string main;
  std::vector<std::pair<std::string, std::string>> files;
  const char* id;
  const char* where;  // file:line
};

TEST(CyclesRun, ParameterRuleViolationsStopWithIdFileAndLine) {
  const std::vector<Bad> cases = {
      {"@P in the main program", "G0 X0\n@P1 = 5\nM30\n", {}, "21382", "main.nc:2"},
      {"@P read in the main program", "G0 X[@P1]\nM30\n", {}, "21382", "main.nc:1"},
      {"@X outside a cycle", "G0 @X10\nM30\n", {}, "21382", "main.nc:1"},
      {"@P not given", "L CYCLE [NAME=c.ecy @P1=1]\nM30\n", {{"c.ecy", "G0 X1\nG0 X[@P1 + @P3]\nM17\n"}},
       "20394", "c.ecy:2"},
      {"@P in a plain subroutine of a cycle", "L CYCLE [NAME=c.ecy @P1=1]\nM30\n",
       {{"c.ecy", "L sub.nc\nM17\n"}, {"sub.nc", "G0 X[@P1]\nM17\n"}}, "21382", "sub.nc:1"},
      {"unknown name in the call", "G0 X0\nL CYCLE [NAME=c.ecy DEPTH=5]\nM30\n", {{"c.ecy", "M17\n"}},
       "920111", "main.nc:2"},
      {"call not closed", "L CYCLE [NAME=c.ecy @P1=1\n]\nM30\n", {{"c.ecy", "M17\n"}}, "920111", "main.nc:1"},
      {"@P201", "L CYCLE [NAME=c.ecy @P201=1]\nM30\n", {{"c.ecy", "M17\n"}}, "920112", "main.nc:1"},
      {"unknown @ word", "L CYCLE [NAME=c.ecy]\nM30\n", {{"c.ecy", "G0 @Q1\nM17\n"}}, "920112", "c.ecy:1"},
      {"cycle while a modal cycle is active",
       "L CYCLE [NAME=c.ecy MODAL_MOVE]\nG0 X1\nL CYCLE [NAME=c.ecy]\nM30\n", {{"c.ecy", "M17\n"}}, "21381",
       "main.nc:3"},
      {"V.CYC. variable after the cycle", "L CYCLE [NAME=c.ecy]\nG0 X[V.CYC.A]\nM30\n",
       {{"c.ecy", "#VAR\n V.CYC.A = 1\n#ENDVAR\nM17\n"}}, "9200", "main.nc:2"},
      {"missing local cycle", "LL CYCLE [NAME=NOPE]\nM30\n", {}, "920110", "main.nc:1"},
  };
  for (const Bad& b : cases) {
    Program p = write_program("bad", b.main, b.files);
    CliResult r = run_program(p);
    EXPECT_EQ(r.exit_code, 1) << b.what << "\n" << r.output;
    EXPECT_NE(r.output.find(b.id), std::string::npos) << b.what << "\n" << r.output;
    EXPECT_NE(r.output.find(b.where), std::string::npos) << b.what << "\n" << r.output;
    EXPECT_EQ(r.output.find("920052"), std::string::npos) << b.what << "\n" << r.output;
  }
}

TEST(CyclesRun, LocalCycleWithContinuationLines) {
  // LL CYCLE calls a %L section of the same file; the call spans three
  // lines joined by '\'.
  Program p = write_program("local",
                            "%main\nG90 G0 X0 Y0 Z0\nLL CYCLE [NAME=half \\\n  @P1=8 \\\n  @P2=3]\nM30\n"
                            "%L half\nG1 @X=[@P1/2] @Y=@P2 F1000\nM17\n");
  CliResult r = run_program(p);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NEAR(final_pcs(p, "X"), 4, 1e-6);
  EXPECT_NEAR(final_pcs(p, "Y"), 3, 1e-6);
}

TEST(CyclesRun, UnsupportedIsgFunctionsAreNamed) {
  for (auto [fn, name] : {std::pair{"#RT CYCLE [ID=1]", "#RT CYCLE"}, {"#MC_MOVEPATH SYN [..]", "#MC_MOVEPATH"},
                          {"#WAIT SYN [ID=1]", "#WAIT SYN"}}) {
    Program p = write_program("unsupported", fmt::format("G0 X0\n{}\nM30\n", fn));
    CliResult r = run_nck("parse " + p.main.string());
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("920052"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("does not support"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("920080"), std::string::npos) << r.output;  // never "unknown # command"
    EXPECT_NE(r.output.find(name), std::string::npos) << r.output;
  }
}

}  // namespace
}  // namespace nck::app
