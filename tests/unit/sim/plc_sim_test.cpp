#include "nck/sim/plc_sim.hpp"

#include <gtest/gtest.h>

namespace nck::sim {
namespace {

using plc::kNoSpindle;
using plc::TechKind;

// Submits o with the next handle, as the kernel numbers its outputs;
// kNoHandle when the PLC took it not.
OutputHandle submit(PlcSim& plc, const TechOutput& o, double now_s) {
  static OutputHandle next = 1;
  const OutputHandle h = next++;
  return plc.submit(h, o, now_s) ? h : kNoHandle;
}

constexpr double kCycle_s = 0.001;

TechOutput m_fn(int n, std::int8_t spindle = kNoSpindle) {
  TechOutput o;
  o.kind = TechKind::m;
  o.number = n;
  o.spindle = spindle;
  return o;
}

// Ticks cycle by cycle from cycle `from` and returns the first cycle whose
// tick acknowledged h (-1 if none within `max` cycles).
int ack_cycle(PlcSim& plc, OutputHandle h, int from, int max = 5000) {
  for (int k = from; k < from + max; ++k) {
    plc.tick(k * kCycle_s);
    if (plc.acknowledged(h)) return k;
  }
  return -1;
}

config::SimConfig sim_config() {
  config::SimConfig sim;  // sim.lis in ms, converted to s by the config layer
  sim.plc_ack_delay_s = 0.010;
  sim.spindle_ack_delay_s = 0.007;
  sim.tool_change_time_s = 0.250;
  sim.gear_change_time_s = 0.500;
  sim.m_ack_delay_s = {{8, 0.020}, {3, 0.003}};
  return sim;
}

TEST(PlcSim, DefaultDelayExactToTheCycle) {
  PlcSim plc(sim_config());
  // Submitted in cycle 5 (t = 5 ms), 10 ms default: acknowledged in cycle 15.
  auto h = submit(plc, m_fn(100), 5 * kCycle_s);
  ASSERT_NE(h, kNoHandle);
  EXPECT_TRUE(plc.pending(h));
  EXPECT_EQ(ack_cycle(plc, h, 5), 15);
  EXPECT_FALSE(plc.pending(h));
}

TEST(PlcSim, DelayPerMNumberWins) {
  PlcSim plc(sim_config());
  auto m8 = submit(plc, m_fn(8), 0.0);
  EXPECT_EQ(ack_cycle(plc, m8, 0), 20);
  // M3 of a spindle has its own entry (3 ms) over the spindle delay (7 ms).
  auto m3 = submit(plc, m_fn(3, 0), 0.1);
  EXPECT_EQ(ack_cycle(plc, m3, 100), 103);
}

TEST(PlcSim, SpindleToolAndHDelays) {
  PlcSim plc(sim_config());
  auto m4 = submit(plc, m_fn(4, 1), 0.0);
  EXPECT_EQ(ack_cycle(plc, m4, 0), 7);
  TechOutput s;
  s.kind = TechKind::s;
  s.spindle = 0;
  s.value = 1000;
  auto hs = submit(plc, s, 1.0);
  EXPECT_EQ(ack_cycle(plc, hs, 1000), 1007);
  TechOutput t;
  t.kind = TechKind::t;
  t.number = 5;
  auto ht = submit(plc, t, 2.0);
  EXPECT_EQ(ack_cycle(plc, ht, 2000), 2250);
  auto m6 = submit(plc, m_fn(6), 3.0);
  EXPECT_EQ(ack_cycle(plc, m6, 3000), 3250);
  TechOutput h;
  h.kind = TechKind::h;
  h.number = 12;
  auto hh = submit(plc, h, 4.0);
  EXPECT_EQ(ack_cycle(plc, hh, 4000), 4010);
  // M3 without a spindle (a channel M function) takes the default delay.
  PlcSim plain(config::SimConfig{});
  auto m5 = submit(plain, m_fn(5), 0.0);
  EXPECT_EQ(ack_cycle(plain, m5, 0), 10);
}

TEST(PlcSim, GearChangeTakesGearTimeAndSetsStage) {
  PlcSim plc(sim_config());
  TechOutput m42 = m_fn(42, 0);
  m42.channel = 2;
  EXPECT_EQ(plc.gear_stage(2, 0), 0);
  auto h = submit(plc, m42, 0.0);
  plc.tick(0.0);
  EXPECT_TRUE(plc.gear_changing(2, 0));
  EXPECT_FALSE(plc.gear_changing(1, 0));
  EXPECT_EQ(ack_cycle(plc, h, 1), 500);
  EXPECT_FALSE(plc.gear_changing(2, 0));
  EXPECT_EQ(plc.gear_stage(2, 0), 3);  // M40 = stage 1, so M42 = stage 3 (FCT-S1 §2.8.2)
  EXPECT_EQ(plc.gear_stage(99, 0), 0);  // out of range never crashes
}

TEST(PlcSim, SilentPlcNeverAcknowledges) {
  PlcSim plc(sim_config());
  plc.set_silent(true);
  auto h = submit(plc, m_fn(100), 0.0);
  EXPECT_EQ(ack_cycle(plc, h, 0, 3000), -1);
  EXPECT_TRUE(plc.pending(h));
  // Waking up acknowledges what is overdue in the next tick.
  plc.set_silent(false);
  plc.tick(3.0);
  EXPECT_TRUE(plc.acknowledged(h));
}

TEST(PlcSim, ZeroDelayAcknowledgesInTheSameCycle) {
  config::SimConfig sim;
  sim.plc_ack_delay_s = 0;
  PlcSim plc(sim);
  auto h = submit(plc, m_fn(100), 0.042);
  EXPECT_EQ(ack_cycle(plc, h, 42), 42);
}

TEST(PlcSim, FullQueueRejectsAndDrainFreesInOrder) {
  PlcSim plc(sim_config());
  OutputHandle first = kNoHandle;
  for (std::size_t i = 0; i < PlcSim::kCapacity; ++i) {
    auto h = submit(plc, m_fn(static_cast<int>(100 + i)), 0.0);
    ASSERT_NE(h, kNoHandle);
    if (i == 0) first = h;
  }
  EXPECT_EQ(submit(plc, m_fn(99), 0.0), kNoHandle);
  EXPECT_EQ(plc.waiting(), PlcSim::kCapacity);
  plc.tick(0.010);
  PlcSim::AckList acks;
  EXPECT_EQ(plc.drain_acks(acks), PlcSim::kCapacity);
  EXPECT_EQ(acks[0].handle, first);
  EXPECT_EQ(acks[0].output.number, 100);
  EXPECT_EQ(acks[63].output.number, 163);
  EXPECT_DOUBLE_EQ(acks[5].t_ack_s, 0.010);
  EXPECT_FALSE(plc.acknowledged(first));  // drained: reported once
  EXPECT_NE(submit(plc, m_fn(99), 0.0), kNoHandle);
  EXPECT_EQ(plc.drain_acks(acks), 0u);
}

TEST(PlcSim, ReleaseAndClear) {
  PlcSim plc(sim_config());
  auto a = submit(plc, m_fn(100), 0.0);
  auto b = submit(plc, m_fn(101), 0.0);
  plc.release(a);
  EXPECT_FALSE(plc.pending(a));
  EXPECT_TRUE(plc.pending(b));
  plc.clear();
  EXPECT_FALSE(plc.pending(b));
  EXPECT_EQ(plc.waiting(), 0u);
  EXPECT_FALSE(plc.acknowledged(kNoHandle));
  plc.release(kNoHandle);  // harmless
}

TEST(PlcSim, BadConfigValuesAreTreatedAsZero) {
  config::SimConfig sim;
  sim.plc_ack_delay_s = -5;
  sim.m_ack_delay_s = {{5000, 1.0}};  // beyond M999: ignored
  PlcSim plc(sim);
  EXPECT_DOUBLE_EQ(plc.ack_delay_s(m_fn(100)), 0.0);
  EXPECT_DOUBLE_EQ(plc.ack_delay_s(m_fn(-3)), 0.0);
}

}  // namespace
}  // namespace nck::sim
