// What `nck check` finds in machine data before a run (issue 44 item 14):
// the ranges the TF5200 pages give (tool speed and acceleration ≥ 1, the
// gear-change position inside the software limits) and the parameters that
// are read but act on nothing in simulation.
#include <gtest/gtest.h>

#include <string>

#include "cli_helpers.hpp"

namespace nck::app::testing {
namespace {

std::string at_line(const std::string& file, std::size_t line, const std::string& what) {
  return file + ":" + std::to_string(line) + ": " + what;
}

// P-TOOL-00014 / P-TOOL-00015: 1 ≤ vb_max, 1 ≤ a_max.
TEST(MachineDataRanges, ToolSpeedAndAccelerationAreAtLeastOne) {
  for (const std::string line : {"wz[5].vb_max 0", "wz[5].a_max 0.5"}) {
    const auto m = patched_example("mill", "tool_range", "tools.lis", line);
    const CliResult r = run_nck("check " + m.dir.string());
    EXPECT_EQ(r.exit_code, 1) << line << "\n" << r.output;
    EXPECT_NE(r.output.find(at_line("tools.lis", m.line, "error 910004")), std::string::npos) << line << "\n" << r.output;
  }
  const auto ok = patched_example("mill", "tool_range_ok", "tools.lis", "wz[7].vb_max 1\nwz[7].a_max 1");
  EXPECT_EQ(run_nck("check " + ok.dir.string()).exit_code, 0);
}

// P-AXIS-00078: swe_neg < getr_schalt_pos < swe_pos (P-AXIS-00177/00178).
TEST(MachineDataRanges, GearChangePositionLiesStrictlyInsideTheSoftwareLimits) {
  struct Case {
    std::string line;
    bool ok;
  } cases[] = {
      {"getriebe[0].getr_schalt_pos 6000000", false},   // 600 mm, beyond swe_pos 500 mm
      {"getriebe[0].getr_schalt_pos 5000000", false},   // on the limit: not strictly inside
      {"getriebe[0].getr_schalt_pos -4999999", true},
  };
  for (const Case& c : cases) {
    const auto m = patched_example("mill", "gear_pos", "x.lis", c.line);
    const CliResult r = run_nck("check " + m.dir.string());
    EXPECT_EQ(r.exit_code, c.ok ? 0 : 1) << c.line << "\n" << r.output;
    if (c.ok) continue;
    EXPECT_NE(r.output.find(at_line("x.lis", m.line, "error 910023")), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("must lie strictly between kenngr.swe_neg (-5000000 × 0.1 µm) and kenngr.swe_pos "
                            "(5000000 × 0.1 µm)"),
              std::string::npos)
        << r.output;
  }
  // A spindle's stage, against the limits of its axis list.
  const auto s = patched_example("lathe", "gear_pos_spindle", "s1.lis", "kenngr.swe_pos 400000");
  const CliResult r = run_nck("check " + s.dir.string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("getriebe[1].getr_schalt_pos (450000 × 0.0001°) must lie strictly between"),
            std::string::npos)
      << r.output;
}

// Read and range-checked, but nothing in the simulation acts on them.
TEST(MachineDataRanges, ParametersWithoutEffectInSimulationSaySo) {
  for (const char* id : {"P-AXIS-00265", "P-AXIS-00266", "P-CHAN-00810"}) {
    const CliResult p = run_nck_raw(std::string("params ") + id);
    EXPECT_EQ(p.exit_code, 0) << id;
    EXPECT_NE(p.output.find("accepted, no effect in simulation"), std::string::npos) << id << "\n" << p.output;
  }
  EXPECT_NE(read_file(root() + "/docs/parameters.md").find("SERCOS drives: above this speed"), std::string::npos);
}

}  // namespace
}  // namespace nck::app::testing
