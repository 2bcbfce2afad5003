// G130...G134, G233 in preparation on examples/mill (X/Y: a_beschl = a_brems
// 2500, a_max 3000; Z: 2000, a_max 2500; every axis the TF5200 ramp times:
// 50 ms feed, 10 ms tr_geom and tr_grenz, tr_min 10 ms, no a_w_max /
// tr_w_min, so a_max and tr_min bound the weightings; the channel's fourth
// axis is S1's C axis, weighted and limited alike). Lines along one axis
// show that axis's weighted values in the path limits. A weighted value
// beyond its range is limited, with a warning at the block.
#include <gtest/gtest.h>

#include <algorithm>
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

// examples/mill with X: a_beschl 1000, a_brems 2000, a_w_max 2500 and
// Y: tr_w_min 20 ms.
const config::Machine& patched_mill() {
  static const config::Machine m = [] {
    config::Machine p = example_machine("mill");
    auto stage = [&](std::size_t j) -> config::GearStage& {
      config::AxisConfig& a = p.axes[static_cast<std::size_t>(p.channels[0].axes[j].axis_index)];
      return a.gears[a.initial_gear_stage - 1];
    };
    stage(0).accel_mm_s2 = 1000;
    stage(0).decel_mm_s2 = 2000;
    stage(0).a_w_max_mm_s2 = 2500;
    stage(1).tr_w_min_s = 0.020;
    return p;
  }();
  return m;
}

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

// The IDs of the warnings c raises, in order.
std::vector<ErrorId> warning_ids(const PlannedCommand& c) {
  std::vector<ErrorId> ids;
  for (const kernel::Warning& w : test::attached<kernel::Warning>(c)) ids.push_back(w.id);
  return ids;
}

// The text of c's first warning with `id` ("" when none).
std::string warning_text(const PlannedCommand& c, const PlanStore& store, ErrorId id) {
  for (const kernel::Warning& w : test::attached<kernel::Warning>(c))
    if (w.id == id && w.message) return store.messages[*w.message];
  return "";
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
  const auto c = r.plan("G0 X0 Y0 Z0\nG130 X120 Z125\nG1 X10 F3000\nZ-10\nM30\n");
  EXPECT_TRUE(warning_ids(at_line(c, 2)).empty());
  EXPECT_DOUBLE_EQ(at_line(c, 3).limits.a_acc_mm_s2, 3000);  // 2500 * 1.2 = a_max
  EXPECT_DOUBLE_EQ(at_line(c, 4).limits.a_acc_mm_s2, 2500);  // 2000 * 1.25 = a_max
}

TEST(DynWeights, AccelerationAboveAwMaxIsLimitedAndWarnedAtTheWeightingOnly) {
  Rig r;
  const auto c = r.plan("G0 X0 Y0 Z0\nG130 X121 Z50\nG1 X10 F3000\nZ-10\nG133=50\nX20\nM30\n");
  EXPECT_EQ(at_line(c, 2).kind, CommandKind::nop);
  EXPECT_EQ(warning_ids(at_line(c, 2)), std::vector<ErrorId>{ErrorId::KernelWeightAccLimited});  // X only
  EXPECT_EQ(warning_text(at_line(c, 2), r.store, ErrorId::KernelWeightAccLimited),
            "axis X: a_beschl 2500 at 121 % is 3025, above a_w_max 3000: 3000 used; "
            "a_brems 2500 at 121 % is 3025, above a_w_max 3000: 3000 used");
  EXPECT_DOUBLE_EQ(at_line(c, 3).limits.a_acc_mm_s2, 3000);
  EXPECT_DOUBLE_EQ(at_line(c, 3).limits.a_dec_mm_s2, 3000);
  EXPECT_DOUBLE_EQ(at_line(c, 4).limits.a_acc_mm_s2, 1000);  // Z's 50 % stays in force
  for (std::uint32_t line : {3u, 4u, 5u, 6u}) EXPECT_TRUE(warning_ids(at_line(c, line)).empty()) << line;
  EXPECT_DOUBLE_EQ(at_line(c, 6).limits.a_acc_mm_s2, 3000);  // G133 leaves G130 in force
}

TEST(DynWeights, AccelerationAndDecelerationAreLimitedEachOnItsOwn) {
  testing::PlannerRig r(patched_mill());
  const auto c = r.plan("G0 X0 Y0 Z0\nG130 X200\nG1 X10 F3000\nM30\n");
  EXPECT_EQ(warning_ids(at_line(c, 2)), std::vector<ErrorId>{ErrorId::KernelWeightAccLimited});
  EXPECT_EQ(warning_text(at_line(c, 2), r.store, ErrorId::KernelWeightAccLimited),
            "axis X: a_brems 2000 at 200 % is 4000, above a_w_max 2500: 2500 used");
  EXPECT_DOUBLE_EQ(at_line(c, 3).limits.a_acc_mm_s2, 2000);  // 1000 * 2: within a_w_max
  EXPECT_DOUBLE_EQ(at_line(c, 3).limits.a_dec_mm_s2, 2500);  // not 4000
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

TEST(DynWeights, FeedRampsBelowTrWMinAreLimitedToIt) {
  Rig r;
  const auto c = r.plan("G0 X0 Y0 Z0\n#SLOPE [TYPE=TRAPEZ]\nG132 Y19\nG1 Y10 F3000\nX10\nM30\n");
  // 50 ms * 19 % = 9.5 ms < tr_w_min = tr_min 10 ms: P-AXIS-00197 has an ID of its own.
  EXPECT_EQ(at_line(c, 3).kind, CommandKind::nop);
  EXPECT_EQ(warning_ids(at_line(c, 3)),
            (std::vector<ErrorId>{ErrorId::KernelWeightRampBelowMin, ErrorId::KernelWeightDecDownBelowMin}));
  EXPECT_EQ(warning_text(at_line(c, 3), r.store, ErrorId::KernelWeightDecDownBelowMin),
            "axis Y: tr_brems_ab 0.05 s at 19 % is 0.0095 s, below tr_w_min 0.01 s: 0.01 s used");
  expect_ramps(at_line(c, 4).limits, 0.010, 4);
  expect_ramps(at_line(c, 5).limits, 0.050, 5);
  testing::PlannerRig p(patched_mill());  // Y: tr_w_min 20 ms
  const auto d = p.plan("G0 X0 Y0 Z0\n#SLOPE [TYPE=TRAPEZ]\nG132 Y30\nG1 Y10 F3000\nM30\n");
  EXPECT_EQ(warning_ids(at_line(d, 3)).size(), 2u);
  expect_ramps(at_line(d, 4).limits, 0.020, 4);
}

TEST(DynWeights, RampWeightingsBeyondTheirRangeAreLimitedAndWarned) {
  Rig r;
  const auto c = r.plan("G0 X0 Y0 Z0\n#SLOPE [TYPE=TRAPEZ]\nG133=10000000\nG1 X10 F3000\nG133=100 G134=99\n"
                        "G233=99\nG0 X20\nG233=100000000\nG233=150 G134=150\nM30\n");
  using V = std::vector<ErrorId>;
  const ErrorId above = ErrorId::KernelWeightRampAboveMax, geom = ErrorId::KernelWeightGeomRampLimited;
  EXPECT_EQ(warning_ids(at_line(c, 3)), (V{above, above, above, above}));  // 5000 s: X, Y, Z and C
  expect_ramps(at_line(c, 4).limits, 4294.967295, 4);
  EXPECT_EQ(warning_ids(at_line(c, 5)), (V{geom, geom, geom, geom}));  // tr_geom 9.9 ms < tr_min
  EXPECT_EQ(warning_text(at_line(c, 5), r.store, geom),
            "axis X: tr_geom 0.01 s at 99 % is 0.0099 s, below tr_min 0.01 s: 0.01 s used");
  const ErrorId rapid_low = ErrorId::KernelWeightRapidRampBelowMin;
  EXPECT_EQ(warning_ids(at_line(c, 6)), (V{rapid_low, rapid_low, rapid_low, rapid_low}));
  expect_ramps(at_line(c, 7).limits, 0.010, 7);  // tr_grenz 10 ms, not 9.9
  const ErrorId rapid_high = ErrorId::KernelWeightRapidRampAboveMax;
  EXPECT_EQ(warning_ids(at_line(c, 8)), (V{rapid_high, rapid_high, rapid_high, rapid_high}));
  EXPECT_TRUE(warning_ids(at_line(c, 9)).empty());
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
