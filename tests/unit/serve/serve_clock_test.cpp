// The live kernel's clock at the ends of its speed range (issue 45, item 3):
// a slow speed's distant deadline never keeps the kernel from an operator
// action or a stop, and a speed far below the range neither overflows the
// deadline (running flat out) nor sleeps for ever.
#include <chrono>
#include <future>
#include <thread>

#include <gtest/gtest.h>

#include "nck/config/load.hpp"
#include "nck/serve/cycle_clock.hpp"
#include "nck/serve/live_kernel.hpp"
#include "nck/sim/dry_run.hpp"

namespace nck::app::serve {
namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

// The milling example (1 ms cycles) live at `speed`, started without real-time priority.
struct LiveMill {
  config::LoadResult loaded = config::load_machine(std::string(NCK_SOURCE_DIR) + "/examples/mill");
  std::unique_ptr<LiveKernel> kernel;

  explicit LiveMill(double speed) {
    sim::DryRunOptions o;
    o.prep_thread = true;
    auto run = sim::DryRun::create(*loaded.machine, {}, o);
    auto first = std::make_unique<sim::DryRun>(std::move(*run));
    first->start_preparation_thread();
    kernel = std::make_unique<LiveKernel>(std::move(first), speed);
    (void)kernel->start(false);
  }
  // The newest state's feedhold of channel 1, once the kernel published one.
  bool feedhold() {
    (void)kernel->take_snapshot();
    return kernel->snapshot().channels[0].hli.feedhold;
  }
};

TEST(ServeClock, ASlowSpeedStopsAtOnce) {
  LiveMill live(kMinSpeed);  // 1 s of wall time per 1 ms cycle
  std::this_thread::sleep_for(milliseconds(50));
  const auto t0 = Clock::now();
  live.kernel->stop();
  // before issue 45: the stop waited for the deadline (1 s here, 100 s at 1e-5)
  EXPECT_LT(ms_since(t0), 300.0);
}

TEST(ServeClock, ASlowSpeedTakesAnOperatorActionAtOnce) {
  LiveMill live(kMinSpeed);
  std::this_thread::sleep_for(milliseconds(50));
  ASSERT_FALSE(live.feedhold());
  const auto t0 = Clock::now();
  ASSERT_TRUE(live.kernel->operate(sim::make_action(1, sim::act::Feedhold{true})));
  while (!live.feedhold() && ms_since(t0) < 2000) std::this_thread::sleep_for(milliseconds(2));
  EXPECT_TRUE(live.feedhold());
  EXPECT_LT(ms_since(t0), 300.0);  // not at the next deadline, up to 1 s away
}

TEST(ServeClock, ASpeedBelowTheRangeNeitherRacesNorSleepsForEver) {
  CycleClock clock(1e-3);
  clock.set_speed(1e-300);  // 1e306 ns per cycle overflowed the deadline: no sleep at all
  clock.start();
  const auto t0 = Clock::now();
  auto waited = std::async(std::launch::async, [&] {
    (void)clock.wait();
    return ms_since(t0);
  });
  std::this_thread::sleep_for(milliseconds(100));
  clock.set_speed(1);  // a new speed wakes the wait
  ASSERT_EQ(waited.wait_for(std::chrono::seconds(2)), std::future_status::ready) << "the wait did not wake";
  const double ms = waited.get();
  EXPECT_GE(ms, 80.0) << "the wait did not sleep";
  EXPECT_LT(ms, 300.0);
}

TEST(ServeClock, AtRealTimeAWakeChangesNoDeadline) {
  CycleClock clock(1e-3);
  clock.start();
  const auto t0 = Clock::now();
  std::uint64_t cycles = 0;
  while (ms_since(t0) < 200) {
    clock.wake();  // as if every cycle brought an action
    cycles += clock.wait();
  }
  EXPECT_NEAR(static_cast<double>(cycles), ms_since(t0), 20.0);  // one cycle per ms, no extra ones
}

}  // namespace
}  // namespace nck::app::serve
