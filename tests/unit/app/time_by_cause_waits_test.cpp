// Time by cause (issue 31), the classes the first tests left out: each wait
// reason the kernel reports that a program can construct (spindle position
// and standstill, an M function's acknowledgement, a coupling holding the
// path, a late synchronisation at #EXPL SYN), a program hold, and starved
// preparation. Each block's time must be >= 90 % the expected class.
#include <gtest/gtest.h>

#include "time_by_cause_helpers.hpp"

namespace nck::app::testing {
namespace {

// The mill with some lines of channel1.lis / sim.lis replaced (key -> line).
std::string mill_with(const std::string& name, const std::map<std::string, std::string>& channel,
                      const std::map<std::string, std::string>& sim) {
  namespace fs = std::filesystem;
  const auto dir = temp_dir("cause_mill_" + name);
  fs::remove_all(dir / "m");
  fs::copy(mill(), dir / "m", fs::copy_options::recursive);
  const auto patch = [&](const std::string& file, const std::map<std::string, std::string>& lines) {
    std::ifstream in(dir / "m" / file);
    std::string text, line;
    while (std::getline(in, line)) {
      for (const auto& [key, replacement] : lines)
        if (line.starts_with(key + " ")) line = replacement;
      text += line + "\n";
    }
    for (const auto& [key, replacement] : lines)
      if (text.find(replacement) == std::string::npos) text = replacement + "\n" + text;  // not there yet: add it
    write(dir / "m" / file, text);
  };
  patch("channel1.lis", channel);
  patch("sim.lis", sim);
  return (dir / "m").string();
}

TEST(TimeByCauseWaits, SpindlePosition) {
  // M19 (MNS_SNS) waits after its block until S1 stands at 270 deg; at
  // 60 rpm (360 deg/s) that takes most of a second, homing included
  expect_dominant(run_program("in_pos", "G90 G0 X0 Y0 Z0\nS.POS=270 M19 S60\nM30\n"), 2, "wait in_position");
}

TEST(TimeByCauseWaits, SpindleStandstill) {
  // M5 (PLC_INFO MVS_SVS) waits until S1 has braked from 12,000 rpm (3.6 s)
  expect_dominant(run_program("standstill", "G90 G0 X0 Y0 Z0\nM3 S12000\nM5\nM30\n"), 3, "wait standstill");
}

TEST(TimeByCauseWaits, MFunctionAcknowledge) {
  // M10 (clamp, PLC_INFO MVS_SNS): the PLC takes 2 s to acknowledge it
  const std::string m = mill_with("m10", {}, {{"m_ack_delay_ms[10]", "m_ack_delay_ms[10] 2000"}});
  expect_dominant(run_program("m10", "G90 G0 X0 Y0 Z0\nM10\nM30\n", "", m), 2, "wait plc_ack");
}

TEST(TimeByCauseWaits, LateSynchronisationWaitsAtExplSyn) {
  // M10 output now, waited for at #EXPL SYN (MVS_SLP): the short move
  // between runs at once, the #EXPL SYN block carries the wait
  const std::string m = mill_with("slp", {{"m_synch[10]", "m_synch[10] MVS_SLP"}},
                                  {{"m_ack_delay_ms[10]", "m_ack_delay_ms[10] 2000"}});
  const CauseRun r = run_program("slp", "G90 G0 X0 Y0 Z0\nM10\nG0 X1\n#EXPL SYN\nM30\n", "", m);
  expect_dominant(r, 4, "wait plc_ack");
  EXPECT_NE(dominant(block_of(r.final, 3)).first, "wait plc_ack") << block_of(r.final, 3).dump(1);
}

TEST(TimeByCauseWaits, CouplingHoldsThePath) {
  // G95 with S1 commanded but held at rest by the PLC's spindle feedhold
  // for 4 s (M3 without a wait, MOS): the feed per revolution holds the
  // path; then 0.2 mm at 0.1 mm/rev and 600 rpm take 0.2 s
  const std::string m = mill_with("coupling", {{"spindel[0].m3_synch", "spindel[0].m3_synch MOS"}}, {});
  expect_dominant(run_program("coupling", "G90 G0 X0 Y0 Z0\nM3 S600 G95 G1 X0.2 F0.1\nM30\n",
                              "0 spindle_feedhold S1 on\n4 spindle_feedhold S1 off\n", m),
                  2, "wait coupling");
}

TEST(TimeByCauseWaits, ProgramHold) {
  // M0 holds until the operator's cycle start 3 s later
  expect_dominant(run_program("hold", "G90 G0 X0 Y0 Z0\nM0\nG1 X1 F600\nM30\n", "0 auto_cycle_start off\n3 cycle_start\n"),
                  2, "hold program");
}

}  // namespace
}  // namespace nck::app::testing
