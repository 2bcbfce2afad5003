// A spindle's amplifier fault (TickInput::axes of its axis list) acts as
// an axis's does: error 930750 naming the spindle, the channel brakes, its
// spindles ramp down, starts are refused until the fault is gone and a
// reset was given.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "test_machine.hpp"

namespace nck::kernel {
namespace {

using testing::add_spindle_s1;
using testing::KernelRig;

constexpr std::size_t kS1 = 3;  // S1's axis list (after X, Y, Z)

TEST(SpindleAmpFault, IsAnErrorNamingTheSpindleAndItBrakes) {
  config::Machine m = testing::xyz_machine(100, 100000);
  add_spindle_s1(m);
  KernelRig rig(m);
  nc::Block b;
  b.line = 1;
  nc::SpindleCommand c;
  c.name = c.target = "S1";
  c.spindle_index = 0;
  c.m = nc::SpindleM::m3;
  c.rev_rpm = 600;
  b.spindles.push_back(c);
  rig.push_block(0, b);
  rig.push_block(0, testing::move(2, nc::Motion::linear, 50.0));  // runs while the fault comes
  rig.push_block(0, testing::end_block(3));
  auto in = std::make_unique<TickInput>();
  auto out = std::make_unique<TickOutput>();
  std::vector<ev::Error> errors;
  double last_rpm = 0, rise_after_fault = 0;
  for (int i = 0; i < 3000 && !rig.k.all_channels_done(); ++i) {
    if (i == 200) in->axes[kS1].amp_fault = true;
    rig.k.tick(*in, *out);
    for (const Event& e : out->events)
      if (const auto* err = e.get<ev::Error>()) errors.push_back(*err);
    const double rpm = rig.k.spindle_status(0).set_rpm;
    if (i > 200) rise_after_fault = std::max(rise_after_fault, rpm - last_rpm);
    last_rpm = rpm;
  }
  ASSERT_TRUE(rig.k.all_channels_done());
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].id, ErrorId::KernelAmpFault);
  ASSERT_TRUE(errors[0].axis.has_value());
  EXPECT_EQ(rig.k.axis_name(static_cast<std::size_t>(*errors[0].axis)), "S1");
  EXPECT_TRUE(rig.k.amp_fault_latched(0));
  EXPECT_LE(rise_after_fault, 0.0);  // from the fault on the spindle only slows down
  EXPECT_LT(rig.k.channel_state(0).axis_mcs[0], 50.0);  // X stopped on its way
}

}  // namespace
}  // namespace nck::kernel
