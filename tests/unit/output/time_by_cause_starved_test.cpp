// Time by cause (issue 31): starved. A kernel driven directly, with a
// producer that delivers the second block 3 s after the first has run: the
// cycles in between go to the block that ran last, and they are starved
// (preparation late), not a wait or a hold.
#include <gtest/gtest.h>

#include "../kernel/test_machine.hpp"
#include "nck/output/output_writers.hpp"
#include "nck/output/time_by_cause.hpp"

namespace nck::app {
namespace {

using kernel::testing::end_block;
using kernel::testing::KernelRig;
using kernel::testing::move;
using kernel::testing::xyz_machine;

// The largest class of the block on `line` and its share of that block's time.
std::pair<std::string, double> dominant(const nlohmann::ordered_json& final, std::uint32_t line) {
  for (const auto& b : final["channels"][0]["blocks"])
    if (b["line"] == line && !b["causes"].empty())
      return {b["causes"][0]["name"].get<std::string>(), b["causes"][0]["share"].get<double>()};
  return {"(none)", 0};
}

TEST(TimeByCauseStarved, ALateProducerStarvesTheChannel) {
  KernelRig rig(xyz_machine());
  TimeByCause ledger;
  ledger.start(*rig.m, 0.001);
  auto in = std::make_unique<kernel::TickInput>();
  auto out = std::make_unique<kernel::TickOutput>();
  const RunNames names{};
  bool ended = false;
  const auto tick = [&] {
    rig.k.tick(*in, *out);
    ledger.take(*out, names);
    for (const kernel::Event& e : out->events) ended = ended || e.kind() == kernel::EventKind::end;
  };
  rig.push_block(0, move(1, nc::Motion::linear, 10));  // 10 mm at 100 mm/s: about 0.1 s
  for (int cycle = 0; cycle < 3000; ++cycle) tick();  // the producer is 3 s late
  rig.push_block(0, move(2, nc::Motion::linear, 20));
  rig.push_block(0, end_block(3));
  for (int cycle = 0; cycle < 100'000 && !ended; ++cycle) tick();
  ledger.finish();
  ASSERT_TRUE(ended);
  const auto json = ledger.json();
  const auto [name, share] = dominant(json, 1);
  EXPECT_EQ(name, "starved") << json.dump(1);
  EXPECT_GE(share, 0.9) << json.dump(1);
  // the block that came in time runs at feed
  EXPECT_NE(dominant(json, 2).first, "starved") << json.dump(1);
}

}  // namespace
}  // namespace nck::app
