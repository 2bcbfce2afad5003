// The HAL component's function (nck.cycle: pins in, command relay, one
// Kernel::tick(), pins and events out) allocates nothing: contour.nc of
// examples/mill runs through it to M30 with counting operator new/delete,
// preparation feeding the shared queues as nck-hal does. No HAL needed: the
// pins are plain cells here.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <deque>
#include <fstream>
#include <memory>
#include <new>

#include "hal/cycle.hpp"
#include "nck/config/load.hpp"
#include "nck/prep/channel_prep.hpp"
#include "nck/prep/plan_store.hpp"

#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

namespace {
bool g_counting = false;
std::atomic<std::size_t> g_allocations = 0;
}  // namespace

void* operator new(std::size_t n) {
  if (g_counting) ++g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  if (g_counting) ++g_allocations;
  return std::malloc(n ? n : 1);
}
void* operator new[](std::size_t n, const std::nothrow_t& t) noexcept { return operator new(n, t); }
void operator delete(void* p) noexcept {
  if (g_counting && p) ++g_allocations;
  std::free(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept { operator delete(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { operator delete(p); }
void operator delete[](void* p) noexcept { operator delete(p); }
void operator delete(void* p, std::size_t) noexcept { operator delete(p); }
void operator delete[](void* p, std::size_t) noexcept { operator delete(p); }

namespace nck::hal {
namespace {

// Pin cells: HAL's pointer to the value, and the value.
struct Cells {
  std::deque<bool> bits;
  std::deque<double> floats;
  std::deque<std::uint32_t> u32s;
  std::deque<std::int32_t> s32s;
  std::deque<volatile bool*> bit_ptrs;
  std::deque<volatile double*> float_ptrs;
  std::deque<volatile std::uint32_t*> u32_ptrs;
  std::deque<volatile std::int32_t*> s32_ptrs;
  PinBit bit() { return &bit_ptrs.emplace_back(&bits.emplace_back(false)); }
  PinFloat flt(double v = 0) { return &float_ptrs.emplace_back(&floats.emplace_back(v)); }
  PinU32 u32() { return &u32_ptrs.emplace_back(&u32s.emplace_back(0u)); }
  PinS32 s32() { return &s32_ptrs.emplace_back(&s32s.emplace_back(0)); }
};

void wire(Cycle& c, Cells& k) {
  c.machine_pins = {k.bit(), k.bit(), k.bit(), k.bit(), k.u32(), k.u32(), k.s32(), k.flt()};
  **c.machine_pins.machine_on = true;
  for (std::size_t i = 0; i < c.axes().size(); ++i)
    c.axis_pins.push_back({k.flt(), k.flt(), k.flt(), k.bit(), k.bit(), k.bit(), k.bit(), k.bit(), k.bit()});
  for (std::size_t ch = 0; ch < c.channel_count(); ++ch)
    c.channel_pins.push_back({k.bit(), k.bit(), k.bit(), k.bit(), k.bit(), k.bit(), k.flt(100), k.flt(100), k.flt(),
                              k.u32(), k.s32(), k.s32(), k.s32()});
  for (std::size_t s = 0; s < c.spindle_count(); ++s)
    c.spindle_pins.push_back({k.flt(), k.flt(), k.flt(), k.flt(), k.bit(), k.bit(), k.bit(), k.bit(), k.bit()});
  for (auto& p : c.plc_pins) p = {k.bit(), k.bit(), k.s32(), k.s32(), k.s32(), k.flt()};
}

// A clock of 1,000 CPU clocks a reading and 500 ns a reading: a timed
// cycle reads the clocks twice and the nanoseconds once.
long long fake_clocks() {
  static long long c = 0;
  return c += 1000;
}
long long fake_ns() {
  static long long n = 0;
  return n += 500;
}

// examples/mill as nck-hal packs it into the shared Link, and the Cycle
// nck.so builds from that pack, its pins wired to cells.
class MillInHal : public ::testing::Test {
 protected:
  void SetUp() override {
    config::LoadOptions options;
    options.read_text = [this](const std::filesystem::path& p) -> std::optional<std::string> {
      std::ifstream in(p, std::ios::binary);
      if (!in) return std::nullopt;
      return pack_[p.string()] = std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    };
    config::LoadResult loaded = config::load_machine(folder_, options);
    ASSERT_TRUE(loaded.ok());
    machine_ = std::move(loaded.machine);
    pack_[""] = folder_.string();
    link_->magic = kLinkMagic;
    link_->version = kLinkVersion;
    ASSERT_TRUE(write_pack(*link_, pack_));
    std::string error;
    ASSERT_TRUE(cycle_.build(*link_, error)) << error;
    wire(cycle_, cells_);
    cycle_.clocks = {fake_clocks, fake_ns};
    prep_ = std::make_unique<prep::ChannelPrep>(*machine_, 0, folder_ / "contour.nc", store_, prep::PrepOptions{});
  }

  // n servo cycles of contour.nc as nck-hal feeds it, with a PLC that
  // acknowledges at once; allocations counted inside nck.cycle only.
  void cycles(std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) {
      prep_->feed(link_->commands[0], link_->feedback[0], false);
      for (std::size_t k = 0; k < kPlcSlots; ++k) {
        **cycle_.plc_pins[k].ack = **cycle_.plc_pins[k].request && !acked_[k];
        acked_[k] = **cycle_.plc_pins[k].ack;
      }
      g_counting = true;
      cycle_.run(1000000);
      g_counting = false;
      while (!link_->events.empty()) link_->events.pop();
    }
  }

  const std::filesystem::path folder_ = NCK_SOURCE_DIR "/examples/mill";
  ListPack pack_;
  std::optional<config::Machine> machine_;
  std::unique_ptr<Link> link_ = std::make_unique<Link>();
  Cycle cycle_;
  Cells cells_;
  prep::PlanStore store_;
  std::unique_ptr<prep::ChannelPrep> prep_;
  std::array<bool, kPlcSlots> acked_{};
};

TEST_F(MillInHal, ContourRunsThroughTheComponentsFunctionWithoutAllocating) {
  g_allocations = 0;
  std::size_t n = 0;
  for (; n < 200000 && !link_->channel_done[0].load(); ++n) cycles(1);
  EXPECT_EQ(g_allocations.load(), 0u);
  EXPECT_TRUE(link_->channel_done[0].load()) << "after " << n << " cycles";
  EXPECT_EQ(**cycle_.machine_pins.error_id, 0u);
  EXPECT_NEAR(**cycle_.axis_pins[2].pos_cmd, 22.0, 1e-9);  // Z, as nck run ends
  EXPECT_FALSE(**cycle_.axis_pins[2].homed);  // nck-hal starts unhomed; contour.nc homes nothing
}

// nck.tick-time is the tick's own clocks (one reading before, one after:
// 1,000), nck.clocks-per-us the rate since the first cycle (2,000 clocks
// per 500 ns a cycle: 4,000 per microsecond).
TEST_F(MillInHal, TheTickIsTimedInTheClocksOfHalsFunctionTime) {
  for (int i = 0; i < 3; ++i) cycle_.run(1000000);
  EXPECT_EQ(**cycle_.machine_pins.tick_time, 1000);
  EXPECT_DOUBLE_EQ(**cycle_.machine_pins.clocks_per_us, 4000.0);
}

TEST_F(MillInHal, AThreadPeriodOtherThanTheCycleTimeIsRefusedWithAnId) {
  cycle_.run(2000000);
  EXPECT_EQ(**cycle_.machine_pins.error_id, 940400u);
  EXPECT_TRUE(**cycle_.machine_pins.error);
  EXPECT_EQ(link_->rt_state.load(), static_cast<std::uint32_t>(RtState::error));
}

TEST(HalCycle, NoPackIsRefusedWithAnId) {
  auto link = std::make_unique<Link>();
  Cycle cycle;
  std::string error;
  EXPECT_FALSE(cycle.build(*link, error));
  EXPECT_NE(error.find("940401"), std::string::npos) << error;
}

// nck.estop is the kernel's E-stop input (issue 48 item 9): the contour
// brakes and ends in error, nck.axis.*.enable go off at standstill, the
// reset pin does nothing while the E-stop is on and leaves the error after
// its release; nothing allocates.
TEST_F(MillInHal, EstopPinBrakesEndsInErrorAndDisablesUntilReset) {
  g_allocations = 0;
  cycles(3000);
  EXPECT_TRUE(**cycle_.axis_pins[0].enable);
  **cycle_.machine_pins.estop = true;
  cycles(2000);
  const auto error_state = static_cast<std::int32_t>(kernel::ProgramState::error);
  EXPECT_EQ(**cycle_.channel_pins[0].program_state, error_state);
  EXPECT_TRUE(link_->channel_done[0].load());
  EXPECT_FALSE(**cycle_.axis_pins[0].enable);
  **cycle_.channel_pins[0].reset = true;  // ignored while the E-stop is on
  cycles(2);
  **cycle_.channel_pins[0].reset = false;
  EXPECT_EQ(**cycle_.channel_pins[0].program_state, error_state);
  **cycle_.machine_pins.estop = false;
  cycles(2);
  EXPECT_TRUE(**cycle_.axis_pins[0].enable);
  EXPECT_EQ(**cycle_.channel_pins[0].program_state, error_state);
  **cycle_.channel_pins[0].reset = true;
  cycles(2);
  EXPECT_EQ(**cycle_.channel_pins[0].program_state, static_cast<std::int32_t>(kernel::ProgramState::idle));
  EXPECT_EQ(g_allocations.load(), 0u);
}

// nck.axis.Y.amp-fault-in (issue 46): the contour brakes and ends in
// error 930750, nck.error / nck.error-id show it, the enables go off at
// standstill; after the fault's release and a reset the error pins clear
// and the enables come back; nothing allocates.
TEST_F(MillInHal, AmpFaultPinEndsInErrorShownOnTheErrorPinsUntilReset) {
  g_allocations = 0;
  cycles(3000);
  **cycle_.axis_pins[1].amp_fault = true;
  cycles(2000);
  EXPECT_EQ(**cycle_.channel_pins[0].program_state, static_cast<std::int32_t>(kernel::ProgramState::error));
  EXPECT_TRUE(link_->channel_done[0].load());
  EXPECT_TRUE(**cycle_.machine_pins.error);
  EXPECT_EQ(**cycle_.machine_pins.error_id, 930750u);
  EXPECT_FALSE(**cycle_.axis_pins[0].enable);
  **cycle_.axis_pins[1].amp_fault = false;
  **cycle_.channel_pins[0].reset = true;
  cycles(2);
  EXPECT_EQ(**cycle_.channel_pins[0].program_state, static_cast<std::int32_t>(kernel::ProgramState::idle));
  EXPECT_FALSE(**cycle_.machine_pins.error);
  EXPECT_EQ(**cycle_.machine_pins.error_id, 0u);
  EXPECT_TRUE(**cycle_.axis_pins[0].enable);
  EXPECT_EQ(g_allocations.load(), 0u);
}

// A limit switch pin: error 930751 on the error pins; the drives stay enabled.
TEST_F(MillInHal, LimitSwitchPinEndsInErrorNamingItsDirection) {
  cycles(3000);
  **cycle_.axis_pins[0].limit_pos = true;
  cycles(2000);
  EXPECT_EQ(**cycle_.machine_pins.error_id, 930751u);
  EXPECT_TRUE(**cycle_.axis_pins[0].enable);
}

// nck-hal --serve: nck.cycle publishes its state every cycle and takes the
// API's actions beside the pins (api_controls.hpp), allocation-free. The
// API's feedhold holds the path; the API's override holds until the pin
// changes; the API's feedhold off lets the program run to its end.
TEST_F(MillInHal, ApiActionsActBesideThePinsAndTheStateIsPublishedWithoutAllocating) {
  link_->serving = 1;
  const auto action = [this](sim::ActionPayload p) {
    sim::ScenarioAction a;
    a.payload = p;
    ASSERT_TRUE(link_->api_actions.push(a));
  };
  const auto state = [this]() -> const app::LiveChannel& {  // the newest published
    (void)link_->state.take();
    return link_->state.front().channels[0];
  };
  g_allocations = 0;
  cycles(3000);
  EXPECT_GT(state().path_velocity_mm_s, 1.0);
  action(sim::act::Feedhold{true});
  action(sim::act::FeedOverride{50});
  cycles(1000);
  EXPECT_EQ(state().path_velocity_mm_s, 0.0);
  EXPECT_EQ(**cycle_.channel_pins[0].path_velocity, 0.0);
  EXPECT_TRUE(state().hli.feedhold);
  EXPECT_EQ(state().hli.feed_override_percent, 50.0);
  **cycle_.channel_pins[0].feed_override = 80;  // the pin changed last: it rules
  action(sim::act::SkipMask{0x3});  // the skip levels for nck-hal's preparation
  cycles(1);
  EXPECT_EQ(state().hli.feed_override_percent, 80.0);
  EXPECT_EQ(link_->skip_mask[0].load(), 0x3u);
  EXPECT_EQ(state().hli.skip_mask, 0x3u);
  **cycle_.channel_pins[0].skip_mask = 0x1;
  cycles(1);
  EXPECT_EQ(link_->skip_mask[0].load(), 0x1u);
  action(sim::act::Feedhold{false});
  std::size_t n = 0;
  for (; n < 200000 && !link_->channel_done[0].load(); ++n) cycles(1);
  EXPECT_TRUE(link_->channel_done[0].load());
  EXPECT_EQ(state().program_state, kernel::ProgramState::ended);
  EXPECT_NEAR(state().axis_mcs[2], 22.0, 1e-9);
  EXPECT_EQ(g_allocations.load(), 0u);
}

}  // namespace
}  // namespace nck::hal
