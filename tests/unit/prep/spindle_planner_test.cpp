// SpindlePlanner: NC spindle words -> SpindleActions (FCT-S1 §2.3-§2.8,
// docs/nc-language.md "Spindles", FCT-S1 2.5.2 both examples, 2.8.2 both gear examples, 2.8.5 tool data).
#include <gtest/gtest.h>

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "nck/prep/spindle_planner.hpp"
#include "../kernel/test_machine.hpp"

namespace nck::prep {

namespace {

using nc::SpindleM;
namespace sync = config::sync;

// X Y Z plus two spindles: S1 (log 6, the main spindle "S") and S2 (log 7).
config::Machine spindle_machine() {
  config::Machine m = kernel::testing::xyz_machine();
  for (std::uint32_t nr : {6u, 7u}) {
    config::AxisConfig ax;
    ax.log_axis_nr = nr;
    ax.name = nr == 6 ? "S1" : "S2";
    ax.kind = config::AxisKind::spindle;
    m.axes.push_back(ax);
    config::ChannelSpindle sp;
    sp.name = ax.name;
    sp.log_axis_nr = nr;
    sp.axis_index = static_cast<int>(m.axes.size() - 1);
    m.channels[0].spindles.push_back(sp);
  }
  m.channels[0].main_spindle_ax_nr = 6;
  return m;
}

// Seed FCT-S1 2.8.2 range table on the main spindle, gear change enabled.
config::Machine gear_machine(bool autom) {
  config::Machine m = spindle_machine();
  auto& sp = m.channels[0].spindles[0];
  sp.autom_range = autom;
  const double t[6][2] = {{50, 560}, {400, 800}, {700, 3500}, {3501, 4000}, {3800, 5500}, {5400, 7000}};
  for (int i = 0; i < 6; ++i) sp.range_table[i] = {t[i][0], t[i][1]};
  m.channels[0].main_spindle_gear_change = true;
  return m;
}

SpindlePlanner planner(const config::Machine& m) { return SpindlePlanner(m, 0, {0, 1}); }

// DIN words of the main spindle S (-> S1).
nc::Block din(std::uint32_t line, SpindleM m, std::optional<double> s = {},
              std::optional<int> gear = {}) {
  nc::Block b;
  b.line = line;
  nc::SpindleCommand c;
  c.name = "S";
  c.target = "S1";
  c.spindle_index = 0;  // as the decoder resolves it
  c.din = true;
  c.column = 5;
  c.m = m;
  c.rev_rpm = s;
  c.gear_stage = gear;
  b.spindles.push_back(c);
  return b;
}

// Spindle syntax S2[..].
nc::Block s2(std::uint32_t line, SpindleM m, std::optional<double> rev = {}) {
  nc::Block b = din(line, m, rev);
  b.spindles[0].name = "S2";
  b.spindles[0].target = "S2";
  b.spindles[0].spindle_index = 1;
  b.spindles[0].din = false;
  return b;
}

SpindleActions ok(SpindlePlanner& p, const nc::Block& b) {
  auto r = p.plan(b);
  EXPECT_TRUE(r.has_value()) << (r ? "" : format(r.error()));
  return r ? *r : SpindleActions{};
}

Diagnostic fails(SpindlePlanner& p, const nc::Block& b) {
  auto r = p.plan(b);
  EXPECT_FALSE(r.has_value());
  return r ? Diagnostic{} : r.error();
}

TEST(SpindlePlanner, RotateStoreStopAndModalSpeed) {
  auto m = spindle_machine();
  auto p = planner(m);
  // N10 S1000: a speed action; the kernel stores it since nothing turns
  auto a = ok(p, din(10, SpindleM::none, 1000));
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].op, SpindleOp::speed);
  EXPECT_EQ(a[0].rpm, 1000);
  EXPECT_EQ(a[0].wait, SpindleWait::speed_reached);  // dropped by the kernel when only stored
  EXPECT_EQ(a[0].fn, plc::TechKind::s);
  a = ok(p, din(20, SpindleM::m3));  // N20 M03: the stored speed
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].op, SpindleOp::rotate);
  EXPECT_EQ(a[0].spindle, 0);
  EXPECT_EQ(a[0].rpm, 1000);
  EXPECT_EQ(a[0].direction, spindle::Direction::positive);
  EXPECT_EQ(a[0].sync, SyncPoint::before);  // default MVS_SVS
  EXPECT_EQ(a[0].wait, SpindleWait::speed_reached);
  EXPECT_FALSE(a[0].output);
  EXPECT_EQ(a[0].fn, plc::TechKind::m);
  EXPECT_EQ(a[0].fn_number, 3);
  a = ok(p, din(40, SpindleM::none, 500));  // N40 S500: the kernel keeps the direction
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].op, SpindleOp::speed);
  EXPECT_EQ(a[0].rpm, 500);
  EXPECT_EQ(a[0].fn, plc::TechKind::s);
  a = ok(p, din(45, SpindleM::m4));
  EXPECT_EQ(a[0].rpm, -500);
  EXPECT_EQ(a[0].direction, spindle::Direction::negative);
  a = ok(p, din(50, SpindleM::m5, 300));  // N50 M05 S300: stop, S stored but not output
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].op, SpindleOp::stop);
  EXPECT_EQ(a[0].wait, SpindleWait::standstill);
  EXPECT_EQ(a[0].fn_number, 5);
  EXPECT_EQ(p.planned(0).speed_rpm, 300);
  a = ok(p, din(60, SpindleM::m3));
  EXPECT_EQ(a[0].rpm, 300);
}

// TF5200 M03/M04: without a valid speed they select the direction at 0 rpm.
TEST(SpindlePlanner, M3WithoutAnySpeedSelectsTheDirectionAtZeroRpm) {
  auto m = spindle_machine();
  auto p = planner(m);
  auto a = ok(p, din(7, SpindleM::m3));
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].op, SpindleOp::rotate);
  EXPECT_EQ(a[0].rpm, 0);
  EXPECT_EQ(a[0].direction, spindle::Direction::positive);
  EXPECT_FALSE(p.planned(0).speed_rpm.has_value());
  a = ok(p, s2(8, SpindleM::m4));
  EXPECT_EQ(a[0].op, SpindleOp::rotate);
  EXPECT_EQ(a[0].direction, spindle::Direction::negative);
  a = ok(p, din(9, SpindleM::m3, 100));
  EXPECT_EQ(a[0].rpm, 100);
}

TEST(SpindlePlanner, M19PositionSpeedAndDirection) {
  auto m = spindle_machine();
  auto p = planner(m);
  Diagnostic d = fails(p, din(5, SpindleM::m19));
  EXPECT_EQ(d.id, ErrorId::KernelSpindleM19NoSpeed);
  EXPECT_NE(d.message.find("M19 without speed"), std::string::npos);
  auto a = ok(p, din(10, SpindleM::m19, 200));  // no POS ever: 0 deg
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].op, SpindleOp::position);
  EXPECT_EQ(a[0].pos_deg, 0);
  EXPECT_EQ(a[0].rpm, 200);
  EXPECT_EQ(a[0].direction, spindle::Direction::none);
  EXPECT_EQ(a[0].wait, SpindleWait::in_position);
  EXPECT_EQ(a[0].fn_number, 19);
  nc::Block b = din(20, SpindleM::m19);  // M19 S.POS=180 M04: speed kept, POS modal
  b.spindles[0].pos_deg = 180;
  b.spindles[0].direction = SpindleM::m4;
  a = ok(p, b);
  EXPECT_EQ(a[0].pos_deg, 180);
  EXPECT_EQ(a[0].rpm, 200);
  EXPECT_EQ(a[0].direction, spindle::Direction::negative);
  b = din(30, SpindleM::m19);
  b.spindles[0].pos_shift_deg = 10;
  b.spindles[0].direction = SpindleM::m3;
  a = ok(p, b);
  EXPECT_EQ(a[0].pos_deg, 190);  // modal POS 180 + POS_SHIFT 10
  EXPECT_EQ(a[0].direction, spindle::Direction::positive);
  a = ok(p, din(40, SpindleM::none, 900));  // S while positioned: the kernel only stores it
  EXPECT_EQ(a[0].op, SpindleOp::speed);
}

TEST(SpindlePlanner, SyncBitsMapToSyncPoints) {
  EXPECT_FALSE(sync_point(sync::NO_SYNCH));
  EXPECT_EQ(sync_point(sync::MOS), SyncPoint::none);
  EXPECT_EQ(sync_point(sync::MVS_SVS), SyncPoint::before);
  EXPECT_EQ(sync_point(sync::MVS_SNS), SyncPoint::before_after);
  EXPECT_EQ(sync_point(sync::MNS_SNS), SyncPoint::after);
  EXPECT_EQ(sync_point(sync::MNE_SNS), SyncPoint::after);
  EXPECT_EQ(sync_point(sync::MVS_SLM), SyncPoint::late_motion);
  EXPECT_EQ(sync_point(sync::MVS_SLP), SyncPoint::late_explicit);
  EXPECT_EQ(sync_point(sync::MVS_SNS | sync::PLC_INFO), SyncPoint::before_after);
  EXPECT_FALSE(sync_point(sync::PLC_INFO));  // no type: NO_SYNCH
}

TEST(SpindlePlanner, PlcInfoAndPlcSpindlesOutputAndTimeouts) {
  auto m = spindle_machine();
  auto& sp1 = m.channels[0].spindles[0];
  sp1.m3_sync = sync::MVS_SNS | sync::PLC_INFO;
  sp1.m3_ack_timeout_s = 2.5;
  m.axes[4].axis_mode = 0x40000;  // S2: PLC spindle by axis list
  auto p = planner(m);
  auto a = ok(p, din(10, SpindleM::m3, 800));
  EXPECT_EQ(a[0].sync, SyncPoint::before_after);
  EXPECT_TRUE(a[0].output);
  EXPECT_EQ(a[0].wait, SpindleWait::speed_reached);  // internal + PLC acknowledgement
  EXPECT_EQ(a[0].sync_bits, sync::MVS_SNS | sync::PLC_INFO);
  EXPECT_EQ(a[0].ack_timeout_s, 2.5);
  a = ok(p, s2(20, SpindleM::m3, 400));
  EXPECT_EQ(a[0].spindle, 1);
  EXPECT_EQ(a[0].sync, SyncPoint::before);
  EXPECT_TRUE(a[0].output);
  EXPECT_EQ(a[0].wait, SpindleWait::none);  // the PLC acknowledgement only
  m.axes[4].axis_mode = 0x1;
  m.channels[0].spindles[1].plc_control = true;  // PLC spindle over the channel HLI
  auto q = planner(m);
  a = ok(q, s2(30, SpindleM::m5));
  EXPECT_TRUE(a[0].output);
  EXPECT_EQ(a[0].wait, SpindleWait::none);
}

TEST(SpindlePlanner, NoSynchMFunctionIsNotExecuted) {
  auto m = spindle_machine();
  m.channels[0].spindles[0].m3_sync = sync::NO_SYNCH;
  m.channels[0].spindles[0].m5_sync = sync::NO_SYNCH;
  auto p = planner(m);
  auto a = ok(p, din(10, SpindleM::m3));  // not executed: no speed error either
  EXPECT_EQ(a.size(), 0u);
  a = ok(p, din(20, SpindleM::m3, 500));  // M3 dropped; the S word stays: stored
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].op, SpindleOp::speed);
  a = ok(p, din(30, SpindleM::m4));
  EXPECT_EQ(a[0].rpm, -500);
  a = ok(p, din(40, SpindleM::m5));  // M5 NO_SYNCH: keeps turning
  EXPECT_EQ(a.size(), 0u);
}

TEST(SpindlePlanner, NoSynchSpeedIsCommandedNotOutputNotWaitedFor) {
  auto m = spindle_machine();
  m.channels[0].spindles[0].s_sync = sync::NO_SYNCH | sync::PLC_INFO;
  auto p = planner(m);
  ok(p, din(10, SpindleM::m3, 1000));
  auto a = ok(p, din(20, SpindleM::none, 2000));
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].op, SpindleOp::speed);
  EXPECT_FALSE(a[0].output);
  EXPECT_EQ(a[0].sync, SyncPoint::none);
  EXPECT_EQ(a[0].wait, SpindleWait::none);
  EXPECT_EQ(p.planned(0).speed_rpm, 2000);
}

TEST(SpindlePlanner, PriorityM19OverM3OverS) {
  auto m = spindle_machine();
  auto& sp = m.channels[0].spindles[0];
  sp.s_sync = sync::MVS_SLM;
  sp.m3_sync = sync::MNS_SNS;
  sp.m19_sync = sync::MVS_SLP;
  sp.s_ack_timeout_s = 1;
  sp.m19_ack_timeout_s = 4;
  auto p = planner(m);
  auto a = ok(p, din(10, SpindleM::m3, 500));  // M3 S500: M3's type, S's ignored
  EXPECT_EQ(a[0].sync, SyncPoint::after);
  EXPECT_EQ(a[0].sync_bits, sync::MNS_SNS);
  nc::Block b = din(20, SpindleM::m19, 100);
  b.spindles[0].direction = SpindleM::m3;  // M19 M3 S100: M19's type
  a = ok(p, b);
  EXPECT_EQ(a[0].sync, SyncPoint::late_explicit);
  EXPECT_EQ(a[0].ack_timeout_s, 4);
  a = ok(p, din(30, SpindleM::m3, 700));
  a = ok(p, din(40, SpindleM::none, 900));  // S alone: its own type
  EXPECT_EQ(a[0].sync, SyncPoint::late_motion);
  EXPECT_EQ(a[0].ack_timeout_s, 1);
}

// FCT-S1 2.5.2 example 1: s_sync MVS_SVS, m3_sync MOS -> the path never waits.
TEST(SpindlePlanner, SeedSyncExample1SpindleAsynchronous) {
  auto m = spindle_machine();
  m.channels[0].spindles[0].s_sync = sync::MVS_SVS;
  m.channels[0].spindles[0].m3_sync = sync::MOS;
  auto p = planner(m);
  EXPECT_EQ(ok(p, kernel::testing::move(10, nc::Motion::rapid, 0, 0)).size(), 0u);  // N10 X0 Y0 G0
  nc::Block n20 = din(20, SpindleM::m3, 500);  // N20 X40 Y40 G1 F1500 M3 S500
  n20.axes[0] = 40;
  n20.axes[1] = 40;
  auto a = ok(p, n20);
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].op, SpindleOp::rotate);
  EXPECT_EQ(a[0].rpm, 500);
  EXPECT_EQ(a[0].sync, SyncPoint::none);  // due to M3: motion starts at once
  EXPECT_EQ(a[0].wait, SpindleWait::none);
  a = ok(p, din(30, SpindleM::m3, 100));  // N30 M3 S100 X0 Y0
  EXPECT_EQ(a[0].rpm, 100);
  EXPECT_EQ(a[0].sync, SyncPoint::none);
  EXPECT_EQ(a[0].wait, SpindleWait::none);
}

// FCT-S1 2.5.2 example 2: same parameters, S programmed without M3 -> the
// path waits before the block until the speed is reached.
TEST(SpindlePlanner, SeedSyncExample2SpindleSynchronous) {
  auto m = spindle_machine();
  m.channels[0].spindles[0].s_sync = sync::MVS_SVS;
  m.channels[0].spindles[0].m3_sync = sync::MOS;
  auto p = planner(m);
  // N10 M3 X0 Y0 G0: no speed yet, so M3 selects the direction at 0 rpm.
  auto a = ok(p, din(10, SpindleM::m3));
  EXPECT_EQ(a[0].op, SpindleOp::rotate);
  EXPECT_EQ(a[0].rpm, 0);
  EXPECT_EQ(a[0].sync, SyncPoint::none);
  EXPECT_EQ(a[0].wait, SpindleWait::none);
  a = ok(p, din(20, SpindleM::none, 500));  // N20 X40 Y40 G1 F1500 S500
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].op, SpindleOp::speed);
  EXPECT_EQ(a[0].rpm, 500);
  EXPECT_EQ(a[0].sync, SyncPoint::before);
  EXPECT_EQ(a[0].wait, SpindleWait::speed_reached);
  a = ok(p, din(30, SpindleM::none, 100));  // N30 S100 X0 Y0
  EXPECT_EQ(a[0].rpm, 100);
  EXPECT_EQ(a[0].sync, SyncPoint::before);
  EXPECT_EQ(a[0].wait, SpindleWait::speed_reached);
}

struct GearRow {
  const char* block;
  SpindleM m;
  double s_rpm;
  std::optional<int> programmed;  // M40..M45 -> 1..6
  std::optional<ErrorId> error;
  std::optional<std::uint32_t> shift_to;  // gear_change action expected (stage)
  std::uint32_t stage_after;
};

void run_gears(const config::Machine& m, const std::vector<GearRow>& rows) {
  auto p = planner(m);
  std::uint32_t line = 0;
  for (const GearRow& r : rows) {
    SCOPED_TRACE(r.block);
    auto res = p.plan(din(++line, r.m, r.s_rpm, r.programmed));
    if (r.error) {
      ASSERT_FALSE(res.has_value());
      EXPECT_EQ(res.error().id, *r.error);
      EXPECT_EQ(res.error().loc.line, line);
      EXPECT_EQ(p.planned(0).gear_stage, r.stage_after);  // unchanged
      continue;
    }
    ASSERT_TRUE(res.has_value()) << format(res.error());
    const SpindleActions& a = *res;
    ASSERT_EQ(a.size(), r.shift_to ? 2u : 1u);
    if (r.shift_to) {
      EXPECT_EQ(a[0].op, SpindleOp::gear_change);  // before the speed action
      EXPECT_EQ(a[0].stage, *r.shift_to);
      EXPECT_EQ(a[0].fn, plc::TechKind::m);
      EXPECT_EQ(a[0].fn_number, static_cast<int>(39 + *r.shift_to));
      EXPECT_EQ(a[0].sync, SyncPoint::before);
      EXPECT_EQ(a[0].wait, SpindleWait::gear_change);
      EXPECT_TRUE(a[0].output);
    }
    EXPECT_EQ(a[a.size() - 1].op, r.m == SpindleM::none ? SpindleOp::speed : SpindleOp::rotate);
    EXPECT_EQ(a[a.size() - 1].rpm, r.s_rpm);
    EXPECT_EQ(p.planned(0).gear_stage, r.stage_after);
  }
}

TEST(SpindlePlanner, SeedGearExampleAutomatic) {
  run_gears(gear_machine(true),
            {
                {"S650 M03", SpindleM::m3, 650, {}, {}, 2, 2},  // M41 -> PLC
                {"S750", SpindleM::none, 750, {}, {}, {}, 2},
                {"S950", SpindleM::none, 950, {}, {}, 3, 3},    // M42 -> PLC
                {"S1050", SpindleM::none, 1050, {}, {}, {}, 3},
                // FCT-S1 §2.8.2 prints M41 here; M42 covers 700..3500 and its own
                // rule keeps a stage that covers S, so nck keeps M42 (docs/decisions.md).
                {"S750", SpindleM::none, 750, {}, {}, {}, 3},
                // Follows from keeping M42: it cannot run 500, bottom-up search -> M40.
                {"S500", SpindleM::none, 500, {}, {}, 1, 1},
                {"S350", SpindleM::none, 350, {}, {}, {}, 1},
                {"S8000", SpindleM::none, 8000, {}, ErrorId::SpindleSpeedTooHigh, {}, 1},
                {"M41 S750", SpindleM::none, 750, 2, {}, 2, 2},  // programmed stage checked, taken
                {"M40 S750", SpindleM::none, 750, 1, ErrorId::SpindleGearStageWrong, {}, 2},
            });
}

TEST(SpindlePlanner, SeedGearExampleManual) {
  run_gears(gear_machine(false),
            {
                {"M41 S650 M03", SpindleM::m3, 650, 2, {}, 2, 2},
                {"M41 S750", SpindleM::none, 750, 2, {}, {}, 2},
                {"M42 S950", SpindleM::none, 950, 3, {}, 3, 3},
                {"M42 S1050", SpindleM::none, 1050, 3, {}, {}, 3},
                {"M41 S750", SpindleM::none, 750, 2, {}, 2, 2},
                {"M41 S500", SpindleM::none, 500, 2, {}, {}, 2},
                // Seed says OK, but M41 runs 400..800: a manual stage that does
                // not cover S is an error (same as gear_select_test).
                {"M41 S350", SpindleM::none, 350, 2, ErrorId::SpindleGearStageWrong, {}, 2},
                {"M41 S200", SpindleM::none, 200, 2, ErrorId::SpindleGearStageWrong, {}, 2},
                {"S950", SpindleM::none, 950, {}, ErrorId::SpindleGearStageRequired, {}, 2},
            });
}

TEST(SpindlePlanner, GearStartsAtInitialStageAndOnlyForMainDin) {
  auto m = gear_machine(true);
  m.axes[3].initial_gear_stage = 3;
  auto p = planner(m);
  EXPECT_EQ(p.planned(0).gear_stage, 3u);
  auto a = ok(p, din(1, SpindleM::m3, 1000));  // M42 covers 1000: no change
  EXPECT_EQ(a.size(), 1u);
  // Spindle syntax on S2 with the same table never shifts.
  m.channels[0].spindles[1].range_table = m.channels[0].spindles[0].range_table;
  m.channels[0].spindles[1].autom_range = true;
  auto q = planner(m);
  EXPECT_EQ(ok(q, s2(2, SpindleM::m3, 6000)).size(), 1u);
  // Gear change disabled: M41 is a free M function, synchronised by m_synch[41].
  m.channels[0].main_spindle_gear_change = false;
  m.channels[0].m_synch[41] = sync::MOS;
  auto r = planner(m);
  a = ok(r, din(3, SpindleM::m3, 8000, 2));
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a[0].op, SpindleOp::user_function);
  EXPECT_EQ(a[0].fn_number, 41);
  EXPECT_TRUE(a[0].output);
  EXPECT_EQ(a[0].sync, SyncPoint::none);
  EXPECT_EQ(a[1].rpm, 8000);
}

TEST(SpindlePlanner, GearChangeWithHomingIsAnError) {
  auto m = gear_machine(false);
  auto p = planner(m);
  nc::Block b = din(4, SpindleM::none, {}, 2);
  b.spindles[0].g74 = true;
  EXPECT_EQ(fails(p, b).id, ErrorId::KernelSpindleGearWithHoming);
  b.spindles[0].gear_stage.reset();
  auto a = ok(p, b);
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].op, SpindleOp::home);
  EXPECT_EQ(a[0].wait, SpindleWait::none);
}

// FCT-S1 2.8.5: wz[5].log_ax_nr_spdl 6, vb_min 60 deg/s (10 rpm),
// max_speed_mm_s 3000 deg/s (500 rpm), a_max 3000 deg/s^2.
TEST(SpindlePlanner, ToolDynamicsFromDAndToolData) {
  auto m = spindle_machine();
  m.channel_data[0].tools.resize(8);
  auto& t = m.channel_data[0].tools[5];
  t.given = true;
  t.log_ax_nr_spdl = 6;
  t.vb_min_rpm = 60.0 / 6.0;
  t.vb_max_rpm = 3000.0 / 6.0;
  t.a_max_deg_s2 = 3000;
  m.channel_data[0].tools[6] = t;
  m.channel_data[0].tools[6].log_ax_nr_spdl = 0;  // no transfer
  m.channel_data[0].tools[7] = t;
  m.channel_data[0].tools[7].log_ax_nr_spdl = 9;  // not in this channel
  auto p = planner(m);
  nc::Block b = din(1, SpindleM::m3, 400);
  b.d = 5;
  auto a = ok(p, b);
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a[0].op, SpindleOp::tool_dynamics);  // before the start it limits
  EXPECT_EQ(a[0].spindle, 0);
  EXPECT_DOUBLE_EQ(a[0].tool_vb_min_rpm, 10);
  EXPECT_DOUBLE_EQ(a[0].tool_vb_max_rpm, 500);
  EXPECT_DOUBLE_EQ(a[0].tool_a_max_deg_s2, 3000);
  nc::Block td;
  td.line = 2;
  td.hash = nc::ToolData{false, {5, 0, 0}, 1};  // #TOOL DATA [5]
  a = ok(p, td);
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].op, SpindleOp::tool_dynamics);
  td.hash = nc::ToolData{true, {5, 0, 0}, 1};  // #TOOL PREP: no
  EXPECT_EQ(ok(p, td).size(), 0u);
  nc::Block d6;
  d6.d = 6;
  EXPECT_EQ(ok(p, d6).size(), 0u);
  d6.d = 0;
  EXPECT_EQ(ok(p, d6).size(), 0u);
  d6.d = 7;
  d6.line = 9;
  Diagnostic d = fails(p, d6);
  EXPECT_EQ(d.id, ErrorId::KernelSpindleToolAxis);
  EXPECT_EQ(d.loc.line, 9u);
}

TEST(SpindlePlanner, OtherSpindleFunctionsInOrder) {
  auto m = spindle_machine();
  auto p = planner(m);
  nc::Block b = s2(1, SpindleM::m4, 5000);  // S2[M4 REV5000 G135 G136=90 G130=50 M=8 H=2]
  auto& c = b.spindles[0];
  c.g135 = true;
  c.g136_pct = 90;
  c.g130_pct = 50;
  c.user_m = {8};
  c.user_h = {2};
  auto a = ok(p, b);
  ASSERT_EQ(a.size(), 6u);
  EXPECT_EQ(a[0].op, SpindleOp::accel_weight);
  EXPECT_EQ(a[0].value, 50);
  EXPECT_EQ(a[1].op, SpindleOp::feedforward_on);
  EXPECT_EQ(a[2].op, SpindleOp::feedforward_weight);
  EXPECT_EQ(a[2].value, 90);
  EXPECT_EQ(a[3].op, SpindleOp::rotate);
  EXPECT_EQ(a[3].rpm, -5000);
  EXPECT_EQ(a[3].spindle, 1);
  EXPECT_EQ(a[4].op, SpindleOp::user_function);
  EXPECT_EQ(a[4].fn, plc::TechKind::m);
  EXPECT_EQ(a[4].fn_number, 8);
  EXPECT_TRUE(a[4].output);
  EXPECT_EQ(a[5].fn, plc::TechKind::h);
  EXPECT_EQ(a[5].fn_number, 2);
  nc::Block g = s2(2, SpindleM::none);
  g.spindles[0].g137 = true;
  EXPECT_EQ(ok(p, g)[0].op, SpindleOp::feedforward_off);
  g = s2(3, SpindleM::none);
  g.spindles[0].g112_stage = 2;
  a = ok(p, g);
  EXPECT_EQ(a[0].op, SpindleOp::load_gear_data);
  EXPECT_EQ(a[0].stage, 2u);
  EXPECT_EQ(p.planned(1).gear_stage, 2u);
  g.spindles[0].g112_stage = 7;
  EXPECT_EQ(fails(p, g).id, ErrorId::SpindleGearStageInvalid);
  g = s2(4, SpindleM::none);
  g.spindles[0].get_dynamic_data = true;
  EXPECT_EQ(ok(p, g)[0].op, SpindleOp::get_dynamic_data);
  g.spindles[0].get_dynamic_data = false;
  g.spindles[0].default_dynamic_data = true;
  EXPECT_EQ(ok(p, g)[0].op, SpindleOp::default_dynamic_data);
  g = s2(5, SpindleM::none, 3000);  // G167 with a speed: flag on the speed action
  g.spindles[0].g167 = true;
  a = ok(p, g);
  EXPECT_EQ(a[0].op, SpindleOp::speed);
  EXPECT_TRUE(a[0].g167);
  g.spindles[0].rev_rpm.reset();  // S2[G167] alone
  a = ok(p, g);
  EXPECT_EQ(a[0].op, SpindleOp::suppress_override);
}

TEST(SpindlePlanner, BadInputBecomesDiagnostics) {
  auto m = spindle_machine();
  auto p = planner(m);
  nc::Block b = s2(1, SpindleM::m3, 100);
  b.spindles[0].target = "S9";
  b.spindles[0].spindle_index.reset();  // not a spindle of the channel
  b.spindles[0].name = "S9";
  EXPECT_EQ(fails(p, b).id, ErrorId::KernelSpindleUnknown);
  b = din(2, SpindleM::m3, std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(fails(p, b).id, ErrorId::SpindleBadValue);
  SpindlePlanner no_kernel(m, 0, {0});  // S2 has no kernel spindle
  EXPECT_EQ(fails(no_kernel, s2(3, SpindleM::m5)).id, ErrorId::KernelSpindleUnknown);
  SpindlePlanner bad_channel(m, 5, {});
  EXPECT_EQ(fails(bad_channel, din(4, SpindleM::m5)).id, ErrorId::KernelSpindleUnknown);
  nc::Block many = s2(5, SpindleM::none);
  many.spindles[0].user_m.assign(20, 7);
  EXPECT_EQ(fails(p, many).id, ErrorId::KernelSpindleTooManyActions);
  p.reset();
  EXPECT_FALSE(p.planned(0).speed_rpm);
}

}  // namespace
}  // namespace nck::prep
