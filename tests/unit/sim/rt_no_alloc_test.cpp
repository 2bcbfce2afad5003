// The cyclic entry points of the simulated machine must not touch the heap: a
// counting global operator new proves it (this replacement applies to the
// whole test_sim binary, it only counts).
#include <atomic>
#include <cstdlib>
#include <new>

#include <gtest/gtest.h>

#include <memory>

#include "nck/sim/scenario.hpp"
#include "nck/sim/machine_sim.hpp"

namespace {
std::atomic<long> g_allocs{0};
}

void* operator new(std::size_t n) {
  ++g_allocs;
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
// Every form is replaced, so that each allocation is released by its twin
// (std::stable_sort uses the nothrow form).
void* operator new[](std::size_t n) { return operator new(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  ++g_allocs;
  return std::malloc(n == 0 ? 1 : n);
}
void* operator new[](std::size_t n, const std::nothrow_t& t) noexcept { return operator new(n, t); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }

namespace nck::sim {
namespace {

// The simulated machine's read/write with a scenario that exercises every
// kind of action, outputs to acknowledge and the external command queue.
TEST(SimRealTime, ReadAndWriteDoNotAllocate) {
  config::Machine m;
  m.channels.resize(1);
  m.channels[0].spindles.resize(1);
  m.channels[0].spindles[0].name = "S1";
  m.channels[0].spindles[0].log_axis_nr = 1;
  m.sim.m_ack_delay_s = {{8, 0.02}};
  Diagnostics d;
  auto sc = sim::parse_scenario(
      "0.001 override S1 50\n0.002 spindle_cmd S1 M3 REV100\n0.003 silent on\n0.004 silent off\n"
      "0.005 spindle_stop_at_end on\n0.006 reset\n",
      "rt.plc", d);
  sim::resolve_spindles(sc, m, plc::build_spindle_map(m), d);
  ASSERT_FALSE(d.has_errors());
  MachineSim sim(m);
  sim.load_scenario(sc);
  auto in = std::make_unique<kernel::TickInput>();
  auto out = std::make_unique<kernel::TickOutput>();
  plc::ExtCommandQueue ext;

  const long before = g_allocs.load();
  for (int k = 0; k < 200; ++k) {
    const double t = k * 0.001;
    sim.read(t, *in);
    for (const auto& c : in->ext_commands) (void)ext.push(c);
    plc::ExtSpindleCommand c;
    while (ext.pop(c)) ext.acknowledge(c.seq);
    out->tech_outputs.clear();
    plc::TechOutput o;
    o.number = 8 + (k % 3);
    o.spindle = 0;
    (void)out->tech_outputs.push_back(kernel::TechRequest{static_cast<plc::OutputHandle>(k + 1), o});
    sim.write(*out);
    (void)plc::encode_position(t * 100, plc::position_format(sim.hli().ads_32_bit_comp_mode));
  }
  EXPECT_EQ(g_allocs.load() - before, 0);
  EXPECT_EQ(ext.last_acknowledged(), 1u);
}

}  // namespace
}  // namespace nck::sim
