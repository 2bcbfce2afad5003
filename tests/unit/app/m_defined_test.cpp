// Issue 44 item 10 through `nck run`: an M function the channel list does
// not define (no m_synch[n], TF5200 P-CHAN-00041 default NOT_VALID) stops the
// program at its block with 930020; the fixed functions need no entry; with
// gear change off M40..M45 are free M functions: defined by m_synch and
// acknowledged like any other, without the gear-change time.
#include <gtest/gtest.h>

#include <map>

#include "cli_helpers.hpp"
#include "spindle_path_helpers.hpp"

namespace nck::app::testing {
namespace {

using nlohmann::json;

const json* first_event(const PathRun& r, const std::string& ev) {
  for (const json& e : r.events)
    if (e["ev"] == ev) return &e;
  return nullptr;
}

TEST(MDefined, AnUndefinedMFunctionStopsTheProgramAtItsBlock) {
  const PathRun r = run_text("mill", "%m\nN10 G1 X10 F3000\nN20 M7\nN30 G1 X20\nN40 M30\n", "m_undefined");
  EXPECT_NE(r.cli.exit_code, 0) << r.cli.output;
  EXPECT_NE(r.cli.output.find("930020"), std::string::npos) << r.cli.output;
  const json* error = first_event(r, "error");
  ASSERT_NE(error, nullptr);
  EXPECT_EQ((*error)["id"], 930020);
  EXPECT_EQ((*error)["line"], 3);
  EXPECT_LT(r.line_t(4), 0) << "nothing after the undefined M function runs";
}

TEST(MDefined, AnEntryDefinesItAndTheFixedFunctionsNeedNone) {
  const auto machine = patched_example("mill", "m_defined", "channel1.lis", "m_synch[7] MOS").dir;
  const PathRun r = run_text(machine.string(), "%m\nN10 G1 X10 F3000 M7\nN20 M0\nN30 M1\nN40 M30\n",
                             "m_defined_run");
  EXPECT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const json* out = first_event(r, "plc_out");
  ASSERT_NE(out, nullptr);
  EXPECT_EQ((*out)["fn"], "M7");
}

TEST(MDefined, AnUndefinedMInSpindleSyntaxIsRefusedToo) {
  const PathRun r = run_text("mill", "%m\nN10 S[M=63]\nN20 M30\n", "m_undefined_spindle");
  EXPECT_NE(r.cli.output.find("930020"), std::string::npos) << r.cli.output;
}

// The mill shifts no gears (main_spindle_gear_change 0); its sim.lis gives
// a gear change 800 ms and a plain M function 10 ms.
TEST(MDefined, FreeGearFunctionsNeedAnEntryAndTakeNoGearTime) {
  const PathRun undefined = run_text("mill", "%m\nN10 M41\nN20 M30\n", "m_free_gear_undefined");
  EXPECT_NE(undefined.cli.output.find("930020"), std::string::npos) << undefined.cli.output;

  const auto machine = patched_example("mill", "m_free_gear", "channel1.lis", "m_synch[41] MVS_SVS").dir;
  const PathRun r = run_text(machine.string(), "%m\nN10 M41\nN20 G1 X1 F3000\nN30 M30\n", "m_free_gear_run");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const double waited_s = r.line_t(3) - r.line_t(2);
  EXPECT_NEAR(waited_s, 0.010, 0.0025) << "acknowledged after plc_ack_delay_ms, not gear_change_time_ms";
}

// Issue 44 item 9 (TF5200 "M/H functions with additional information"): the
// value travels with the function to the PLC, in the plc_out event.
TEST(MDefined, AnAdditionalValueTravelsWithItsFunctionToThePlc) {
  const auto machine = patched_example("mill", "m_value", "channel1.lis", "m_synch[52] MOS").dir;
  const PathRun r =
      run_text(machine.string(), "%m\nN10 P2 = 345\nN20 M52=-345 H10=P2\nN30 M8\nN40 M30\n", "m_value_run");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  std::map<std::string, json> out;
  for (const json& e : r.events)
    if (e["ev"] == "plc_out") out[e["fn"].get<std::string>()] = e["value"];
  ASSERT_EQ(out.count("M52"), 1u);
  EXPECT_EQ(out["M52"], -345);
  EXPECT_EQ(out["H10"], 345);
  EXPECT_TRUE(out["M8"].is_null());  // no value programmed: none given

  const PathRun spindle = run_text("mill", "%m\nN10 S1000 M3=5\nN20 M30\n", "m_value_spindle");
  EXPECT_NE(spindle.cli.output.find("920121"), std::string::npos) << spindle.cli.output;
}

}  // namespace
}  // namespace nck::app::testing
