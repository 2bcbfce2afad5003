// G130...G134, G233 in preparation on examples/mill (X/Y: a_beschl = a_brems
// 2500, a_max 3000; Z: 2000, a_max 2500; every axis the TF5200 ramp times:
// 50 ms feed, 10 ms tr_geom and tr_grenz, tr_min 10 ms, no a_w_max /
// tr_w_min, so a_max and tr_min bound the weightings). Lines along one
// axis show that axis's weighted values in the path limits.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "example_blocks.hpp"
#include "nck/prep/planner.hpp"
#include "planner_rig.hpp"
#include "planned_parts.hpp"

namespace nck::prep {
namespace {

using testing::decode_blocks;
using testing::example_machine;

// examples/mill's planner.
struct Rig : testing::PlannerRig {
  Rig() : PlannerRig("mill") {}
};

// The command planned for program line `line`.
const PlannedCommand& at_line(const std::vector<PlannedCommand>& cs, std::uint32_t line) {
  for (const PlannedCommand& c : cs)
    if (c.head.line == line) return c;
  static const PlannedCommand kNone;
  ADD_FAILURE() << "nothing planned for line " << line;
  return kNone;
}

void expect_ramps(const motion::PathLimits& l, double tr_s, std::uint32_t line) {
  EXPECT_DOUBLE_EQ(l.tr.acc_up_s, tr_s) << "line " << line;
  EXPECT_DOUBLE_EQ(l.tr.acc_down_s, tr_s) << "line " << line;
  EXPECT_DOUBLE_EQ(l.tr.dec_up_s, tr_s) << "line " << line;
  EXPECT_DOUBLE_EQ(l.tr.dec_down_s, tr_s) << "line " << line;
}

void expect_error(const PlannedCommand& c, ErrorId id) {
  EXPECT_EQ(c.kind, CommandKind::error) << "line " << c.head.line;
  EXPECT_EQ(test::error_of(c).id, id) << "line " << c.head.line;
}

TEST(DynWeights, G131WeightsTheConfiguredAccelerationNotThePreviousWeighting) {
  Rig r;
  const auto c = r.plan("G0 X0 Y0 Z0\nG1 X10 F3000\nG131=50\nX20\nG131=50\nX30\nG131=100\nX40\nM30\n");
  EXPECT_DOUBLE_EQ(at_line(c, 2).limits.a_acc_mm_s2, 2500);
  EXPECT_DOUBLE_EQ(at_line(c, 4).limits.a_acc_mm_s2, 1250);
  EXPECT_DOUBLE_EQ(at_line(c, 4).limits.a_dec_mm_s2, 1250);
  EXPECT_DOUBLE_EQ(at_line(c, 6).limits.a_acc_mm_s2, 1250);  // 50 % twice: 50 %, not 25 %
  EXPECT_DOUBLE_EQ(at_line(c, 8).limits.a_acc_mm_s2, 2500);
}

TEST(DynWeights, G130SetsTheAxesItDoesNotNameBackTo100Percent) {
  Rig r;
  const auto c = r.plan("G0 X0 Y0 Z0\nG130 X70\nG1 X10 F3000\nY10\nG130 Y60\nX20\nY20\nZ-10\nM30\n");
  EXPECT_EQ(at_line(c, 2).kind, CommandKind::nop);  // the axis words are weightings, no motion
  EXPECT_DOUBLE_EQ(at_line(c, 3).limits.a_acc_mm_s2, 1750);
  EXPECT_DOUBLE_EQ(at_line(c, 4).limits.a_acc_mm_s2, 2500);
  EXPECT_DOUBLE_EQ(at_line(c, 6).limits.a_acc_mm_s2, 2500);  // X back to 100 %
  EXPECT_DOUBLE_EQ(at_line(c, 7).limits.a_acc_mm_s2, 1500);
  EXPECT_DOUBLE_EQ(at_line(c, 8).limits.a_acc_mm_s2, 2000);
  // The motion after the weighting starts where the axes stand (X10 Y10, not X70).
  EXPECT_DOUBLE_EQ(at_line(c, 6).segment.start_point()[0], 10);
}

TEST(DynWeights, AccelerationMayBeRaisedUpToAwMax) {
  Rig r;
  const auto c = r.plan("G0 X0 Y0 Z0\nG130 X120 Z125\nG1 X10 F3000\nZ-10\nG130 X121\nX20\nM30\n");
  EXPECT_DOUBLE_EQ(at_line(c, 3).limits.a_acc_mm_s2, 3000);  // 2500 * 1.2 = a_max
  EXPECT_DOUBLE_EQ(at_line(c, 4).limits.a_acc_mm_s2, 2500);  // 2000 * 1.25 = a_max
  expect_error(at_line(c, 5), ErrorId::KernelWeightedAcceleration);
}

TEST(DynWeights, AccelerationWeightingActsUnderStepAndOnFeedOnly) {
  Rig r;
  const auto c = r.plan("G0 X0 Y0 Z0\nG131=50\nG1 X10 F3000\nG0 X20\nM30\n");
  EXPECT_EQ(at_line(c, 3).limits.slope, SlopeProfile::step);
  EXPECT_DOUBLE_EQ(at_line(c, 3).limits.a_acc_mm_s2, 1250);
  EXPECT_DOUBLE_EQ(at_line(c, 4).limits.a_acc_mm_s2, 3000);  // G0: a_grenz
}

TEST(DynWeights, G133AndG132WeightTheFeedRampTimes) {
  Rig r;
  const auto c = r.plan("G0 X0 Y0 Z0\n#SLOPE [TYPE=TRAPEZ]\nG133=50\nG1 X10 F3000\nG133=50\nX20\n"
                        "G132 X40\nX30\nY10\nG133=20\nX40\nG0 X50\nM30\n");
  expect_ramps(at_line(c, 4).limits, 0.025, 4);
  expect_ramps(at_line(c, 6).limits, 0.025, 6);  // 50 % twice: 50 %
  expect_ramps(at_line(c, 8).limits, 0.020, 8);
  expect_ramps(at_line(c, 9).limits, 0.050, 9);  // Y not named: 100 %
  expect_ramps(at_line(c, 11).limits, 0.010, 11);  // 20 %: exactly tr_min
  expect_ramps(at_line(c, 12).limits, 0.010, 12);  // G0 keeps tr_grenz
}

TEST(DynWeights, RampWeightingsBelowTheirFloorAreRefused) {
  Rig r;
  const auto c = r.plan("G0 X0 Y0 Z0\nG133=19\nG132 Y19.9\nG134=99\nG233=99\nG133=1000\nG134=150\nG233=200\nM30\n");
  expect_error(at_line(c, 2), ErrorId::KernelWeightedRampTime);  // 9.5 ms < tr_w_min = tr_min 10 ms
  expect_error(at_line(c, 3), ErrorId::KernelWeightedRampTime);
  expect_error(at_line(c, 4), ErrorId::KernelWeightedRampTime);  // tr_geom 9.9 ms
  expect_error(at_line(c, 5), ErrorId::KernelWeightedRampTime);  // tr_grenz 9.9 ms
  for (std::uint32_t ok : {6u, 7u, 8u}) EXPECT_EQ(at_line(c, ok).kind, CommandKind::nop) << ok;
}

TEST(DynWeights, G233WeightsTheRapidRampsAndG134TheGeometricOne) {
  Rig r;
  const auto c = r.plan("G0 X0 Y0 Z0\n#SLOPE [TYPE=TRAPEZ]\nG233=200 G134=300\nG0 X10\nG1 X20 F3000\nM30\n");
  expect_ramps(at_line(c, 4).limits, 0.020, 4);
  expect_ramps(at_line(c, 5).limits, 0.050, 5);  // G233 leaves feed moves alone
  EXPECT_DOUBLE_EQ(at_line(c, 5).weights.geom, 3.0);
}

TEST(DynWeights, SlopeDefaultAndProgramStartRestore100Percent) {
  Rig r;
  const auto c = r.plan("G0 X0 Y0 Z0\n#SLOPE [TYPE=TRAPEZ]\nG131=50 G133=50\nG1 X10 F3000\n#SLOPE DEFAULT\n"
                        "#SLOPE [TYPE=TRAPEZ]\nX20\nM30\n");
  EXPECT_DOUBLE_EQ(at_line(c, 4).limits.a_acc_mm_s2, 1250);
  EXPECT_DOUBLE_EQ(at_line(c, 7).limits.a_acc_mm_s2, 2500);
  expect_ramps(at_line(c, 7).limits, 0.050, 7);
  EXPECT_TRUE(at_line(c, 7).weights.unit());
  Rig next;  // the next program's planner
  const auto d = next.plan("G0 X0 Y0 Z0\nG1 X10 F3000\nM30\n");
  EXPECT_DOUBLE_EQ(at_line(d, 2).limits.a_acc_mm_s2, 2500);
}

}  // namespace
}  // namespace nck::prep
