// A spindle on a CiA 402 drive (kenngr.antr_typ 8), as on a real machine:
// no simulated drive attached, the drive's actual values are the spindle's
// feedback. Its mode of operation follows the spindle (FCT-S1's graph for
// digital drives): velocity while it turns, position for M19, homing mode
// while G74 lets the drive home; a homing error and a homing that never
// ends are errors naming the spindle. The drive is drives::IdealDrive.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "nck/drives/ideal_drive.hpp"
#include "test_machine.hpp"

namespace nck::kernel {
namespace {

namespace cia = drives::cia402;
using testing::add_spindle_s1;
using testing::end_block;
using testing::KernelRig;
using testing::spindle_block;
using testing::xyz_machine;

constexpr std::size_t kS1 = 3;  // S1's axis list (after X, Y, Z)

config::Machine machine() {
  config::Machine m = xyz_machine(100, 100000);
  config::AxisConfig& s1 = add_spindle_s1(m);
  s1.drive_type = 8;
  s1.drive_mode = config::DriveMode::open_loop_pos_feedback;  // speed-controlled, knows its position
  s1.drive_homing_timeout_s = 0.5;
  return m;
}

// The kernel and S1's drive; `homing_fault` makes the drive answer a
// homing start with a homing error, `never_homes` keeps it searching.
struct SpindleDriveRig {
  SpindleDriveRig() : rig(machine()) {}
  void cycle() {
    in->drives[kS1] = drive.feedback();
    if (never_homes && in->drives[kS1].mode_display == 6)
      in->drives[kS1].statusword &= static_cast<std::uint16_t>(~(cia::sw::homing_attained | cia::sw::target_reached));
    if (homing_fault && (out->drives[kS1].controlword & cia::cw::homing_start_bit))
      in->drives[kS1].statusword |= cia::sw::homing_error;
    const double last_target = out->drives[kS1].target_pos, last_vel = out->drives[kS1].target_vel;
    rig.k.tick(*in, *out);
    for (const Event& e : out->events) {
      if (const auto* d = e.get<drives::DriveEvent>(); d && d->axis == static_cast<std::int8_t>(kS1))
        modes.push_back(d->mode);
      if (const auto* err = e.get<ev::Error>()) errors.push_back(*err);
    }
    const drives::DriveCommand& cmd = out->drives[kS1];
    if (cmd.mode_of_operation == 8 && last_mode == 8)
      max_step_deg = std::max(max_step_deg, std::fabs(cmd.target_pos - last_target));
    if (cmd.mode_of_operation == 9 && last_mode == 9)
      max_accel_deg_s2 = std::max(max_accel_deg_s2, std::fabs(cmd.target_vel - last_vel) / 0.001);
    last_mode = cmd.mode_of_operation;
    (void)drive.step(cmd, false, 0.001);
  }
  void run(int cycles) {
    for (int i = 0; i < cycles && !rig.k.all_channels_done(); ++i) cycle();
  }
  // G74 S1 runs beside the program (FCT-S1 2.7): the next spindle
  // command would end it, so the test lets it run `cycles` first.
  void home(int cycles) {
    rig.push_block(0, spindle_block(1, nc::SpindleM::none, {}, {}, true));
    for (int i = 0; i < cycles; ++i) cycle();
  }
  KernelRig rig;
  std::unique_ptr<TickInput> in = std::make_unique<TickInput>();
  std::unique_ptr<TickOutput> out = std::make_unique<TickOutput>();
  drives::IdealDrive drive;
  bool homing_fault = false, never_homes = false;
  std::vector<std::int8_t> modes;
  std::vector<ev::Error> errors;
  std::int8_t last_mode = 0;
  double max_step_deg = 0, max_accel_deg_s2 = 0;
};

TEST(Cia402Spindle, ModeFollowsTheSpindleHomingTurningPositioning) {
  SpindleDriveRig d;
  d.home(300);  // G74 S1
  EXPECT_TRUE(d.rig.k.spindle_status(0).homed);
  d.rig.push_block(0, spindle_block(2, nc::SpindleM::m3, 600.0));            // M3 S600
  d.rig.push_block(0, spindle_block(3, nc::SpindleM::m19, 400.0, 90.0));     // S.POS=90 M19 S400
  d.rig.push_block(0, spindle_block(4, nc::SpindleM::m3, 300.0));            // M3 S300
  d.rig.push_block(0, end_block(5));
  d.run(20000);
  ASSERT_TRUE(d.rig.k.all_channels_done());
  for (int i = 0; i < 500; ++i) d.cycle();  // the program ended; S1 runs up to its speed
  EXPECT_TRUE(d.errors.empty());
  // power-up in velocity, homing, velocity, position (M19), velocity
  EXPECT_EQ(d.modes, (std::vector<std::int8_t>{9, 6, 9, 8, 9}));
  const spindle::SpindleStatus& s = d.rig.k.spindle_status(0);
  EXPECT_TRUE(s.homed);
  EXPECT_NEAR(s.set_rpm, 300.0, 1e-9);
  // The set point never jumps: positioning moves the drive's continuous
  // target by at most the top speed per cycle (6000 deg/s), and velocity
  // mode changes its target velocity within the spindle's acceleration.
  EXPECT_LE(d.max_step_deg, 6000 * 0.001 + 1e-9);
  EXPECT_LE(d.max_accel_deg_s2, 60000 * 1.0001);
}

TEST(Cia402Spindle, M19PositionsTheDriveAfterItHomed) {
  SpindleDriveRig d;
  d.home(300);
  d.rig.push_block(0, spindle_block(2, nc::SpindleM::m3, 600.0));
  d.rig.push_block(0, spindle_block(3, nc::SpindleM::m19, 400.0, 90.0));
  d.rig.push_block(0, end_block(4));
  d.run(20000);
  ASSERT_TRUE(d.rig.k.all_channels_done());
  EXPECT_TRUE(d.errors.empty());
  const spindle::SpindleStatus& s = d.rig.k.spindle_status(0);
  EXPECT_TRUE(s.in_position);
  EXPECT_NEAR(s.act_pos_deg, 90.0, 0.01);
  // The drive counts on from its home (0): it stands at 90 deg modulo a turn.
  const double turns = d.drive.feedback().actual_pos / 360.0;
  EXPECT_NEAR((turns - std::floor(turns)) * 360.0, 90.0, 0.01);
  EXPECT_EQ(d.drive.feedback().mode_display, 8);
}

TEST(Cia402Spindle, HomingErrorIsAnErrorNamingTheSpindle) {
  SpindleDriveRig d;
  d.homing_fault = true;
  d.home(300);
  d.rig.push_block(0, end_block(3));
  d.run(5000);
  ASSERT_TRUE(d.rig.k.all_channels_done());  // never a hang
  ASSERT_EQ(d.errors.size(), 1u);
  EXPECT_EQ(d.errors[0].id, ErrorId::KernelDriveHomingError);
  ASSERT_TRUE(d.errors[0].axis.has_value());
  EXPECT_EQ(d.rig.k.axis_name(static_cast<std::size_t>(*d.errors[0].axis)), "S1");
  EXPECT_FALSE(d.rig.k.spindle_status(0).homed);
  EXPECT_NE(d.rig.k.spindle_status(0).mode, spindle::SpindleMode::homing);
}

TEST(Cia402Spindle, HomingThatNeverEndsTimesOut) {
  SpindleDriveRig d;
  d.never_homes = true;
  d.home(1000);
  d.rig.push_block(0, end_block(3));
  d.run(5000);
  ASSERT_TRUE(d.rig.k.all_channels_done());
  ASSERT_EQ(d.errors.size(), 1u);
  EXPECT_EQ(d.errors[0].id, ErrorId::KernelDriveHomingTimeout);
  EXPECT_GE(d.rig.k.time_s(), 0.5);  // antr.homing_timeout_ms
}

}  // namespace
}  // namespace nck::kernel
