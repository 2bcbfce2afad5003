// G51/G52 diameter programming through `nck run` (docs/nc-language.md, issue 11 item
// 5): the lathe's X (kenngr.achs_mode 0x40, diameter_prog_abs/rel 1) takes
// diameters; the trace stays in radius, --final shows both.
#include <gtest/gtest.h>

#include "cli_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;
using nlohmann::json;

struct LatheRun {
  CliResult cli;
  std::filesystem::path dir;
};

LatheRun run_lathe(const std::string& name, const std::string& program, const std::string& x_lines = "") {
  const auto machine = x_lines.empty() ? temp_dir(name) / "lathe" : patched_example("lathe", name, "x.lis", x_lines).dir;
  if (x_lines.empty())
    std::filesystem::copy(root() + "/examples/lathe", machine, std::filesystem::copy_options::recursive);
  const auto dir = machine.parent_path();
  std::ofstream(dir / "p.nc") << program;
  LatheRun r{run_nck("run " + machine.string() + " " + (dir / "p.nc").string() + " --events " + (dir / "e.jsonl").string() +
                " --trace " + (dir / "t.csv").string() + " --final " + (dir / "f.json").string()),
        dir};
  return r;
}

std::vector<json> of_kind(const std::filesystem::path& events, const std::string& ev) {
  std::vector<json> out;
  for (const json& e : read_jsonl(events))
    if (e["ev"] == ev) out.push_back(e);
  return out;
}

// The trace columns after t, from its header.
std::vector<std::string> columns(const std::filesystem::path& trace) {
  return split(split(read_file(trace), '\n')[0], ',');
}

// diameter.nc is turn.nc in diameters: both machine the same path, so their
// traces are the same cycle for cycle.
TEST(Diameter, ExampleMachinesTheSameRadiiAsTheRadiusProgram) {
  const auto dir = temp_dir("diameter-example");
  const std::string lathe = root() + "/examples/lathe";
  CliResult d = run_nck("run " + lathe + " " + lathe + "/diameter.nc --trace " + (dir / "d.csv").string());
  CliResult r = run_nck("run " + lathe + " " + lathe + "/turn.nc --trace " + (dir / "r.csv").string());
  ASSERT_EQ(d.exit_code, 0) << d.output;
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto cols = columns(dir / "d.csv");
  ASSERT_EQ(cols[1], "X");
  const auto dl = split(read_file(dir / "d.csv"), '\n'), rl = split(read_file(dir / "r.csv"), '\n');
  ASSERT_EQ(dl.size(), rl.size());
  double x_max = 0;
  for (std::size_t i = 1; i < dl.size(); ++i) {
    if (dl[i].empty()) continue;
    const auto a = split(dl[i], ','), b = split(rl[i], ',');
    ASSERT_NEAR(std::stod(a[1]), std::stod(b[1]), 1e-9) << "cycle " << i;  // X
    ASSERT_NEAR(std::stod(a[2]), std::stod(b[2]), 1e-9) << "cycle " << i;  // Z
    x_max = std::max(x_max, std::stod(a[1]));
  }
  EXPECT_DOUBLE_EQ(x_max, 30.0);  // G51 X60 is radius 30
}

TEST(Diameter, FinalShowsRadiusAndDiameterAndG91TakesDiameters) {
  LatheRun r = run_lathe("diameter-final", "N10 G18 G51 G0 X40 Z0\nN20 G91 X-10\nN30 M30\n");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const json f = json::parse(read_file(r.dir / "f.json"));
  const json& x = f["channels"][0]["axes"]["X"];
  EXPECT_DOUBLE_EQ(x["mcs"].get<double>(), 15.0);  // 40/2, then -10/2
  EXPECT_DOUBLE_EQ(x["pcs"].get<double>(), 15.0);
  EXPECT_DOUBLE_EQ(x["pcs_diameter"].get<double>(), 30.0);
  EXPECT_FALSE(f["channels"][0]["axes"]["Z"].contains("pcs_diameter"));
  EXPECT_EQ(f["channels"][0]["modal"]["diameter"], "G51");
  const auto lines = split(read_file(r.dir / "t.csv"), '\n');
  EXPECT_DOUBLE_EQ(std::stod(split(lines[lines.size() - 2], ',')[1]), 15.0);  // trace: radius
}

TEST(Diameter, OffsetsActInRadiusOnTheDiameter) {
  // G54 shifts Z only (zero.lis); a G92 X5 shift is a radius offset.
  LatheRun r = run_lathe("diameter-offset", "N10 G18 G51 G92 X5\nN20 G0 X40 Z10\nN30 M30\n");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const json f = json::parse(read_file(r.dir / "f.json"));
  EXPECT_DOUBLE_EQ(f["channels"][0]["axes"]["X"]["mcs"].get<double>(), 25.0);  // 40/2 + 5
  EXPECT_DOUBLE_EQ(f["channels"][0]["axes"]["X"]["pcs_diameter"].get<double>(), 40.0);
}

TEST(Diameter, BadUseIsAnErrorWithItsLine) {
  struct Case {
    const char* program;
    std::uint32_t id;
    int line;
  } cases[] = {
      {"N10 G18 G51\nN20 G0 X-20\nN30 M30\n", 930200, 2},           // negative diameter
      {"N10 G18 G51\nN20 #PSET X10\nN30 M30\n", 930201, 2},       // #PSET under G51
      {"N10 G19\nN20 G51\nN30 M30\n", 20042, 2},                    // no face axis in G19 (Y Z)
  };
  for (const Case& c : cases) {
    LatheRun r = run_lathe("diameter-bad", c.program);
    EXPECT_EQ(r.cli.exit_code, 1) << c.program << r.cli.output;
    const auto errors = of_kind(r.dir / "e.jsonl", "error");
    ASSERT_EQ(errors.size(), 1u) << c.program;
    EXPECT_EQ(errors[0]["id"], c.id) << c.program;
    EXPECT_EQ(errors[0]["line"], c.line) << c.program;
    EXPECT_EQ(of_kind(r.dir / "e.jsonl", "end").back()["reason"], "error");
    EXPECT_TRUE(json::parse(read_file(r.dir / "f.json")).contains("channels"));  // complete
  }
  // A mill has no face-turning axis.
  const auto dir = temp_dir("diameter-mill");
  std::ofstream(dir / "p.nc") << "N10 G18 G51\nN20 M30\n";
  CliResult m = run_nck("run " + root() + "/examples/mill " + (dir / "p.nc").string());
  EXPECT_EQ(m.exit_code, 1);
  EXPECT_NE(m.output.find("20042"), std::string::npos) << m.output;
}

TEST(Diameter, WithoutTheAxisFlagsG51WarnsAndRadiiStay) {
  LatheRun r = run_lathe("diameter-unset", "N10 G18 G51 G0 X40\nN20 M30\n",
                    "kenngr.durchm_prog_abs 0\nkenngr.durchm_prog_rel 0");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const auto warnings = of_kind(r.dir / "e.jsonl", "warning");
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0]["id"], 930202);
  EXPECT_EQ(warnings[0]["line"], 1);
  EXPECT_DOUBLE_EQ(json::parse(read_file(r.dir / "f.json"))["channels"][0]["axes"]["X"]["mcs"].get<double>(), 40.0);
}

}  // namespace
}  // namespace nck::app
