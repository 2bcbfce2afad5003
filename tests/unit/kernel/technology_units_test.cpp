// The channel's technology units (src/kernel/units/) each run alone, with
// nothing but a cycle context: no channel, no program.
#include <gtest/gtest.h>

#include <memory>

#include "../../../src/kernel/units/dwell_unit.hpp"
#include "../../../src/kernel/units/handwheel_unit.hpp"

namespace nck::kernel {
namespace {

constexpr double kDt_s = 0.001;

// One cycle's context around a block, without spindles or a PLC.
struct Bench {
  ChannelInput in{};
  std::unique_ptr<TickOutput> sink = std::make_unique<TickOutput>();
  ChannelContext machine{};
  FeedbackQueue feedback;
  Command block{};
  Cycle cycle(double t_s) { return Cycle{t_s, kDt_s, in, *sink, machine, feedback, block, 1, 3, {}}; }
};

TEST(DwellUnit, DwellOfKCyclesTakesExactlyKCycles) {
  Bench b;
  const Dwell d{5 * kDt_s, std::nullopt};
  b.block.action = d;
  DwellUnit dwell;
  dwell.start(d);
  int cycles = 0;
  for (bool over = false; !over; ++cycles) {
    Cycle cy = b.cycle(cycles * kDt_s);
    ASSERT_FALSE(dwell.step(d, cy, over).any());
  }
  EXPECT_EQ(cycles, 5);
}

TEST(DwellUnit, RevolutionsOfAMissingSpindleAreAFault) {
  Bench b;
  const Dwell d{0, Dwell::Revolutions{2, 0}};  // no spindle in the context: it stands
  b.block.action = d;
  DwellUnit dwell;
  dwell.start(d);
  Cycle cy = b.cycle(0);
  bool over = false;
  EXPECT_EQ(dwell.step(d, cy, over).id, ErrorId::KernelDwellSpindleStopped);
  EXPECT_FALSE(over);
}

TEST(HandwheelUnit, OffsetIsTravelledAtItsSpeedAndReported) {
  Bench b;
  const ManualChange g201{0b001, 0, true};  // G201 X, #GET MANUAL OFFSETS
  HandwheelUnit hw;
  hw.start(&g201);
  b.in.handwheel_mm[0] = 1.0;
  Cycle cy = b.cycle(0);
  ASSERT_FALSE(hw.follow(cy).any());
  EXPECT_DOUBLE_EQ(hw.in_force_mm()[0], kHandwheelSpeed_mm_s * kDt_s);
  ASSERT_FALSE(b.feedback.empty());
  EXPECT_EQ(b.feedback.front().kind, FeedbackKind::manual_offsets);
  EXPECT_DOUBLE_EQ(b.feedback.front().manual_offsets_mm[0], kHandwheelSpeed_mm_s * kDt_s);
}

TEST(HandwheelUnit, MotionBlendsTheOffsetOutAlongItsPath) {
  Bench b;
  const ManualChange g201{0b001, 0, false};
  HandwheelUnit hw;
  hw.start(&g201);
  b.in.handwheel_mm[0] = 0.005;
  Cycle cy = b.cycle(0);
  (void)hw.follow(cy);  // 5 µm reached, all of it in force
  b.in.handwheel_mm[0] = 0;
  Motion motion{};
  motion.handwheel_axes = 0;  // #SUPPRESS OFFSETS: this block takes it out
  hw.start(nullptr);
  hw.blend(motion, 10.0, 5.0, 3);  // half way along 10 mm
  (void)hw.follow(cy);
  EXPECT_DOUBLE_EQ(hw.in_force_mm()[0], 0.005 * 0.5);
}

}  // namespace
}  // namespace nck::kernel
