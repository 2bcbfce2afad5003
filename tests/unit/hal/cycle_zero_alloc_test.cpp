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
  c.machine_pins = {k.bit(), k.bit(), k.bit(), k.bit(), k.u32(), k.u32()};
  **c.machine_pins.machine_on = true;
  for (std::size_t i = 0; i < c.axes().size(); ++i)
    c.axis_pins.push_back({k.flt(), k.flt(), k.flt(), k.bit(), k.bit(), k.bit(), k.bit(), k.bit()});
  for (std::size_t ch = 0; ch < c.channel_count(); ++ch)
    c.channel_pins.push_back({k.bit(), k.bit(), k.bit(), k.bit(), k.bit(), k.bit(), k.flt(100), k.flt(100), k.flt(),
                              k.u32(), k.s32(), k.s32(), k.s32()});
  for (std::size_t s = 0; s < c.spindle_count(); ++s)
    c.spindle_pins.push_back({k.flt(), k.flt(), k.flt(), k.flt(), k.bit(), k.bit(), k.bit()});
  for (auto& p : c.plc_pins) p = {k.bit(), k.bit(), k.s32(), k.s32(), k.s32(), k.flt()};
}

TEST(HalCycle, ContourRunsThroughTheComponentsFunctionWithoutAllocating) {
  const std::filesystem::path folder = NCK_SOURCE_DIR "/examples/mill";
  ListPack pack;
  config::LoadOptions options;
  options.read_text = [&pack](const std::filesystem::path& p) -> std::optional<std::string> {
    std::ifstream in(p, std::ios::binary);
    if (!in) return std::nullopt;
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    pack[p.string()] = text;
    return text;
  };
  auto loaded = config::load_machine(folder, options);
  ASSERT_TRUE(loaded.ok());
  pack[""] = folder.string();

  auto link = std::make_unique<Link>();
  link->magic = kLinkMagic;
  link->version = kLinkVersion;
  ASSERT_TRUE(write_pack(*link, pack));
  Cycle cycle;
  std::string error;
  ASSERT_TRUE(cycle.build(*link, error)) << error;
  Cells cells;
  wire(cycle, cells);
  prep::PlanStore store;
  prep::ChannelPrep prep(*loaded.machine, 0, folder / "contour.nc", store, prep::PrepOptions{});

  std::size_t cycles = 0;
  std::array<bool, kPlcSlots> acked{};
  for (; cycles < 200000 && !link->channel_done[0].load(); ++cycles) {
    prep.feed(link->commands[0], link->feedback[0], false);
    for (std::size_t k = 0; k < kPlcSlots; ++k) {  // a PLC that acknowledges at once
      **cycle.plc_pins[k].ack = **cycle.plc_pins[k].request && !acked[k];
      acked[k] = **cycle.plc_pins[k].ack;
    }
    g_counting = true;
    cycle.run(1000000);
    g_counting = false;
    while (!link->events.empty()) link->events.pop();
  }
  EXPECT_EQ(g_allocations.load(), 0u);
  EXPECT_TRUE(link->channel_done[0].load()) << "after " << cycles << " cycles";
  EXPECT_EQ(**cycle.machine_pins.error_id, 0u);
  EXPECT_NEAR(**cycle.axis_pins[2].pos_cmd, 22.0, 1e-9);  // Z, as nck run ends
}

TEST(HalCycle, AThreadPeriodOtherThanTheCycleTimeIsRefusedWithAnId) {
  const std::filesystem::path folder = NCK_SOURCE_DIR "/examples/mill";
  ListPack pack;
  config::LoadOptions options;
  options.read_text = [&pack](const std::filesystem::path& p) -> std::optional<std::string> {
    std::ifstream in(p, std::ios::binary);
    if (!in) return std::nullopt;
    return pack[p.string()] = std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  ASSERT_TRUE(config::load_machine(folder, options).ok());
  pack[""] = folder.string();
  auto link = std::make_unique<Link>();
  link->magic = kLinkMagic;
  link->version = kLinkVersion;
  ASSERT_TRUE(write_pack(*link, pack));
  Cycle cycle;
  std::string error;
  ASSERT_TRUE(cycle.build(*link, error)) << error;
  Cells cells;
  wire(cycle, cells);
  cycle.run(2000000);
  EXPECT_EQ(**cycle.machine_pins.error_id, 940400u);
  EXPECT_TRUE(**cycle.machine_pins.error);
  EXPECT_EQ(link->rt_state.load(), static_cast<std::uint32_t>(RtState::error));
}

TEST(HalCycle, NoPackIsRefusedWithAnId) {
  auto link = std::make_unique<Link>();
  Cycle cycle;
  std::string error;
  EXPECT_FALSE(cycle.build(*link, error));
  EXPECT_NE(error.find("940401"), std::string::npos) << error;
}

}  // namespace
}  // namespace nck::hal

namespace nck::hal {
namespace {

// nck.estop is the kernel's E-stop input (issue 48 item 9): the contour
// brakes and ends in error, nck.axis.*.enable go off at standstill, the
// reset pin does nothing while the E-stop is on and leaves the error after
// its release; nothing allocates.
TEST(HalCycle, EstopPinBrakesEndsInErrorAndDisablesUntilReset) {
  const std::filesystem::path folder = NCK_SOURCE_DIR "/examples/mill";
  ListPack pack;
  config::LoadOptions options;
  options.read_text = [&pack](const std::filesystem::path& p) -> std::optional<std::string> {
    std::ifstream in(p, std::ios::binary);
    if (!in) return std::nullopt;
    return pack[p.string()] = std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  auto loaded = config::load_machine(folder, options);
  ASSERT_TRUE(loaded.ok());
  pack[""] = folder.string();
  auto link = std::make_unique<Link>();
  link->magic = kLinkMagic;
  link->version = kLinkVersion;
  ASSERT_TRUE(write_pack(*link, pack));
  Cycle cycle;
  std::string error;
  ASSERT_TRUE(cycle.build(*link, error)) << error;
  Cells cells;
  wire(cycle, cells);
  prep::PlanStore store;
  prep::ChannelPrep prep(*loaded.machine, 0, folder / "contour.nc", store, prep::PrepOptions{});
  std::array<bool, kPlcSlots> acked{};
  auto run = [&](std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) {
      prep.feed(link->commands[0], link->feedback[0], false);
      for (std::size_t k = 0; k < kPlcSlots; ++k) {
        **cycle.plc_pins[k].ack = **cycle.plc_pins[k].request && !acked[k];
        acked[k] = **cycle.plc_pins[k].ack;
      }
      g_counting = true;
      cycle.run(1000000);
      g_counting = false;
      while (!link->events.empty()) link->events.pop();
    }
  };
  g_allocations = 0;
  run(3000);
  EXPECT_TRUE(**cycle.axis_pins[0].enable);
  **cycle.machine_pins.estop = true;
  run(2000);
  const auto error_state = static_cast<std::int32_t>(kernel::ProgramState::error);
  EXPECT_EQ(**cycle.channel_pins[0].program_state, error_state);
  EXPECT_TRUE(link->channel_done[0].load());
  EXPECT_FALSE(**cycle.axis_pins[0].enable);
  **cycle.channel_pins[0].reset = true;  // ignored while the E-stop is on
  run(2);
  **cycle.channel_pins[0].reset = false;
  EXPECT_EQ(**cycle.channel_pins[0].program_state, error_state);
  **cycle.machine_pins.estop = false;
  run(2);
  EXPECT_TRUE(**cycle.axis_pins[0].enable);
  EXPECT_EQ(**cycle.channel_pins[0].program_state, error_state);
  **cycle.channel_pins[0].reset = true;
  run(2);
  EXPECT_EQ(**cycle.channel_pins[0].program_state, static_cast<std::int32_t>(kernel::ProgramState::idle));
  EXPECT_EQ(g_allocations.load(), 0u);
}

}  // namespace
}  // namespace nck::hal
