// Proof of the cyclic contract: a whole example program runs through
// Kernel::tick() without a single heap allocation or release inside tick().
// The global operator new/delete are replaced by counting versions that only
// count while `g_in_tick` is set.
#include <gtest/gtest.h>

#include <cstdlib>
#include <new>

#include "nck/config/load.hpp"
#include "nck/kernel/decoder_setup.hpp"
#include "nck/kernel/kernel.hpp"
#include "nck/nc/decoder.hpp"

namespace {
bool g_in_tick = false;
std::size_t g_allocations = 0;
}  // namespace

void* operator new(std::size_t n) {
  if (g_in_tick) ++g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
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
};

// Runs the example; returns the number of cycles. Decoding and planning
// happen outside tick(), as in `nck run`.
std::uint64_t run_counting(const Example& ex) {
  const std::string root = NCK_SOURCE_DIR;
  config::LoadResult loaded = config::load_machine(root + "/" + ex.machine);
  EXPECT_TRUE(loaded.ok());
  if (!loaded.ok()) return 0;
  Kernel k;
  EXPECT_TRUE(k.configure(*loaded.machine));
  std::vector<nc::Decoder> decoders;
  for (std::size_t ch = 0; ch < ex.programs.size(); ++ch)
    decoders.emplace_back(root + "/" + ex.programs[ch], decoder_config(*loaded.machine, ch));
  std::vector<bool> fed(decoders.size(), false);
  TickInput in;
  TickOutput out;
  for (std::uint64_t cycle = 0; cycle < 10'000'000; ++cycle) {
    for (std::size_t ch = 0; ch < decoders.size(); ++ch)
      while (!fed[ch] && k.queue_space(ch) > 0) {
        nc::Decoder::Result r = decoders[ch].next();
        EXPECT_EQ(r.status, nc::Decoder::Status::block) << ex.programs[ch];
        if (r.status != nc::Decoder::Status::block) return 0;
        k.push_block(ch, r.block, decoders[ch].file_name(r.block.file_id));
        fed[ch] = r.block.program_end;
      }
    g_in_tick = true;
    k.tick(in, out);
    g_in_tick = false;
    for (const Event& e : out.events) EXPECT_NE(e.kind, EventKind::error) << e.line;
    if (k.all_channels_done()) return cycle + 1;
  }
  return 0;
}

TEST(ZeroAllocation, CountingHookSeesAllocations) {
  g_allocations = 0;
  g_in_tick = true;
  auto* p = new int(3);
  delete p;
  g_in_tick = false;
  EXPECT_EQ(g_allocations, 2u);  // the hook works, so a 0 below means something
}

TEST(ZeroAllocation, WholeExamplesRunThroughTickWithoutHeap) {
  const Example examples[] = {
      {"examples/mill", {"examples/mill/contour.nc"}},
      {"examples/mill", {"examples/mill/offsets.nc"}},
      {"examples/mill", {"examples/mill/coordinates.nc"}},
      {"examples/mill", {"examples/mill/tools.nc"}},
      {"examples/mill", {"examples/mill/spindle.nc"}},
      {"examples/lathe", {"examples/lathe/turn.nc"}},
      {"examples/lathe", {"examples/lathe/gears.nc"}},
      {"examples/two-channel", {"examples/two-channel/channel1.nc", "examples/two-channel/channel2.nc"}},
  };
  for (const Example& ex : examples) {
    g_allocations = 0;
    const std::uint64_t cycles = run_counting(ex);
    EXPECT_GT(cycles, 1000u) << ex.machine;
    EXPECT_EQ(g_allocations, 0u) << ex.machine;
  }
}

}  // namespace
}  // namespace nck::kernel
