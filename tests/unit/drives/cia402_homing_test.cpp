// Drive-controlled homing, both sides: the NC's handshake (DriveHoming)
// and the ideal drive's homing mode; and the ideal drive's velocity mode.
#include <gtest/gtest.h>

#include "nck/drives/cia402_homing.hpp"
#include "nck/drives/ideal_drive.hpp"

namespace nck::drives {
namespace {

namespace cia = cia402;
using Outcome = cia::DriveHoming::Outcome;
constexpr std::int8_t kHoming = static_cast<std::int8_t>(cia::Mode::homing);
constexpr std::uint16_t kEnabled = 0x0027;  // operation enabled

TEST(DriveHoming, StartsOnlyOnceTheDriveShowsHomingModeAndEndsOnAttained) {
  cia::DriveHoming h;
  EXPECT_EQ(h.step(true, kEnabled, 8), Outcome::none);  // asked: switch the mode
  EXPECT_TRUE(h.active());
  EXPECT_EQ(h.start_bit(), 0);
  EXPECT_EQ(h.step(true, kEnabled, 8), Outcome::none);  // the drive still shows CSP
  EXPECT_EQ(h.start_bit(), 0);
  EXPECT_EQ(h.step(true, kEnabled, kHoming), Outcome::none);  // now in homing mode: start
  EXPECT_EQ(h.start_bit(), cia::cw::homing_start_bit);
  EXPECT_EQ(h.step(true, kEnabled, kHoming), Outcome::none);  // searching (bit 12 clear)
  const std::uint16_t done = kEnabled | cia::sw::homing_attained | cia::sw::target_reached;
  EXPECT_EQ(h.step(true, done, kHoming), Outcome::attained);
  EXPECT_FALSE(h.active());
  EXPECT_EQ(h.step(true, done, kHoming), Outcome::none);  // reported once
  EXPECT_EQ(h.step(false, done, kHoming), Outcome::none);  // done with: idle again
  EXPECT_EQ(h.cycles(), 0u);
}

TEST(DriveHoming, BitTwelveLeftFromAnEarlierHomingIsNotAttained) {
  cia::DriveHoming h;
  const std::uint16_t stale = kEnabled | cia::sw::homing_attained | cia::sw::target_reached;
  (void)h.step(true, stale, 8);
  (void)h.step(true, stale, kHoming);  // running
  EXPECT_EQ(h.step(true, stale, kHoming), Outcome::none);  // the drive has not seen the edge yet
  EXPECT_EQ(h.step(true, kEnabled, kHoming), Outcome::none);  // its search begins
  EXPECT_EQ(h.step(true, stale, kHoming), Outcome::attained);
}

TEST(DriveHoming, HomingErrorFailsAndCyclesCountForATimeout) {
  cia::DriveHoming h;
  (void)h.step(true, kEnabled, 8);
  for (int i = 0; i < 9; ++i) (void)h.step(true, kEnabled, kHoming);
  EXPECT_EQ(h.cycles(), 9u);  // the cycles since the one that asked
  EXPECT_EQ(h.step(true, kEnabled | cia::sw::homing_error, kHoming), Outcome::failed);
  EXPECT_FALSE(h.active());
}

// The ideal drive powered up into operation enabled in mode `mode`.
IdealDrive enabled_drive(std::int8_t mode) {
  IdealDrive d;
  for (std::uint16_t c : {cia::cw::disable_voltage, cia::cw::shutdown, cia::cw::enable_operation, cia::cw::enable_operation})
    (void)d.step(DriveCommand{c, mode, true, 0, 0}, false, 0.001);
  EXPECT_EQ(d.state(), cia::State::operation_enabled);
  return d;
}

TEST(IdealDrive, VelocityModeTurnsAtTheTargetVelocity) {
  IdealDrive d = enabled_drive(9);
  for (int i = 0; i < 1000; ++i) (void)d.step(DriveCommand{cia::cw::enable_operation, 9, true, 0, 360.0}, false, 0.001);
  EXPECT_NEAR(d.feedback().actual_pos, 360.0, 1e-9);  // 1 s at 360 deg/s, whatever the target position
  EXPECT_DOUBLE_EQ(d.feedback().actual_vel, 360.0);
  EXPECT_EQ(d.feedback().mode_display, 9);
}

TEST(IdealDrive, HomingModeSearchesThenStandsAtItsHomeOffset) {
  IdealDrive d = enabled_drive(8);
  (void)d.step(DriveCommand{cia::cw::enable_operation, 8, true, 1234.5, 0}, false, 0.001);
  EXPECT_DOUBLE_EQ(d.feedback().actual_pos, 1234.5);
  const std::uint16_t start = cia::cw::enable_operation | cia::cw::homing_start_bit;
  (void)d.step(DriveCommand{cia::cw::enable_operation, kHoming, true, 0, 0}, false, 0.001);
  EXPECT_EQ(d.feedback().mode_display, kHoming);
  std::uint32_t searching = 0;
  for (std::uint32_t i = 0; i < 2 * IdealDrive::kHomingCycles; ++i) {
    (void)d.step(DriveCommand{start, kHoming, true, 0, 0}, false, 0.001);
    if (!(d.feedback().statusword & cia::sw::homing_attained)) ++searching;
  }
  EXPECT_EQ(searching, IdealDrive::kHomingCycles);
  EXPECT_TRUE(d.feedback().statusword & cia::sw::target_reached);
  EXPECT_DOUBLE_EQ(d.feedback().actual_pos, 0.0);
}

}  // namespace
}  // namespace nck::drives
