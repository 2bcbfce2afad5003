#include <gtest/gtest.h>

#include <cmath>

#include "nck/kernel/kernel.hpp"
#include "test_machine.hpp"

namespace nck::kernel {
namespace {

using testing::end_block;
using testing::KernelRig;
using testing::move;
using testing::xyz_machine;

struct RunLog {
  std::vector<Event> events;  // without the program-state changes
  kernel::ev::Error first_error() const {
    for (const Event& e : events)
      if (const auto* error = e.get<kernel::ev::Error>()) return *error;
    return {};
  }
  std::vector<std::array<double, 3>> positions;
  double end_t = 0;
};

RunLog run_all(Kernel& k, std::size_t max_cycles = 1'000'000) {
  RunLog r;
  TickInput in;
  TickOutput out;
  for (std::size_t i = 0; i < max_cycles && !k.all_channels_done(); ++i) {
    k.tick(in, out);
    for (const Event& e : out.events)
      if (e.kind() != EventKind::state) r.events.push_back(e);
    r.positions.push_back({out.channels[0].axis_mcs[0], out.channels[0].axis_mcs[1],
                           out.channels[0].axis_mcs[2]});
    r.end_t = out.t_s;
  }
  return r;
}

TEST(Channel, LinearMoveEndsExactlyAtTargetWithinLimits) {
  config::Machine m = xyz_machine(500, 2000);
  KernelRig rig(m);
  Kernel& k = rig.k;
  rig.push_block(0, move(1, nc::Motion::linear, 100.0, 50.0, {}, 6000));
  rig.push_block(0, end_block(2));
  RunLog r = run_all(k);
  ASSERT_TRUE(k.all_channels_done());
  EXPECT_DOUBLE_EQ(r.positions.back()[0], 100.0);
  EXPECT_DOUBLE_EQ(r.positions.back()[1], 50.0);
  // F6000 mm/min = 100 mm/s along the path, never faster.
  for (std::size_t i = 1; i < r.positions.size(); ++i) {
    const double dx = r.positions[i][0] - r.positions[i - 1][0];
    const double dy = r.positions[i][1] - r.positions[i - 1][1];
    EXPECT_LE(std::hypot(dx, dy) / 0.001, 100.0 + 1e-6);
  }
  // Analytic trapezoid: 111.8 mm at 100 mm/s with 2000 mm/s^2 (X component
  // limits the path acceleration: 2000 / (100/111.8)).
  const double len = std::hypot(100.0, 50.0);
  const double a = 2000.0 / (100.0 / len);
  const double t_expected = len / 100.0 + 100.0 / a;
  EXPECT_NEAR(r.end_t, t_expected, 0.01);
}

TEST(Channel, RapidMovesAtRapidVelocity) {
  config::Machine m = xyz_machine(250, 10000);
  KernelRig rig(m);
  Kernel& k = rig.k;
  rig.push_block(0, move(1, nc::Motion::rapid, 250.0));
  rig.push_block(0, end_block(2));
  RunLog r = run_all(k);
  double v_max = 0;
  for (std::size_t i = 1; i < r.positions.size(); ++i)
    v_max = std::max(v_max, (r.positions[i][0] - r.positions[i - 1][0]) / 0.001);
  EXPECT_NEAR(v_max, 250.0, 1e-6);
  EXPECT_DOUBLE_EQ(r.positions.back()[0], 250.0);
}

TEST(Channel, IncrementalWordsAddToTheProgrammedPosition) {
  KernelRig rig(xyz_machine());
  Kernel& k = rig.k;
  rig.push_block(0, move(1, nc::Motion::linear, 10.0));
  nc::Block inc = move(2, nc::Motion::linear, 5.0);
  inc.modal.absolute = false;
  rig.push_block(0, inc);
  rig.push_block(0, end_block(3));
  RunLog r = run_all(k);
  EXPECT_DOUBLE_EQ(r.positions.back()[0], 15.0);
}

TEST(Channel, QuarterCircleEndsOnTarget) {
  KernelRig rig(xyz_machine());
  Kernel& k = rig.k;
  rig.push_block(0, move(1, nc::Motion::linear, 10.0, 0.0));
  nc::Block arc = move(2, nc::Motion::ccw, 0.0, 10.0);
  arc.ijk[0] = -10.0;  // centre at the origin
  rig.push_block(0, arc);
  rig.push_block(0, end_block(3));
  RunLog r = run_all(k);
  EXPECT_NEAR(r.positions.back()[0], 0.0, 1e-9);
  EXPECT_NEAR(r.positions.back()[1], 10.0, 1e-9);
  for (const auto& p : r.positions) {
    if (p[1] > 1e-9) {
      EXPECT_NEAR(std::hypot(p[0], p[1]), 10.0, 1e-6);
    }
  }
}

TEST(Channel, DwellTakesItsTime) {
  KernelRig rig(xyz_machine());
  Kernel& k = rig.k;
  nc::Block d;
  d.line = 1;
  d.dwell_s = 0.25;
  rig.push_block(0, d);
  rig.push_block(0, end_block(2));
  RunLog r = run_all(k);
  ASSERT_FALSE(r.events.empty());
  EXPECT_EQ(r.events.back().kind(), EventKind::end);
  EXPECT_NEAR(r.events.back().t_s, 0.25, 1e-9);
}

TEST(Channel, FeedMoveWithoutFeedIsAnErrorAtItsLine) {
  KernelRig rig(xyz_machine());
  Kernel& k = rig.k;
  rig.push_block(0, move(7, nc::Motion::linear, 10.0, {}, {}, 0.0));
  rig.push_block(0, end_block(8));
  RunLog r = run_all(k);
  auto err = std::find_if(r.events.begin(), r.events.end(),
                          [](const Event& e) { return e.kind() == EventKind::error; });
  ASSERT_NE(err, r.events.end());
  EXPECT_EQ(err->get<kernel::ev::Error>()->id, ErrorId::KernelNoFeed);
  EXPECT_EQ(err->at.line, 7u);
  EXPECT_EQ(r.events.back().get<kernel::ev::End>()->reason, EndReason::error);
  EXPECT_EQ(k.channel_state(0).status, ChannelStatus::aborted);
}

TEST(Channel, SoftwareLimitIsAnError) {
  config::Machine m = xyz_machine();
  m.axes[0].sw_limit_pos = 50;
  KernelRig rig(m);
  Kernel& k = rig.k;
  rig.push_block(0, move(3, nc::Motion::linear, 60.0));
  RunLog r = run_all(k);
  ASSERT_FALSE(r.events.empty());
  EXPECT_EQ(r.first_error().id, ErrorId::KernelSoftwareLimit);
  EXPECT_NE(rig.message(r.first_error().message.value()).find("X 60"), std::string::npos);
}

TEST(Channel, CircleWithBadEndPointIsAnError) {
  KernelRig rig(xyz_machine());
  Kernel& k = rig.k;
  nc::Block arc = move(4, nc::Motion::cw, 20.0, 0.0);
  arc.ijk[0] = 5.0;  // centre (5,0): start radius 5, end radius 15
  rig.push_block(0, arc);
  RunLog r = run_all(k);
  ASSERT_FALSE(r.events.empty());
  EXPECT_EQ(r.first_error().id, ErrorId::KernelArcEndNotOnCircle);
}

TEST(Channel, UnsupportedFunctionIsReportedNotIgnored) {
  KernelRig rig(xyz_machine());
  Kernel& k = rig.k;
  nc::Block b;
  b.line = 5;
  b.kernel_writes.push_back({"V.G.WZ_AKT.R", 5.0});  // writing the tool radius is not executed yet
  b.axes[0] = 1.0;
  rig.push_block(0, b);
  RunLog r = run_all(k);
  ASSERT_FALSE(r.events.empty());
  EXPECT_EQ(r.first_error().id, ErrorId::KernelNotYetSupported);
  EXPECT_NE(rig.message(r.first_error().message.value()).find("V.G.WZ_AKT.R"), std::string::npos);
}

TEST(Channel, FeedholdStopsAndResumes) {
  KernelRig rig(xyz_machine());
  Kernel& k = rig.k;
  rig.push_block(0, move(1, nc::Motion::linear, 100.0));
  rig.push_block(0, end_block(2));
  TickInput in;
  TickOutput out;
  for (int i = 0; i < 300; ++i) k.tick(in, out);
  in.channels[0].feedhold = true;
  for (int i = 0; i < 500; ++i) k.tick(in, out);
  const double held = out.channels[0].axis_mcs[0];
  k.tick(in, out);
  EXPECT_DOUBLE_EQ(out.channels[0].axis_mcs[0], held);
  EXPECT_LT(held, 100.0);
  in.channels[0].feedhold = false;
  for (int i = 0; i < 5000 && !k.all_channels_done(); ++i) k.tick(in, out);
  EXPECT_TRUE(k.all_channels_done());
  EXPECT_DOUBLE_EQ(out.channels[0].axis_mcs[0], 100.0);
}

TEST(Channel, ResetBrakesThenEndsTheProgram) {
  KernelRig rig(xyz_machine());
  Kernel& k = rig.k;
  rig.push_block(0, move(1, nc::Motion::linear, 100.0));
  TickInput in;
  TickOutput out;
  for (int i = 0; i < 50; ++i) k.tick(in, out);
  const double x_at_reset = out.channels[0].axis_mcs[0];
  in.channels[0].reset = true;
  k.tick(in, out);
  in.channels[0].reset = false;
  // The path brakes: the reset's cycle still moves, and nothing ends yet.
  EXPECT_GT(out.channels[0].axis_mcs[0], x_at_reset);
  EXPECT_FALSE(k.all_channels_done());
  int cycles = 1;
  for (; cycles < 1000 && !k.all_channels_done(); ++cycles) k.tick(in, out);
  EXPECT_GT(cycles, 2);
  ASSERT_EQ(out.events.size(), 2u);  // the state change to idle, then the end
  ASSERT_TRUE(out.events[0].get<kernel::ev::State>());
  EXPECT_EQ(out.events[0].get<kernel::ev::State>()->to, ProgramState::idle);
  ASSERT_TRUE(out.events[1].get<kernel::ev::End>());
  EXPECT_EQ(out.events[1].get<kernel::ev::End>()->reason, EndReason::reset);
  EXPECT_LT(out.channels[0].axis_mcs[0], 100.0);
}

TEST(Kernel, TwoChannelsTickSideBySide) {
  config::Machine m = xyz_machine();
  m.channels.push_back(m.channels[0]);
  m.channels[1].number = 2;
  m.channel_data.emplace_back();
  KernelRig rig(m);
  Kernel& k = rig.k;
  rig.push_block(0, move(1, nc::Motion::linear, 10.0));
  rig.push_block(0, end_block(2));
  rig.push_block(1, move(1, nc::Motion::linear, 20.0));
  rig.push_block(1, end_block(2));
  TickInput in;
  TickOutput out;
  for (int i = 0; i < 10000 && !k.all_channels_done(); ++i) k.tick(in, out);
  EXPECT_TRUE(k.all_channels_done());
  EXPECT_DOUBLE_EQ(k.channel_state(0).axis_mcs[0], 10.0);
  EXPECT_DOUBLE_EQ(k.channel_state(1).axis_mcs[0], 20.0);
}

// A block homes at most kMaxCommandsPerBlock order groups in sequence; one
// more is an error, not a silently dropped group.
TEST(Channel, HomingMoreOrderGroupsThanABlockHoldsIsAnError) {
  config::Machine m = xyz_machine();
  for (std::uint32_t i = 3; i < 5; ++i) {
    config::AxisConfig ax = m.axes[0];
    ax.log_axis_nr = i + 1;
    ax.name = i == 3 ? "U" : "V";
    m.axes.push_back(ax);
    m.channels[0].axes.push_back({ax.name, i + 1, static_cast<int>(i)});
  }
  KernelRig rig(m);
  nc::Block b;
  b.line = 4;
  (void)b.g_nonmodal.add(nc::GCode::g74);
  for (std::size_t j = 0; j < 5; ++j) b.axes[j] = static_cast<double>(j + 1);  // five groups
  rig.push_block(0, b);
  RunLog r = run_all(rig.k);
  ASSERT_FALSE(r.events.empty());
  EXPECT_EQ(r.events.back().kind(), EventKind::end);
  bool error = false;
  for (const Event& e : r.events) error = error || (e.get<kernel::ev::Error>() && e.get<kernel::ev::Error>()->id == ErrorId::KernelTooManyHomingGroups);
  EXPECT_TRUE(error);
}

}  // namespace
}  // namespace nck::kernel
