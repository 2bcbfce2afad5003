// Planner: decoded blocks -> commands for the cyclic executor. Blocks come
// from program texts decoded with the example machines' own decoder
// configuration; every expected number is worked out by hand from the
// example lists (examples/mill: G54 = X100 Y50 Z-150, G55 = X200 Y100 Z-150,
// D1 = length 100 mm, D2 = 125 mm, clamp group 1 = X10 Y-5; axes X Y Z with
// max_speed_mm_s = rapid_mm_s = 500 mm/s, X/Y accel_mm_s2 2500 rapid_accel_mm_s2 3000 a_max 3000,
// Z accel_mm_s2 2000 rapid_accel_mm_s2 2500 a_max 2500, software limits X ±500, Y ±400,
// Z -400..200, reference_pos 0).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "nck/prep/planner.hpp"
#include "example_blocks.hpp"
#include "planner_rig.hpp"
#include "planned_parts.hpp"

namespace nck::prep {
namespace {

using testing::decode_blocks;
using testing::example_machine;
using testing::PlannerRig;
constexpr double kPi = std::numbers::pi;


// Machine-coordinate end point of a motion command, first three axes.
void expect_end(const PlannedCommand& c, double x, double y, double z) {
  ASSERT_EQ(c.kind, CommandKind::motion) << "line " << c.head.line;
  const motion::AxisVector& e = c.segment.end_point();
  EXPECT_NEAR(e[0], x, 1e-9) << "line " << c.head.line;
  EXPECT_NEAR(e[1], y, 1e-9) << "line " << c.head.line;
  EXPECT_NEAR(e[2], z, 1e-9) << "line " << c.head.line;
}

void expect_error(const PlannedCommand& c, ErrorId id, std::uint32_t line) {
  EXPECT_EQ(c.kind, CommandKind::error);
  EXPECT_EQ(test::error_of(c).id, id);
  EXPECT_EQ(c.head.line, line);
}

TEST(Planner, RapidMoveAtG53GoesToTheProgrammedMachinePosition) {
  PlannerRig r("mill");
  auto c = r.plan("N10 G90 G0 X10 Y20 Z30\nM30\n");
  ASSERT_EQ(c.size(), 2u);
  expect_end(c[0], 10, 20, 30);
  EXPECT_FALSE(c[0].head.feed_motion);
  EXPECT_EQ(c[0].head.n, std::optional<std::int64_t>(10));
  EXPECT_EQ(c[0].head.line, 1u);
  EXPECT_EQ(c[1].kind, CommandKind::end);
  EXPECT_EQ(test::end_reason_of(c[1]), EndReason::m30);
}

TEST(Planner, RapidAlongOneAxisUsesRapidVelocityAndAGrenz) {
  PlannerRig r("mill");
  auto c = r.plan("G0 X100\nG0 Z-10\nM30\n");
  // X: rapid_mm_s 500 mm/s, min(rapid_accel_mm_s2 3000, a_max 3000).
  EXPECT_DOUBLE_EQ(c[0].v_cmd_mm_s, 500.0);
  EXPECT_DOUBLE_EQ(c[0].limits.a_acc_mm_s2, 3000.0);
  // Z: min(rapid_accel_mm_s2 2500, a_max 2500).
  EXPECT_DOUBLE_EQ(c[1].limits.a_acc_mm_s2, 2500.0);
  EXPECT_DOUBLE_EQ(c[1].segment.length(), 10.0);
}

TEST(Planner, FeedInMmPerMinuteBecomesMmPerSecond) {
  PlannerRig r("mill");
  auto c = r.plan("G1 X100 F1200\nG1 Z-10\nM30\n");
  EXPECT_TRUE(c[0].head.feed_motion);
  EXPECT_DOUBLE_EQ(c[0].v_cmd_mm_s, 20.0);            // 1200 / 60
  EXPECT_DOUBLE_EQ(c[0].limits.a_acc_mm_s2, 2500.0);  // X accel_mm_s2
  EXPECT_DOUBLE_EQ(c[1].v_cmd_mm_s, 20.0);            // F is modal
  EXPECT_DOUBLE_EQ(c[1].limits.a_acc_mm_s2, 2000.0);  // Z accel_mm_s2
}

TEST(Planner, DiagonalLineLimitsComeFromTheLoadedAxis) {
  PlannerRig r("mill");
  // X30 Y40: length 50, direction (0.6, 0.8); Y is the limiting axis:
  // v = 500 / 0.8 = 625 mm/s, a = 2500 / 0.8 = 3125 mm/s^2.
  auto c = r.plan("G1 X30 Y40 F60000\nM30\n");
  EXPECT_DOUBLE_EQ(c[0].segment.length(), 50.0);
  EXPECT_NEAR(c[0].limits.v_max_mm_s, 625.0, 1e-9);
  EXPECT_NEAR(c[0].limits.a_acc_mm_s2, 3125.0, 1e-9);
  EXPECT_DOUBLE_EQ(c[0].v_cmd_mm_s, 1000.0);  // F as programmed; the executor caps it
}

TEST(Planner, InchUnitsScaleWordsAndFeed) {
  PlannerRig r("mill");
  auto c = r.plan("G70 G1 X1 F10\nM30\n");
  expect_end(c[0], 25.4, 0, 0);
  EXPECT_NEAR(c[0].v_cmd_mm_s, 254.0 / 60.0, 1e-12);
}

TEST(Planner, FeedMoveWithoutFeedIsError930002) {
  PlannerRig r("mill");
  auto c = r.plan("G0 X1\nG1 X10\nM30\n");
  expect_error(c[1], ErrorId::KernelNoFeed, 2);
  EXPECT_EQ(static_cast<std::uint32_t>(test::error_of(c[1]).id), 930002u);
}

TEST(Planner, IncrementalWordsAddToTheProgrammedPosition) {
  PlannerRig r("mill");
  auto c = r.plan("G0 X10 Y10\nG91 G1 X5 F1000\nY-15\nG90 X0\nM30\n");
  expect_end(c[1], 15, 10, 0);
  expect_end(c[2], 15, -5, 0);
  expect_end(c[3], 0, -5, 0);
}

TEST(Planner, ZeroLengthMoveIsANop) {
  PlannerRig r("mill");
  auto c = r.plan("G0 X0 Y0\nM30\n");
  EXPECT_EQ(c[0].kind, CommandKind::nop);
}

TEST(Planner, G54AndG55ShiftTheMachineTarget) {
  PlannerRig r("mill");
  // PCS (0, 0, 50) + G54 (100, 50, -150); then + G55 (200, 100, -150).
  auto c = r.plan("G54 G0 X0 Y0 Z50\nG55 G0 X0 Y0 Z50\nG53 G0 X1 Y2 Z3\nM30\n");
  expect_end(c[0], 100, 50, -100);
  expect_end(c[1], 200, 100, -100);
  expect_end(c[2], 1, 2, 3);
}

TEST(Planner, ToolLengthOfD1ActsOnZ) {
  PlannerRig r("mill");
  // offsets.nc N40: Z = 50 - 150 + 100 = 0.
  auto c = r.plan("G54\nD1\nG0 X0 Y0 Z50\nM30\n");
  EXPECT_EQ(c[1].kind, CommandKind::nop);  // move_tool_offsets_directly 0
  expect_end(c[2], 100, 50, 0);
}

TEST(Planner, NewToolLengthUnderG91WaitsForTheNextAbsoluteWord) {
  PlannerRig r("mill");
  // tools.nc: D1 at Z0 -> Z100; G91 D2, Z-10 -> 90 (the 125 mm waits);
  // G90 Z-10 -> -10 + 125 = 115.
  auto c = r.plan("D1\nG0 Z0\nG91 D2\nG0 Z-10\nG90 G0 Z-10\nM30\n");
  expect_end(c[1], 0, 0, 100);
  expect_end(c[3], 0, 0, 90);
  expect_end(c[4], 0, 0, 115);
}

TEST(Planner, UnknownToolIsAnErrorWithTheBlocksLine) {
  PlannerRig r("mill");
  auto c = r.plan("G0 X1\nD7\nM30\n");
  expect_error(c[1], ErrorId::KernelUnknownTool, 2);
}

TEST(Planner, G92IsAnAdditiveShift) {
  PlannerRig r("mill");
  // offsets.nc N50..N80: G92 X10 puts X0 10 mm further on; G92 X0 removes it.
  auto c = r.plan("G54 G0 X0 Y0 Z0\nG92 X10\nG1 X0 F2000\nG92 X0\nG0 X0\nM30\n");
  EXPECT_EQ(c[1].kind, CommandKind::nop);  // G92's X is an offset, not a move
  expect_end(c[2], 110, 50, -150);
  expect_end(c[4], 100, 50, -150);
}

TEST(Planner, ClampOffsetOfTheChosenGroupActsFromTheStart) {
  PlannerRig r("mill", 1);
  auto c = r.plan("G0 X1 Y1\nM30\n");
  expect_end(c[0], 11, -4, 0);  // + clamp group 1 (10, -5)
}

TEST(Planner, RotatedCoordinateSystemMapsTheTarget) {
  PlannerRig r("mill");
  // offsets.nc N90/N100: CS shift (20, 0), 90 deg about Z: PCS (10, 0) ->
  // (0, 10) + (20, 0) + G54 (100, 50) = (120, 60); Z stays at -150.
  auto c = r.plan("G54 G0 X0 Y0 Z0\n#CS ON [1][20,0,0,0,0,90]\nG1 X10 Y0 F2000\n#CS OFF\nG0 X0 Y0\nM30\n");
  expect_end(c[2], 120, 60, -150);
  expect_end(c[4], 100, 50, -150);
}

TEST(Planner, RotationTurnsTheContourAboutTheProgramOrigin) {
  PlannerRig r("mill");
  // PCS (20, 0) turned 45 deg: (14.142.., 14.142..) + G54.
  auto c = r.plan("G54 G0 X0 Y0 Z0\n#ROTATION ON [ANGLE=45]\nG1 X20 Y0 F2000\nM30\n");
  const double h = 20 * std::sqrt(0.5);
  expect_end(c[2], 100 + h, 50 + h, -150);
}

TEST(Planner, PsetMakesTheCurrentPositionReadTheGivenValue) {
  PlannerRig r("mill");
  // At MCS X100 (PCS 0), #PSET X5: X15 is 10 mm further on -> MCS 110;
  // after #PRESET, X0 is MCS 100 again.
  auto c = r.plan("G54 G0 X0 Y0 Z0\n#PSET X5\nG1 X15 F2000\n#PRESET\nG0 X0\nM30\n");
  expect_end(c[2], 110, 50, -150);
  expect_end(c[4], 100, 50, -150);
}

TEST(Planner, SoftwareLimitIsError930003) {
  PlannerRig r("mill");
  auto c = r.plan("G0 X1\nG0 Z250\nM30\n");  // Z sw_limit_pos 200 mm
  expect_error(c[1], ErrorId::KernelSoftwareLimit, 2);
}

TEST(Planner, CcwHalfCircleWithCentre) {
  PlannerRig r("mill");
  // Start (0, 0), centre (10, 0): start angle 180 deg, end (20, 0) at 0 deg
  // counter-clockwise -> sweep +pi, radius 10, length 10 pi.
  auto c = r.plan("G0 X0 Y0\nG3 X20 Y0 I10 J0 F600\nM30\n");
  ASSERT_EQ(c[1].kind, CommandKind::motion);
  const motion::Segment& s = c[1].segment;
  ASSERT_EQ(s.kind(), motion::SegmentKind::arc);
  EXPECT_NEAR(s.center_a(), 10, 1e-9);
  EXPECT_NEAR(s.center_b(), 0, 1e-9);
  EXPECT_NEAR(s.radius_start(), 10, 1e-9);
  EXPECT_NEAR(s.sweep_rad(), kPi, 1e-9);
  EXPECT_NEAR(s.length(), 10 * kPi, 1e-9);
  expect_end(c[1], 20, 0, 0);
}

TEST(Planner, ArcCentreIsShiftedByTheZeroOffset) {
  PlannerRig r("mill");
  // In G54, centre PCS (10, 0) = MCS (110, 50); end PCS (10, -10) lies on
  // the circle; G3 from 180 deg to 270 deg is a quarter: length 5 pi.
  auto c = r.plan("G54 G0 X0 Y0 Z0\nG3 X10 Y-10 I10 J0 F600\nM30\n");
  const motion::Segment& s = c[1].segment;
  ASSERT_EQ(s.kind(), motion::SegmentKind::arc);
  EXPECT_NEAR(s.center_a(), 110, 1e-9);
  EXPECT_NEAR(s.center_b(), 50, 1e-9);
  EXPECT_NEAR(s.sweep_rad(), kPi / 2, 1e-9);
  EXPECT_NEAR(s.length(), 5 * kPi, 1e-9);
  expect_end(c[1], 110, 40, -150);
}

TEST(Planner, ClockwiseArcWithRadiusInG18OnTheLathe) {
  PlannerRig r("lathe");
  // turn.nc N80: from X10 Z-20 G2 X20 Z-30 R10. In G18 the plane is (Z, X);
  // of the two centres (Z-30, X10) and (Z-20, X20) only the second gives a
  // clockwise quarter: start at -90 deg, end at 180 deg, sweep -pi/2.
  auto c = r.plan("G18 G90 G0 X10 Z-20\nG2 X20 Z-30 R10 F250\nM30\n");
  const motion::Segment& s = c[1].segment;
  ASSERT_EQ(s.kind(), motion::SegmentKind::arc);
  EXPECT_EQ(s.plane_a(), 1u);  // Z is the lathe's second channel axis
  EXPECT_EQ(s.plane_b(), 0u);
  EXPECT_NEAR(s.center_a(), -20, 1e-9);
  EXPECT_NEAR(s.center_b(), 20, 1e-9);
  EXPECT_NEAR(s.sweep_rad(), -kPi / 2, 1e-9);
  EXPECT_NEAR(s.end_point()[0], 20, 1e-9);
  EXPECT_NEAR(s.end_point()[1], -30, 1e-9);
}

TEST(Planner, LatheToolOffsetsActOnXAndZ) {
  PlannerRig r("lathe");
  // G54 Z200, D1 ax_versatz X25 Z50: X10 -> 35, Z-240 -> -240 + 200 + 50 = 10.
  auto c = r.plan("G18 G54 D1 G0 X10 Z-240\nM30\n");
  ASSERT_EQ(c[0].kind, CommandKind::motion);
  EXPECT_NEAR(c[0].segment.end_point()[0], 35, 1e-9);
  EXPECT_NEAR(c[0].segment.end_point()[1], 10, 1e-9);
}

TEST(Planner, EndPointOffTheCircleIsError930004) {
  PlannerRig r("mill");
  // Centre (10, 0): start radius 10, end (30, 0) radius 20.
  auto c = r.plan("G0 X0 Y0\nN20 G2 X30 Y0 I10 J0 F600\nM30\n");
  expect_error(c[1], ErrorId::KernelArcEndNotOnCircle, 2);
  EXPECT_EQ(static_cast<std::uint32_t>(test::error_of(c[1]).id), 930004u);
}

TEST(Planner, RadiusSmallerThanHalfTheChordIsError930006) {
  PlannerRig r("mill");
  auto c = r.plan("G0 X0 Y0\nG2 X30 Y0 R10 F600\nM30\n");  // chord 30 > 2 R
  expect_error(c[1], ErrorId::KernelArcRadiusTooSmall, 2);
}

TEST(Planner, HomingSplitsIntoOrderGroups) {
  PlannerRig r("mill");
  // G74 X1 Y2 Z1: X and Z (order 1) home together, then Y (order 2), each to
  // reference_pos 0 at rapid; only the first command shows the block.
  auto c = r.plan("G0 X10 Y20 Z30\nG74 X1 Y2 Z1\nM30\n");
  ASSERT_EQ(c.size(), 4u);
  expect_end(c[1], 0, 20, 0);
  EXPECT_TRUE(c[1].head.emit_block_event);
  expect_end(c[2], 0, 0, 0);
  EXPECT_FALSE(c[2].head.emit_block_event);
  EXPECT_EQ(c[2].head.line, 2u);
  // rapid along X and Z together: length sqrt(10^2 + 30^2)
  EXPECT_NEAR(c[1].segment.length(), std::hypot(10.0, 30.0), 1e-9);
  EXPECT_EQ(c[3].kind, CommandKind::end);
  // Each group's command says which axes it homes (the kernel marks them
  // homed at its end, P-AXIS-00277): X and Z, then Y.
  const auto* first = c[1].find<kernel::HomeAxes>();
  const auto* second = c[2].find<kernel::HomeAxes>();
  ASSERT_TRUE(first && second);
  EXPECT_EQ(first->mask, 0b101u);
  EXPECT_EQ(second->mask, 0b010u);
  EXPECT_FALSE(c[0].has<kernel::HomeAxes>());
}

TEST(Planner, M2AndM30EndTheProgramWithTheirReason) {
  PlannerRig a("mill");
  EXPECT_EQ(test::end_reason_of(a.plan("G0 X1\nM2\n").back()), EndReason::m2);
  PlannerRig b("mill");
  auto c = b.plan("G0 X1\nM30\n");
  EXPECT_EQ(c.back().kind, CommandKind::end);
  EXPECT_EQ(test::end_reason_of(c.back()), EndReason::m30);
}

TEST(Planner, DwellInSeconds) {
  PlannerRig r("mill");
  auto c = r.plan("G4 X0.5\nM30\n");
  EXPECT_EQ(c[0].kind, CommandKind::dwell);
  EXPECT_DOUBLE_EQ(std::get<kernel::Dwell>(c[0].step).time_s, 0.5);
}

TEST(Planner, FunctionsNotExecutedYetAreError930001) {
  PlannerRig r("mill");
  // Writing the tool radius V.G.WZ_AKT.R is decoded but not executed.
  auto c = r.plan("G0 X1\nV.G.WZ_AKT.R = 5\nM30\n");
  expect_error(c[1], ErrorId::KernelNotYetSupported, 2);
  EXPECT_EQ(static_cast<std::uint32_t>(test::error_of(c[1]).id), 930001u);
  EXPECT_NE(r.store.messages.at(*test::error_of(c[1]).message).find("V.G.WZ_AKT.R"), std::string::npos);
}

TEST(Planner, ChannelMFunctionsAreOutputWithTheirSynchronisation) {
  PlannerRig r("mill");
  // channel1.lis: m_synch[8] MOS, m_synch[6] MVS_SVS.
  auto c = r.plan("M8\nM6\nM30\n");
  ASSERT_EQ(test::attached<kernel::Output>(c[0]).size(), 1u);
  EXPECT_EQ(test::attached<kernel::Output>(c[0])[0].fn, TechKind::m);
  EXPECT_EQ(test::attached<kernel::Output>(c[0])[0].number, 8);
  EXPECT_EQ(test::attached<kernel::Output>(c[0])[0].sync, config::sync::MOS);
  ASSERT_EQ(test::attached<kernel::Output>(c[1]).size(), 1u);
  EXPECT_EQ(test::attached<kernel::Output>(c[1])[0].sync, config::sync::MVS_SVS);
}

TEST(Planner, OffsetChangesAreRecordedForTheirEvents) {
  PlannerRig r("mill");
  auto c = r.plan("G54 D1\nM30\n");
  const auto offsets = test::attached<frames::OffsetEvent>(c[0]);
  ASSERT_EQ(offsets.size(), 2u);
  const OffsetPayload& zero = r.store.offsets.at(offsets[0].index);
  EXPECT_EQ(zero.kind, "zero");
  ASSERT_EQ(zero.values.size(), 4u);  // X Y Z and S1 as C axis
  EXPECT_EQ(zero.values[0].first, "X");
  EXPECT_DOUBLE_EQ(zero.values[0].second, 100.0);
  EXPECT_DOUBLE_EQ(zero.values[2].second, -150.0);
  const OffsetPayload& tool = r.store.offsets.at(offsets[1].index);
  EXPECT_EQ(tool.kind, "tool");
  EXPECT_DOUBLE_EQ(tool.values[2].second, 100.0);
}

TEST(Planner, IncrementalArcResolvesEndAndCentreFromTheStart) {
  PlannerRig r("mill");
  // From (5, 5): G91 end +20/0 -> (25, 5); centre start + (10, 0) = (15, 5).
  auto c = r.plan("G0 X5 Y5\nG91 G3 X20 Y0 I10 J0 F600\nM30\n");
  const motion::Segment& s = c[1].segment;
  ASSERT_EQ(s.kind(), motion::SegmentKind::arc);
  EXPECT_NEAR(s.center_a(), 15, 1e-9);
  EXPECT_NEAR(s.center_b(), 5, 1e-9);
  expect_end(c[1], 25, 5, 0);
}

TEST(Planner, AbsoluteCentreG161IsInProgramCoordinates) {
  PlannerRig r("mill");
  // G54, G161: I10 J0 is the PCS point (10, 0) = MCS (110, 50).
  auto c = r.plan("G54 G0 X0 Y0 Z0\nG161 G2 X20 Y0 I10 J0 F600\nM30\n");
  const motion::Segment& s = c[1].segment;
  ASSERT_EQ(s.kind(), motion::SegmentKind::arc);
  EXPECT_NEAR(s.center_a(), 110, 1e-9);
  EXPECT_NEAR(s.center_b(), 50, 1e-9);
  EXPECT_NEAR(s.sweep_rad(), -kPi, 1e-9);
  expect_end(c[1], 120, 50, -150);
}

TEST(Planner, InchArcScalesCentreWords) {
  PlannerRig r("mill");
  // G70: X2 = 50.8 mm, I1 = 25.4 mm.
  auto c = r.plan("G70 G3 X2 Y0 I1 J0 F10\nM30\n");
  const motion::Segment& s = c[0].segment;
  ASSERT_EQ(s.kind(), motion::SegmentKind::arc);
  EXPECT_NEAR(s.center_a(), 25.4, 1e-9);
  EXPECT_NEAR(s.radius_start(), 25.4, 1e-9);
  expect_end(c[0], 50.8, 0, 0);
}

TEST(Planner, HelixLengthCountsTheThirdAxis) {
  PlannerRig r("mill");
  // contour.nc N190: a full turn of radius 15 down 3 mm.
  auto c = r.plan("G0 X15 Y0\nG3 X15 Y0 Z-3 I-15 J0 F900\nM30\n");
  const motion::Segment& s = c[1].segment;
  ASSERT_EQ(s.kind(), motion::SegmentKind::arc);
  EXPECT_NEAR(s.sweep_rad(), 2 * kPi, 1e-9);
  EXPECT_NEAR(s.length(), std::hypot(2 * kPi * 15, 3.0), 1e-9);
  expect_end(c[1], 15, 0, -3);
}

TEST(Planner, ArcUnderRotationIsMappedFromProgramCoordinates) {
  PlannerRig r("mill");
  // #ROTATION 90: the arc is planned in PCS and mapped; its end (20, 0)
  // turned 90 deg is MCS (0, 20).
  auto c = r.plan("G0 X0 Y0\n#ROTATION ON [ANGLE=90]\nG3 X20 Y0 I10 J0 F600\nM30\n");
  ASSERT_EQ(c[2].kind, CommandKind::motion);
  EXPECT_TRUE(c[2].has<kernel::ProgramMap>());
  motion::AxisVector m{};
  c[2].find<kernel::ProgramMap>()->map.apply(c[2].segment.end_point(), m, 3);
  EXPECT_NEAR(m[0], 0, 1e-9);
  EXPECT_NEAR(m[1], 20, 1e-9);
}

TEST(Planner, HomingClearsThePreset) {
  PlannerRig r("mill");
  // #PSET X5 at MCS X100 shifts X by -5; G74 homes X (to MCS 0) and clears
  // it: G0 X0 is MCS 100 again (not 95).
  auto c = r.plan("G54 G0 X0 Y0 Z0\n#PSET X5\nG74 X1\nG0 X0\nM30\n");
  expect_end(c[2], 0, 50, -150);
  expect_end(c[3], 100, 50, -150);
}

TEST(Planner, IncrementalG92AddsToTheShift) {
  PlannerRig r("mill");
  // G92 X10, then G91 G92 X5: 15 mm in all; G90 X0 -> MCS 15.
  auto c = r.plan("G92 X10\nG91 G92 X5\nG90 G1 X0 F1000\nM30\n");
  expect_end(c[2], 15, 0, 0);
}

TEST(Planner, SoftwareLimitAppliesToTheMachinePositionAfterOffsets) {
  PlannerRig r("mill");
  // G55 X301 is MCS 501, beyond sw_limit_pos 500; X299 (MCS 499) is fine.
  auto c = r.plan("G55 G0 X299\nG0 X301\nM30\n");
  expect_end(c[0], 499, 0, 0);
  expect_error(c[1], ErrorId::KernelSoftwareLimit, 2);
}

TEST(Planner, IncrementalMoveAfterCsOnRunsAlongTheTurnedAxis) {
  PlannerRig r("mill");
  // The axes stay at MCS (0, 0) when the CS (turned 90 deg) comes on; G91
  // X10 is 10 mm along the CS X axis, which is the machine's +Y.
  auto c = r.plan("G0 X0 Y0\n#CS ON [1][0,0,0,0,0,90]\nG91 G1 X10 F1000\nM30\n");
  expect_end(c[2], 0, 10, 0);
}

TEST(Planner, ZeroOffsetUnderG91WaitsForTheNextAbsoluteWord) {
  PlannerRig r("mill");
  // G91 G54 X10 moves 10 mm (G54 waits); G90 X0 then lands on G54's X100;
  // Y was never programmed absolutely and stays.
  auto c = r.plan("G91 G54 G0 X10\nG90 X0\nM30\n");
  expect_end(c[0], 10, 0, 0);
  expect_end(c[1], 100, 0, 0);
}

TEST(Planner, CircleWithoutCentreOrRadiusIsError930005) {
  PlannerRig r("mill");
  auto c = r.plan("G0 X0 Y0\nG2 X10 Y0 F600\nM30\n");
  expect_error(c[1], ErrorId::KernelArcNoCenter, 2);
}

TEST(Planner, ProgramStopIsAStopCommand) {
  PlannerRig r("mill");
  auto c = r.plan("M0\nM30\n");
  EXPECT_EQ(c[0].kind, CommandKind::stop);
}

}  // namespace
}  // namespace nck::prep
