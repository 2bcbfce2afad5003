// G74 on a real drive (kernel::HomingSearch): a conventional drive's axis
// searches its home cam, the cam's edge becomes pos_refpkt without a jump
// in the drive's set point, and the homing block's motion then brings the
// axis to pos_refpkt. Every cycle keeps the drive within the homing speed
// and acceleration while searching, and within the axis's limits after.
// An axis on its cam only leaves it; no cam is an error within the time;
// a reset brakes the search and homes nothing.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "../seen_events.hpp"
#include "test_machine.hpp"

namespace nck::kernel {
namespace {

using testing::KernelRig;

constexpr double kDt = 0.001;
constexpr double kVmax = 500, kAmax = 2000;
constexpr double kFast = 50, kSlow = 10, kAref = 500;
constexpr double kReference = 5.0;  // pos_refpkt
constexpr double kCamEdge = -37.5;  // where the cam begins, in the drive's coordinates (unknown to the NC)

config::Machine machine(double timeout_s = 60) {
  config::Machine m = testing::xyz_machine(kVmax, kAmax);
  config::AxisConfig& x = m.axes[0];
  x.drive_type = 1;  // conventional: the NC homes it on its cam
  x.homing_positive = false;
  x.fast_from_cam = false;
  x.drive_homing_timeout_s = timeout_s;
  for (auto& g : x.gears) {
    g.homing_fast_mm_s = kFast;
    g.homing_slow_mm_s = kSlow;
    g.homing_accel_mm_s2 = kAref;
    g.reference_pos = kReference;
  }
  return m;
}

nc::Block g74_x(std::uint32_t line) {
  nc::Block b;
  b.line = line;
  (void)b.g_nonmodal.add(nc::GCode::g74);
  b.axes[0] = 1.0;
  return b;
}


struct Homing {
  test::EventLog log;
  std::vector<double> drive;  // X's drive position per cycle
  std::vector<bool> searching;  // the channel waited for the search in that cycle
};

// Runs G74 X1 (and M30) with a cam on where the drive stands at or below
// cam_edge, answered one cycle late as a real switch is; reset_after:
// the operator's reset in that cycle (-1: none).
Homing run_g74(KernelRig& rig, double cam_edge, int cycles, int reset_after = -1) {
  rig.push_block(0, g74_x(1));
  rig.push_block(0, testing::end_block(2));
  TickInput in;
  TickOutput out;
  Homing h;
  rig.k.set_homed_axes(0, 0);
  for (int i = 0; i < cycles && !rig.k.all_channels_done(); ++i) {
    in.axes[0].home_cam = h.drive.empty() ? 0.0 <= cam_edge : h.drive.back() <= cam_edge;
    in.channels[0].reset = i == reset_after;
    rig.k.tick(in, out);
    h.log.take(out);
    h.drive.push_back(out.channels[0].drive_pos(0));
    h.searching.push_back(out.channels[0].cause == CycleCause::wait &&
                          out.channels[0].wait_reason == WaitReason::homing);
  }
  return h;
}

// Every cycle: the drive's speed within v_max (the homing speed while the
// search runs) and its acceleration within a (a_ref while searching).
void expect_within_limits(const Homing& h) {
  double v_last = 0, p_last = 0;
  for (std::size_t i = 0; i < h.drive.size(); ++i) {
    const double v = (h.drive[i] - p_last) / kDt;
    const double v_cap = h.searching[i] ? kFast : kVmax;
    const double a_cap = h.searching[i] ? kAref : kAmax;
    EXPECT_LE(std::abs(v), v_cap * (1 + 1e-9)) << "cycle " << i;
    EXPECT_LE(std::abs(v - v_last) / kDt, a_cap * (1 + 1e-6) + 1e-6) << "cycle " << i;
    v_last = v;
    p_last = h.drive[i];
  }
}

TEST(HomingSearch, FindsTheCamSetsTheReferenceAtItsEdgeAndEndsAtPosRefpkt) {
  KernelRig rig(machine());
  const Homing h = run_g74(rig, kCamEdge, 20000);
  ASSERT_TRUE(rig.k.all_channels_done());
  EXPECT_TRUE(test::seen<ev::Error>(h.log.events).empty());
  EXPECT_EQ(rig.k.program_state(0), ProgramState::ended);
  expect_within_limits(h);
  // The drive went past the edge towards the cam (negative) and back.
  EXPECT_LT(*std::min_element(h.drive.begin(), h.drive.end()), kCamEdge);
  // It stands at the cam's edge, which is pos_refpkt now (within one slow cycle).
  const ChannelState st = rig.k.channel_state(0);
  EXPECT_DOUBLE_EQ(st.axis_mcs[0], kReference);
  EXPECT_NEAR(h.drive.back(), kCamEdge, kSlow * kDt + 1e-9);
  EXPECT_GT(h.drive.back(), kCamEdge);
  EXPECT_EQ(st.homed_axes & 1u, 1u);
  EXPECT_EQ(test::seen<ev::Wait>(h.log.events).size(), 1u);
  EXPECT_EQ(test::seen<ev::WaitEnd>(h.log.events).size(), 1u);
}

TEST(HomingSearch, AnAxisOnItsCamOnlyLeavesIt) {
  KernelRig rig(machine());
  const Homing h = run_g74(rig, 10.0, 20000);  // the cam reaches up to +10: X at 0 stands on it
  ASSERT_TRUE(rig.k.all_channels_done());
  expect_within_limits(h);
  EXPECT_GE(*std::min_element(h.drive.begin(), h.drive.end()), 0.0);  // never towards the cam
  EXPECT_NEAR(h.drive.back(), 10.0, kSlow * kDt + 1e-9);
  EXPECT_DOUBLE_EQ(rig.k.channel_state(0).axis_mcs[0], kReference);
}

TEST(HomingSearch, NoCamIsAnErrorNamingTheAxisAfterItsTime) {
  KernelRig rig(machine(0.5));
  const Homing h = run_g74(rig, -1e9, 5000);
  ASSERT_TRUE(rig.k.all_channels_done());
  expect_within_limits(h);
  const auto errors = test::seen<ev::Error>(h.log.events);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].id, ErrorId::KernelHomingCamNotFound);
  ASSERT_TRUE(errors[0].axis.has_value());
  EXPECT_EQ(*errors[0].axis, 0);
  // Raised after 0.5 s and the braking from the fast speed, not before.
  EXPECT_GE(h.drive.size(), 500u + static_cast<std::size_t>(kFast / kAref / kDt) - 2);
  EXPECT_EQ(h.drive.end()[-1], h.drive.end()[-2]);  // at standstill
  EXPECT_EQ(rig.k.program_state(0), ProgramState::error);
  EXPECT_EQ(rig.k.channel_state(0).homed_axes & 1u, 0u);
}

TEST(HomingSearch, AResetBrakesTheSearchAndHomesNothing) {
  KernelRig rig(machine());
  const Homing h = run_g74(rig, kCamEdge, 5000, 300);  // at full fast speed by then
  ASSERT_TRUE(rig.k.all_channels_done());
  expect_within_limits(h);
  EXPECT_EQ(h.drive.end()[-1], h.drive.end()[-2]);
  EXPECT_GT(h.drive.back(), kCamEdge);  // stopped before the cam
  // Braked with a_ref from 50 mm/s: 0.1 s.
  EXPECT_LE(h.drive.size(), 300u + static_cast<std::size_t>(kFast / kAref / kDt) + 3);
  EXPECT_EQ(rig.k.channel_state(0).homed_axes & 1u, 0u);
  EXPECT_EQ(rig.k.channel_state(0).axis_mcs[0], h.drive.back());  // no reference: no offset
}

}  // namespace
}  // namespace nck::kernel
