// Proof of the cyclic contract: a whole example program runs through
// Kernel::tick() without a single heap allocation or release inside tick().
// The global operator new/delete are replaced by counting versions that only
// count while `g_in_tick` is set, and only in the thread that set it: with
// preparation in a thread of its own, that thread may allocate, the cycle's
// may not.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "nck/config/load.hpp"
#include "nck/sim/scenario.hpp"
#include "nck/sim/dry_run.hpp"
#include "../seen_events.hpp"

// GCC 12 takes the malloc/free inside these replacements for a mismatch
// with new/delete at inlined call sites: a known false positive.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

namespace {
thread_local bool g_in_tick = false;
std::atomic<std::size_t> g_allocations = 0;
}  // namespace

void* operator new(std::size_t n) {
  if (g_in_tick) ++g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
// The nothrow forms too (std::stable_sort uses them), so that every
// allocation is released by its twin.
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  if (g_in_tick) ++g_allocations;
  return std::malloc(n ? n : 1);
}
void* operator new[](std::size_t n, const std::nothrow_t& t) noexcept { return operator new(n, t); }
void operator delete(void* p, const std::nothrow_t&) noexcept { operator delete(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { operator delete(p); }
void operator delete(void* p) noexcept {
  if (g_in_tick && p) ++g_allocations;
  std::free(p);
}
void operator delete[](void* p) noexcept { operator delete(p); }
void operator delete(void* p, std::size_t) noexcept { operator delete(p); }
void operator delete[](void* p, std::size_t) noexcept { operator delete(p); }

namespace nck::kernel {
namespace {

struct Example {
  const char* machine;
  std::vector<const char*> programs;
  const char* plc = nullptr;  // --plc scenario (handwheel, probe, PLC acknowledgements)
  bool errors_expected = false;  // the scenario raises errors on purpose (an E-stop)
  bool unhomed = false;          // no axis homed at start (nck run --unhomed)
};

// Runs the example; returns the number of cycles. Decoding and planning
// (prepare) happen outside the cycle, as in `nck run`; the cycle covers the
// simulated machine's read and write, the kernel's tick and both queues.
std::uint64_t run_counting(const Example& ex, bool prep_thread = false) {
  const std::string root = NCK_SOURCE_DIR;
  // Relative to the repository; an absolute path (a machine written by the test) as it is.
  config::LoadResult loaded = config::load_machine(std::filesystem::path(root) / ex.machine);
  EXPECT_TRUE(loaded.ok());
  if (!loaded.ok()) return 0;
  std::vector<std::filesystem::path> programs;
  for (const char* p : ex.programs) programs.emplace_back(std::filesystem::path(root) / p);
  sim::DryRunOptions options;
  options.prep_thread = prep_thread;
  if (ex.unhomed) options.homed_axes.fill(0u);
  auto run = sim::DryRun::create(*loaded.machine, programs, options);
  EXPECT_TRUE(run.has_value());
  if (!run) return 0;
  sim::Scenario scenario;
  if (ex.plc) {
    Diagnostics ds;
    std::ifstream f(root + "/" + ex.plc);
    std::stringstream text;
    text << f.rdbuf();
    scenario = sim::parse_scenario(text.str(), ex.plc, ds);
    sim::resolve_spindles(scenario, *loaded.machine, plc::build_spindle_map(*loaded.machine), ds);
    EXPECT_FALSE(ds.has_errors()) << ex.plc;
    run->load_scenario(scenario);
  }
  auto out = std::make_unique<TickOutput>();
  for (std::uint64_t cycle = 0; cycle < 10'000'000; ++cycle) {
    run->prepare();
    g_in_tick = true;
    run->cycle(*out);
    g_in_tick = false;
    if (!ex.errors_expected) {
      for (const Event& e : out->events) EXPECT_NE(e.kind(), EventKind::error) << e.at.line;
    }
    if (run->done()) return cycle + 1;
  }
  return 0;
}

TEST(ZeroAllocation, CountingHookSeesAllocations) {
  g_allocations = 0;
  g_in_tick = true;
  auto* p = new int(3);
  delete p;
  g_in_tick = false;
  EXPECT_EQ(g_allocations.load(), 2u);  // the hook works, so a 0 below means something
}

// The spindle-link seed's programs are short (about 590 cycles each).
TEST(ZeroAllocation, SeedLinkProgramsRunThroughTickWithoutHeap) {
  const Example examples[] = {
      {"examples/twin-spindle", {"examples/twin-spindle/link_names.nc"}},
      {"examples/twin-spindle", {"examples/twin-spindle/link_on_off.nc"}},
      {"examples/twin-spindle", {"examples/twin-spindle/link_nbr.nc"}},
  };
  for (const Example& ex : examples) {
    g_allocations = 0;
    EXPECT_GT(run_counting(ex), 500u) << ex.programs[0];
    EXPECT_EQ(g_allocations.load(), 0u) << ex.programs[0];
  }
}

TEST(ZeroAllocation, WholeExamplesRunThroughTickWithoutHeap) {
  const Example examples[] = {
      {"examples/mill", {"examples/mill/contour.nc"}},
      {"examples/mill-cia402", {"examples/mill-cia402/enable.nc"}},  // CiA 402 drives: enable, set points
      {"examples/mill-cia402", {"examples/mill-cia402/home.nc"}},  // G74: the drives home (mode 6)
      {"examples/mill-analog", {"examples/mill-analog/home.nc"}},  // G74: the NC's cam search
      {"examples/mill", {"examples/mill/contour.nc"}, "examples/mill/single_step.plc"},  // hold and release
      {"examples/mill", {}, "examples/mill/mdi.plc"},                                    // MDI
      {"examples/mill", {"examples/mill/contour_blend.nc"}},
      // P-AXIS-00277: G74 homes the unhomed axes in the cycle (HomeAxes), the homing check at each block start
      {"tests/data/machine_homing", {"tests/data/machine_homing/home_then_move.nc"}, nullptr, false, true},
      // ... and its refusal (930740) ends the run
      {"tests/data/machine_homing", {"tests/data/machine_homing/move.nc"}, nullptr, true, true},
      {"examples/mill", {"examples/mill/offsets.nc"}},
      {"examples/mill", {"examples/mill/coordinates.nc"}},
      {"examples/mill", {"examples/mill/tools.nc"}},
      {"examples/mill", {"examples/mill/spindle.nc"}, "examples/mill/spindle.plc"},
      {"examples/mill", {"examples/mill/measure.nc"}},
      {"examples/mill", {"examples/mill/manual.nc"}, "examples/mill/manual.plc"},
      {"examples/mill", {"examples/mill/jog.nc"}, "examples/mill/jog.plc"},  // jog, handwheel in manual mode, soft limit
      // E-stop braking, refusals, reset, machine off and on
      {"examples/mill", {"examples/mill/contour.nc"}, "examples/mill/estop.plc", true},
      // an amplifier fault and a limit switch: braking, refusals, reset, MDI refused and run
      {"examples/mill", {"tests/scenarios/mill-amp-fault/prog.nc"}, "tests/scenarios/mill-amp-fault/amp.plc", true},
      {"examples/mill", {"tests/scenarios/mill-limit-switch/prog.nc"}, "tests/scenarios/mill-limit-switch/limit.plc", true},
      {"examples/mill", {"examples/mill/caxis.nc"}},
      {"examples/mill", {"examples/mill/cylinder.nc"}},
      {"examples/mill", {"examples/mill/jumps.nc"}},
      {"examples/mill", {"examples/mill/contour_trc.nc"}},
      {"examples/lathe", {"examples/lathe/profile_trc.nc"}},
      {"examples/mill", {"examples/mill/cycles.nc"}},
      {"examples/lathe", {"examples/lathe/turn.nc"}},
      {"examples/lathe", {"examples/lathe/gears.nc"}},
      {"examples/lathe", {"examples/lathe/diameter.nc"}},
      {"examples/lathe", {"examples/lathe/facing.nc"}},
      {"examples/lathe", {"examples/lathe/profile.nc"}},
      {"examples/lathe", {"examples/lathe/thread.nc"}},
      {"examples/lathe", {"examples/lathe/tapping.nc"}},
      {"examples/mill", {"examples/mill/tapping.nc"}},
      {"examples/cutter", {"examples/cutter/contour.nc"}},
      {"examples/two-channel", {"examples/two-channel/channel1.nc", "examples/two-channel/channel2.nc"}},
      {"examples/twin-spindle", {"examples/twin-spindle/twin.nc"}},
      {"examples/two-channel", {"examples/two-channel/link_ch1.nc", "examples/two-channel/link_ch2.nc"}},
  };
  for (const Example& ex : examples) {
    g_allocations = 0;
    const std::uint64_t cycles = run_counting(ex);
    EXPECT_GT(cycles, ex.errors_expected ? 0u : 1000u) << ex.machine;  // a refusal ends at once
    EXPECT_EQ(g_allocations.load(), 0u) << ex.machine;
  }
}

// The spindles' jerk-limited ramps (slope_type 1 and 2): examples/mill
// with S1 on TRAPEZ and S2 on SIN2 runs spindle.nc (run-ups, override,
// reversal, M19 with homing, G74) through tick without heap.
TEST(ZeroAllocation, JerkLimitedSpindlesRunThroughTickWithoutHeap) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("nck_zero_alloc_slope_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::copy(std::string(NCK_SOURCE_DIR) + "/examples/mill", dir, fs::copy_options::recursive);
  for (auto [file, type] : {std::pair{"s1.lis", "1"}, {"s2.lis", "2"}}) {
    std::stringstream text;
    text << std::ifstream(dir / file).rdbuf();
    std::string s = text.str();
    s.insert(s.rfind("Ende"), std::string("getriebe[0].slope_type ") + type + "\n");
    std::ofstream(dir / file) << s;
  }
  const std::string machine = dir.string();
  g_allocations = 0;
  const Example ex{machine.c_str(), {"examples/mill/spindle.nc"}, "examples/mill/spindle.plc"};
  EXPECT_GT(run_counting(ex), 1000u);
  EXPECT_EQ(g_allocations.load(), 0u);
  fs::remove_all(dir);
}

// HSC's chains (#SLOPE [TYPE=HSC]): 400 short collinear and slightly
// turning blocks, more than the command queue holds, so the chain grows as
// preparation queues more, then a corner and an arc; through tick without
// heap.
TEST(ZeroAllocation, HscChainsRunThroughTickWithoutHeap) {
  namespace fs = std::filesystem;
  const fs::path file = fs::temp_directory_path() / ("nck_zero_alloc_hsc_" + std::to_string(getpid()) + ".nc");
  std::ofstream out(file);
  out << "N1 G17 G90 G0 X0 Y0 Z0\n#SLOPE [TYPE=HSC]\n";
  double x = 0, y = 0, angle = 0;
  for (int i = 0; i < 400; ++i) {
    angle += (i % 40 < 20 ? 0.002 : -0.002);
    x += 0.5 * std::cos(angle);
    y += 0.5 * std::sin(angle);
    out << "G1 X" << x << " Y" << y << " F6000\n";
  }
  out << "G1 Y" << y + 20 << "\nG2 X" << x + 20 << " I10 J0\nM30\n";
  out.close();
  const std::string program = file.string();
  g_allocations = 0;
  const Example ex{"examples/mill", {program.c_str()}};
  EXPECT_GT(run_counting(ex), 1000u);
  EXPECT_EQ(g_allocations.load(), 0u);
  fs::remove(file);
}

// Preparation in its own thread (--prep-thread): the cycle thread still
// allocates nothing, while the preparation thread plans beside it (the
// programs with feedback from execution, G100 and #CAX, included).
TEST(ZeroAllocation, CycleThreadAllocatesNothingBesidePreparationThread) {
  const Example examples[] = {
      {"examples/mill", {"examples/mill/contour.nc"}},
      {"examples/mill", {"examples/mill/measure.nc"}},
      {"examples/mill", {"examples/mill/caxis.nc"}},
      {"examples/mill", {"examples/mill/manual.nc"}, "examples/mill/manual.plc"},
      {"examples/mill", {}, "examples/mill/mdi.plc"},
      {"examples/cutter", {"examples/cutter/contour.nc"}},
      {"examples/two-channel", {"examples/two-channel/channel1.nc", "examples/two-channel/channel2.nc"}},
  };
  for (const Example& ex : examples) {
    g_allocations = 0;
    const char* name = ex.programs.empty() ? ex.plc : ex.programs[0];
    EXPECT_GT(run_counting(ex, true), 1000u) << name;
    EXPECT_EQ(g_allocations.load(), 0u) << name;
  }
}

}  // namespace
}  // namespace nck::kernel
