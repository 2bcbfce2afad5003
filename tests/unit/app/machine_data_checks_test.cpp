// What `nck check` finds in machine data before a run (issue 44 items 14,
// 15): the ranges the TF5200 pages give (tool speed and acceleration ≥ 1,
// the gear-change position inside the software limits), the parameters
// that are read but act on nothing in simulation, and a spindle that cannot
// position or home.
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

// The mill's S2 is speed-controlled without feedback (s2.lis): no program
// can position or home it. Without programs `nck check` says so, as a
// warning at its operation mode; with a program, the check gives the run's
// error 70252 where the program asks for either.
TEST(SpindleCapabilities, ASpindleThatCannotPositionIsReportedBeforeTheRun) {
  const CliResult machine = run_nck("check " + mill());
  EXPECT_EQ(machine.exit_code, 0) << machine.output;
  EXPECT_NE(machine.output.find("s2.lis:10: warning 70252: spindle S2 of channel 1 is speed-controlled without "
                                "position feedback (antr.operation_mode OPEN_POSITION_LOOP_MODE)"),
            std::string::npos)
      << machine.output;
  EXPECT_NE(machine.output.find("0 error(s), 1 warning(s)"), std::string::npos) << machine.output;
  // The lathe's spindle is position-controlled: nothing to say.
  EXPECT_EQ(run_nck("check " + root() + "/examples/lathe").output.find("70252"), std::string::npos);

  const auto dir = temp_dir("sensorless_check");
  for (const std::string block : {"S2[M19 REV100 POS10]", "S2[G74]"}) {
    const std::string prog = write(dir / "p.nc", "N10 G0 X0\nN20 " + block + "\nN30 M30\n").string();
    const CliResult check = run_nck("check " + mill() + " " + prog);
    EXPECT_EQ(check.exit_code, 1) << block << "\n" << check.output;
    EXPECT_NE(check.output.find(prog + ":2: error 70252"), std::string::npos) << block << "\n" << check.output;
    const CliResult run = run_nck("run " + mill() + " " + prog + " --no-progress");
    EXPECT_EQ(run.exit_code, 1) << run.output;
    EXPECT_NE(run.output.find(prog + ":2: error 70252"), std::string::npos) << block << "\n" << run.output;
  }
  // S1 (position-controlled) may position.
  const std::string s1 = write(dir / "s1.nc", "N10 S[M19 REV100 POS10]\nN20 G74 S1\nN30 M30\n").string();
  EXPECT_EQ(run_nck("check " + mill() + " " + s1).exit_code, 0);
}

}  // namespace
}  // namespace nck::app::testing
