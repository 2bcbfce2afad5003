// Planned commands packed for the kernel (command_packer.hpp): a motion's
// start goes along only when it is not where the motion before ended, the
// kernel's segment joins back bit for bit, and what only some blocks carry
// travels as attachments in their order.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>

#include "nck/prep/command_packer.hpp"

namespace nck::prep {
namespace {

PlannedCommand line(const motion::AxisVector& from, const motion::AxisVector& to) {
  PlannedCommand c;
  c.kind = CommandKind::motion;
  c.segment = *motion::make_line(from, to, 3);
  c.v_cmd_mm_s = 10;
  return c;
}

motion::AxisVector at(double x, double y) {
  motion::AxisVector v{};
  v[0] = x;
  v[1] = y;
  return v;
}

bool same_bits(const motion::AxisVector& a, const motion::AxisVector& b) {
  return std::memcmp(a.data(), b.data(), sizeof(a)) == 0;
}

TEST(CommandPacker, AStartPointGoesAlongOnlyWhereThePathDoesNotContinue) {
  auto q = std::make_unique<kernel::CommandQueue>();
  CommandPacker p;
  ASSERT_TRUE(p.pack(line(at(0, 0), at(1.0 / 3.0, 0)), *q));        // starts at the origin: nothing to add
  ASSERT_TRUE(p.pack(line(at(1.0 / 3.0, 0), at(1, 2)), *q));        // continues
  ASSERT_TRUE(p.pack(line(at(5, 5), at(6, 6)), *q));                // jumps (a new frame)
  ASSERT_EQ(q->size(), 3u);
  EXPECT_EQ(q->front().attachments, 0);
  q->pop();
  EXPECT_EQ(q->front().attachments, 0);
  q->pop();
  ASSERT_EQ(q->front().attachments, 1);
  const auto* start = std::get_if<kernel::StartPoint>(&q->attachment(0));
  ASSERT_NE(start, nullptr);
  EXPECT_TRUE(same_bits(start->pos, at(5, 5)));
}

TEST(CommandPacker, TheKernelJoinsTheSegmentBitForBit) {
  const PlannedCommand first = line(at(0, 0), at(0.1, 0.7));
  PlannedCommand arc;
  arc.kind = CommandKind::motion;
  arc.segment = *motion::make_arc_center(at(0.1, 0.7), at(0.7, 0.1), 3, 0, 1, 0, 0, false);
  auto q = std::make_unique<kernel::CommandQueue>();
  CommandPacker p;
  ASSERT_TRUE(p.pack(first, *q) && p.pack(arc, *q));
  q->pop();
  const auto* m = q->front().as<kernel::Motion>();
  ASSERT_NE(m, nullptr);
  const motion::Segment joined = motion::Segment::joined(first.segment.end_point(), m->path);
  for (double s : {0.0, 0.123, 0.5, arc.segment.length()}) {
    motion::AxisVector a{}, b{};
    arc.segment.point_at(s, a);
    joined.point_at(s, b);
    EXPECT_TRUE(same_bits(a, b)) << "s = " << s;
  }
}

// Attached in any order, they leave in the order the channel handles them
// (attachment.hpp: reports, switches, outputs), each kind in planned order.
TEST(CommandPacker, AttachmentsLeaveInHandlingOrderWithTheirCommand) {
  PlannedCommand c;
  c.kind = CommandKind::nop;
  c.attach(kernel::Output{plc::TechKind::m, 8, 0, 0, std::nullopt});
  c.attach(trc::TrcChange{trc::RadiusComp::g41, 3, 2.5});
  c.attach(kernel::Output{plc::TechKind::h, 9, 0, 0, std::nullopt});
  c.attach(kernel::Warning{{ErrorId::KernelPrepStarved, 7, {}}});
  auto q = std::make_unique<kernel::CommandQueue>();
  CommandPacker p;
  ASSERT_TRUE(p.pack(c, *q));
  ASSERT_TRUE(p.pack(PlannedCommand{}, *q));
  const kernel::Command& k = q->front();
  ASSERT_EQ(k.attachments, 4);
  EXPECT_TRUE(std::holds_alternative<kernel::Warning>(q->attachment(0)));
  EXPECT_EQ(std::get<kernel::TrcChange>(q->attachment(1)).mode, trc::RadiusComp::g41);
  EXPECT_EQ(std::get<kernel::Output>(q->attachment(2)).number, 8);
  EXPECT_EQ(std::get<kernel::Output>(q->attachment(3)).number, 9);
  q->pop();
  EXPECT_EQ(q->size(), 1u);
  EXPECT_EQ(q->front().attachments, 0);
  EXPECT_EQ(q->free_attachment_slots(), kernel::kAttachmentQueueLength);
}

TEST(CommandPacker, AFullAttachmentRingTakesNothing) {
  PlannedCommand c;
  for (int i = 0; i < 8; ++i) c.attach(kernel::Output{plc::TechKind::m, i, 0, 0, std::nullopt});
  auto q = std::make_unique<kernel::CommandQueue>();
  CommandPacker p;
  std::size_t packed = 0;
  while (p.pack(c, *q)) ++packed;
  EXPECT_EQ(packed, kernel::kAttachmentQueueLength / 8);
  EXPECT_EQ(q->size(), packed);  // the one that did not fit left nothing behind
}

TEST(CommandPacker, ACommandAndItsQueueStaySmall) {
  static_assert(sizeof(kernel::Command) <= 512);
  static_assert(sizeof(PlannedCommand) <= 1200);
  // docs/performance.md: the queue with its attachment ring, per channel.
  EXPECT_LT(sizeof(kernel::CommandQueue), 217u * 1024u);
}

}  // namespace
}  // namespace nck::prep
