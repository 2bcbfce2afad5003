// The kernel's side of CiA 402 drives (kenngr.antr_typ 8): the program
// waits until every drive is in operation enabled, a drive that never gets
// there and a fault in motion are errors with their ID and the axis, the
// other axes brake within their deceleration, and a reset resets the fault.
// The drives here are cia402::Device, stepped with the kernel's controlword.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include "nck/drives/cia402.hpp"
#include "test_machine.hpp"

namespace nck::kernel {
namespace {

namespace cia = drives::cia402;
using testing::KernelRig;
using testing::move;
using testing::xyz_machine;

config::Machine cia_machine(double a_mm_s2 = 2000) {
  config::Machine m = xyz_machine(500, a_mm_s2);
  for (auto& ax : m.axes) {
    ax.drive_type = 8;
    ax.drive_enable_timeout_s = 0.05;
  }
  return m;
}

// The kernel with three simulated drives around it.
struct DriveRig {
  explicit DriveRig(const config::Machine& m) : rig(m) {}
  // One cycle: the drives' last statuswords in, a tick, the controlwords to the drives.
  void cycle() {
    for (std::size_t i = 0; i < 3; ++i) in->drives[i].statusword = status[i];
    rig.k.tick(*in, *out);
    for (const Event& e : out->events) events.push_back(e);
    for (std::size_t i = 0; i < 3; ++i) {
      status[i] = devices[i].step(out->drives[i].controlword, fault[i]);
      ++cycles;
    }
    in->channels[0].reset = false;
  }
  template <class T>
  std::vector<const T*> of() const {
    std::vector<const T*> r;
    for (const Event& e : events)
      if (const T* p = e.get<T>()) r.push_back(p);
    return r;
  }
  KernelRig rig;
  std::unique_ptr<TickInput> in = std::make_unique<TickInput>();
  std::unique_ptr<TickOutput> out = std::make_unique<TickOutput>();
  std::array<cia::Device, 3> devices{cia::Device{2}, cia::Device{2}, cia::Device{2}};
  std::array<std::uint16_t, 3> status{};
  std::array<bool, 3> fault{};
  std::vector<Event> events;
  std::uint64_t cycles = 0;
};

TEST(Cia402Kernel, ProgramWaitsForOperationEnabledThenRuns) {
  DriveRig d(cia_machine());
  d.rig.push_block(0, move(10, nc::Motion::linear, 10.0));
  d.rig.push_block(0, testing::end_block(20));
  for (int i = 0; i < 2000 && !d.rig.k.all_channels_done(); ++i) d.cycle();
  ASSERT_TRUE(d.rig.k.all_channels_done());
  for (const auto& dev : d.devices) EXPECT_EQ(dev.state(), cia::State::operation_enabled);
  EXPECT_EQ(d.rig.k.channel_state(0).status, ChannelStatus::ended);
  const auto waits = d.of<ev::Wait>();
  ASSERT_EQ(waits.size(), 1u);
  EXPECT_EQ(waits[0]->reason, WaitReason::drive_enable);
  ASSERT_EQ(d.of<ev::WaitEnd>().size(), 1u);
  EXPECT_TRUE(d.of<ev::Error>().empty());
  // Cyclic synchronous position for path axes; the set point reaches the drive.
  EXPECT_EQ(d.out->drives[0].mode_of_operation, 8);
  EXPECT_DOUBLE_EQ(d.out->drives[0].target_pos, 10.0);
  EXPECT_EQ(d.out->drives[0].controlword, cia::cw::enable_operation);
}

TEST(Cia402Kernel, DriveThatNeverEnablesIsAnErrorWithTheAxis) {
  DriveRig d(cia_machine());
  d.fault[2] = true;  // Z holds a fault from power-up
  d.rig.push_block(0, move(10, nc::Motion::linear, 10.0));
  d.rig.push_block(0, testing::end_block(20));
  for (int i = 0; i < 2000 && !d.rig.k.all_channels_done(); ++i) d.cycle();
  ASSERT_TRUE(d.rig.k.all_channels_done());  // never a hang
  const auto errors = d.of<ev::Error>();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0]->id, ErrorId::KernelDriveEnableTimeout);
  ASSERT_TRUE(errors[0]->axis.has_value());
  EXPECT_EQ(*errors[0]->axis, 2);
  EXPECT_EQ(d.rig.k.axis_name(2), "Z");
  EXPECT_EQ(d.rig.k.channel_state(0).program_state, ProgramState::error);
  EXPECT_EQ(d.rig.k.channel_state(0).axis_mcs[0], 0.0);  // nothing moved
}

TEST(Cia402Kernel, FaultInMotionBrakesWithinDecelerationAndResetRecovers) {
  const double a_mm_s2 = 2000;
  DriveRig d(cia_machine(a_mm_s2));
  d.rig.push_block(0, move(10, nc::Motion::linear, 200.0, 200.0, {}, 12000));
  d.rig.push_block(0, testing::end_block(20));
  double last_v = 0, last_x = 0;
  bool faulted = false;
  double max_decel = 0;
  for (int i = 0; i < 5000 && !d.rig.k.all_channels_done(); ++i) {
    if (!faulted && d.rig.k.channel_state(0).axis_mcs[0] > 50) {
      d.fault[1] = true;  // Y faults at full speed
      faulted = true;
    }
    d.cycle();
    const double x = d.out->channels[0].axis_mcs[0];
    const double v = (x - last_x) / 0.001;
    if (faulted) max_decel = std::max(max_decel, (last_v - v) / 0.001);
    last_v = v;
    last_x = x;
  }
  ASSERT_TRUE(faulted);
  ASSERT_TRUE(d.rig.k.all_channels_done());
  const auto errors = d.of<ev::Error>();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0]->id, ErrorId::KernelDriveFault);
  ASSERT_TRUE(errors[0]->axis.has_value());
  EXPECT_EQ(*errors[0]->axis, 1);
  EXPECT_LT(d.rig.k.channel_state(0).axis_mcs[0], 200.0);  // stopped on the way
  EXPECT_LE(max_decel, a_mm_s2 * 1.01);                     // braked, not stopped dead
  EXPECT_NEAR(last_v, 0.0, 1e-9);
  // The faulted drive is switched off; the healthy ones stay enabled.
  for (int i = 0; i < 10; ++i) d.cycle();
  EXPECT_EQ(d.devices[1].state(), cia::State::fault);
  EXPECT_EQ(d.devices[0].state(), cia::State::operation_enabled);
  // The cause is gone; the operator's reset resets the fault and powers up again.
  d.fault[1] = false;
  d.in->channels[0].reset = true;
  for (int i = 0; i < 20; ++i) d.cycle();
  EXPECT_EQ(d.devices[1].state(), cia::State::operation_enabled);
  EXPECT_EQ(d.of<ev::Error>().size(), 1u);
}

}  // namespace
}  // namespace nck::kernel
