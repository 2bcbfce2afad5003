// Each offset kind alone, then combinations in the order the seed allows,
// and PCS -> MCS -> PCS round trips. Expected numbers are worked by hand.
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "chain_fixture.hpp"

namespace nck::frames::test {
namespace {

constexpr double kS45 = 0.70710678118654752;  // sin 45 = cos 45

struct Case {
  std::string name;
  std::function<void(OffsetChain&)> setup;
  PcsPoint in;
  McsPoint want;
};

std::vector<Case> single_kinds() {
  const ZeroOffsetTable t = zero_table();
  return {
      {"none", [](OffsetChain&) {}, pcs(1, 2, 3, 4), mcs(1, 2, 3, 4)},
      {"G54", [t](OffsetChain& c) { ok(c.select_zero_offset(t, 1)); }, pcs(0, 0, 0), mcs(10, -5, 0)},
      {"G55", [t](OffsetChain& c) { ok(c.select_zero_offset(t, 2)); }, pcs(1, 1, 1), mcs(1, 1, 4)},
      {"G159=7", [t](OffsetChain& c) { ok(c.select_zero_offset(t, 7)); }, pcs(0, 0, 0), mcs(70, 0, 0)},
      {"G53 deselects", [t](OffsetChain& c) { ok(c.select_zero_offset(t, 0)); }, pcs(0, 0, 0), mcs(0, 0, 0)},
      {"G53 with g53_verfuegbar",
       [t](OffsetChain& c) {
         ZeroOffsetTable u = t;
         u.g53_available = true;
         ok(c.select_zero_offset(u, 0));
       },
       pcs(0, 0, 0), mcs(7, 0, 0)},
      {"G54 with Y inaktiv",
       [t](OffsetChain& c) {
         ZeroOffsetTable u = t;
         u.groups[1].inactive_mask = 1u << 1;
         ok(c.select_zero_offset(u, 1));
       },
       pcs(0, 0, 0), mcs(10, 0, 0)},
      {"G92 X10 Z30 (G90)",
       [](OffsetChain& c) {
         ok(c.set_g92(0, 10, false));
         ok(c.set_g92(2, 30, false));
       },
       pcs(0, 0, 0), mcs(10, 0, 30)},
      {"G92 X10 then G91 G92 X5 adds",
       [](OffsetChain& c) {
         ok(c.set_g92(0, 10, false));
         ok(c.set_g92(0, 5, true));
       },
       pcs(0, 0, 0), mcs(15, 0, 0)},
      {"G92 X10 then G90 G92 X5 sets",
       [](OffsetChain& c) {
         ok(c.set_g92(0, 10, false));
         ok(c.set_g92(0, 5, false));
       },
       pcs(0, 0, 0), mcs(5, 0, 0)},
      {"#PSET X20 at machine X50", [](OffsetChain& c) { ok(c.pset(0, 20, mcs(50, 0, 0))); },
       pcs(20, 0, 0), mcs(50, 0, 0)},
      {"#PSET then #PRESET",
       [](OffsetChain& c) {
         ok(c.pset(0, 20, mcs(50, 0, 0)));
         ok(c.preset(std::nullopt));
       },
       pcs(20, 0, 0), mcs(20, 0, 0)},
      {"G101 X factor 1: measured 10.2 target 10",
       [](OffsetChain& c) { ok(c.measure_apply(0, 1.0, 10.2, 10.0)); }, pcs(0, 0, 0), mcs(0.2, 0, 0)},
      {"G101 Y factor 0.5: measured 4 target 5",
       [](OffsetChain& c) { ok(c.measure_apply(1, 0.5, 4.0, 5.0)); }, pcs(0, 0, 0), mcs(0, -0.5, 0)},
      {"manual offset X1.5 (no deferral)", [](OffsetChain& c) { ok(c.set_manual_offset(0, 1.5)); },
       pcs(0, 0, 0), mcs(1.5, 0, 0)},
      {"clamp offset X10 (TF5200 [CLMP] example)",
       [](OffsetChain& c) {
         AxisValues v{};
         v[0] = 10;
         ok(c.set_clamp_offsets(v));
       },
       pcs(0, 0, 0), mcs(10, 0, 0)},
      {"D5 length 60 in G17 on Z (wz[5].laenge 600000)",
       [](OffsetChain& c) {
         ToolOffsets d{5, 60.0, {}, false};
         ok(c.select_tool(d));
       },
       pcs(0, 0, 0), mcs(0, 0, 60)},
      {"D5 length 60 in G18 on Y",
       [](OffsetChain& c) {
         c.set_plane(Plane::g18);
         ok(c.select_tool(ToolOffsets{5, 60.0, {}, false}));
       },
       pcs(0, 0, 0), mcs(0, 60, 0)},
      {"D5 length 60 in G19 on X",
       [](OffsetChain& c) {
         c.set_plane(Plane::g19);
         ok(c.select_tool(ToolOffsets{5, 60.0, {}, false}));
       },
       pcs(0, 0, 0), mcs(60, 0, 0)},
      {"tool ax_versatz X2 C0.5",
       [](OffsetChain& c) {
         ToolOffsets d{2, 0, {}, false};
         d.axis_offset_mm[0] = 2;
         d.axis_offset_mm[3] = 0.5;
         ok(c.select_tool(d));
       },
       pcs(0, 0, 0, 0), mcs(2, 0, 0, 0.5)},
      {"#TLC ON [15]", [](OffsetChain& c) { ok(c.tlc_on(15)); }, pcs(0, 0, 0), mcs(0, 0, 15)},
      {"#CS ON [1][0,0,10,0,0,45] (TF5200 #CS example)",
       [](OffsetChain& c) { ok(c.cs_on(CsFamily::cs, 1, CsValues{{0, 0, 10}, {0, 0, 45}})); },
       pcs(10, 0, 0), mcs(10 * kS45, 10 * kS45, 10)},
      {"#ACS ON [2][0,0,0,0,0,1.5] (TF5200 #ACS example)",
       [](OffsetChain& c) { ok(c.cs_on(CsFamily::acs, 2, CsValues{{0, 0, 0}, {0, 0, 1.5}})); },
       pcs(100, 0, 0), mcs(99.965732497555726, 2.6176948307873153, 0)},
      {"#ROTATION ON [ANGLE=30 CENTER1=10 CENTER2=5] (TF5200 #ROTATION example)",
       [](OffsetChain& c) { ok(c.rotation_on(30, 10, 5)); }, pcs(20, 5, 7), mcs(18.660254037844386, 10, 7)},
      {"#ROTATION 90 in G18 turns Z towards X",
       [](OffsetChain& c) {
         c.set_plane(Plane::g18);
         ok(c.rotation_on(90));
       },
       pcs(0, 0, 1), mcs(1, 0, 0)},
      {"#ECS ON with a given effector frame",
       [](OffsetChain& c) { ok(c.ecs_on(RigidFrame{{1, 2, 3}, rot_x(90)})); }, pcs(0, 1, 0), mcs(1, 2, 4)},
  };
}

std::vector<Case> combinations() {
  const ZeroOffsetTable t = zero_table();
  return {
      // ACS is outside the CS: CS shift first, then the ACS turn.
      {"ACS rotZ90 + CS shift X10",
       [](OffsetChain& c) {
         ok(c.cs_on(CsFamily::acs, 1, CsValues{{0, 0, 0}, {0, 0, 90}}));
         ok(c.cs_on(CsFamily::cs, 1, CsValues{{10, 0, 0}, {0, 0, 0}}));
       },
       pcs(1, 0, 0), mcs(0, 11, 0)},
      // Same result whichever of the two is switched on first.
      {"CS shift X10 then ACS rotZ90",
       [](OffsetChain& c) {
         ok(c.cs_on(CsFamily::cs, 1, CsValues{{10, 0, 0}, {0, 0, 0}}));
         ok(c.cs_on(CsFamily::acs, 1, CsValues{{0, 0, 0}, {0, 0, 90}}));
       },
       pcs(1, 0, 0), mcs(0, 11, 0)},
      // Nested CS: the inner one is relative to the outer one.
      {"CS1 X10 rotZ90, nested CS2 X5",
       [](OffsetChain& c) {
         ok(c.cs_on(CsFamily::cs, 1, CsValues{{10, 0, 0}, {0, 0, 90}}));
         ok(c.cs_on(CsFamily::cs, 2, CsValues{{5, 0, 0}, {0, 0, 0}}));
       },
       pcs(0, 0, 0), mcs(10, 5, 0)},
      // The CS sits in the WCS, which already holds the zero offset.
      {"G54 + CS rotZ90",
       [t](OffsetChain& c) {
         ok(c.select_zero_offset(t, 1));
         c.commit_all();
         ok(c.cs_on(CsFamily::cs, 1, CsValues{{0, 0, 0}, {0, 0, 90}}));
       },
       pcs(1, 0, 0), mcs(10, -4, 0)},
      // #ROTATION acts on the programmed point before the CS.
      {"#ROTATION 90 + CS shift X10",
       [](OffsetChain& c) {
         ok(c.cs_on(CsFamily::cs, 1, CsValues{{10, 0, 0}, {0, 0, 0}}));
         ok(c.rotation_on(90));
       },
       pcs(1, 0, 0), mcs(10, 1, 0)},
      // Machining directions: the tool offset turns with the CS.
      {"CS rotZ90 + tool ax_versatz X2 length 60 (tool_fixed 0)",
       [](OffsetChain& c) {
         ToolOffsets d{1, 60, {}, false};
         d.axis_offset_mm[0] = 2;
         ok(c.select_tool(d));
         c.commit_all();
         ok(c.cs_on(CsFamily::cs, 1, CsValues{{0, 0, 0}, {0, 0, 90}}));
       },
       pcs(0, 0, 0), mcs(0, 2, 60)},
      // Machine directions: it does not.
      {"CS rotZ90 + tool ax_versatz X2 length 60 (tool_fixed 1)",
       [](OffsetChain& c) {
         ToolOffsets d{1, 60, {}, true};
         d.axis_offset_mm[0] = 2;
         ok(c.select_tool(d));
         c.commit_all();
         ok(c.cs_on(CsFamily::cs, 1, CsValues{{0, 0, 0}, {0, 0, 90}}));
       },
       pcs(0, 0, 0), mcs(2, 0, 60)},
      {"every translation at once",
       [t](OffsetChain& c) {
         AxisValues clamp{};
         clamp[0] = 100;
         ok(c.set_clamp_offsets(clamp));
         ok(c.select_zero_offset(t, 1));   // X10 Y-5
         ok(c.set_g92(0, 1, false));       // X1
         ok(c.measure_apply(1, 1, 2, 1));  // Y1
         ok(c.set_manual_offset(2, 0.25));
         ok(c.select_tool(ToolOffsets{3, 50, {}, false}));
         ok(c.tlc_on(-0.5));
         c.commit_all();
       },
       pcs(0, 0, 0), mcs(111, -4, 49.75)},
  };
}

void run(const std::vector<Case>& cases) {
  for (const Case& k : cases) {
    SCOPED_TRACE(k.name);
    OffsetChain c = make_chain();
    k.setup(c);
    c.commit_all();
    expect_point(c.to_mcs(k.in).pos_mm, k.want.pos_mm);
    expect_point(c.to_pcs(k.want).pos_mm, k.in.pos_mm);  // exact inverse
  }
}

TEST(OffsetKinds, EachKindAlone) { run(single_kinds()); }
TEST(OffsetKinds, Combinations) { run(combinations()); }

TEST(OffsetKinds, RoundTripEverythingActive) {
  OffsetChain c = make_chain();
  ZeroOffsetTable t = zero_table();
  ok(c.select_zero_offset(t, 1));
  ok(c.set_g92(2, -3, false));
  ok(c.pset(1, 4, mcs(9, 9, 9)));
  ok(c.measure_apply(0, 0.8, 1.3, 1.0));
  ok(c.set_manual_offset(3, 2));
  ToolOffsets d{4, 80, {}, false};
  d.axis_offset_mm[1] = -1.25;
  ok(c.select_tool(d));
  ok(c.tlc_on(0.3));
  c.commit_all();
  ok(c.cs_on(CsFamily::acs, 1, CsValues{{1, 2, 3}, {0.5, -1, 2}}));
  ok(c.cs_on(CsFamily::cs, 1, CsValues{{10, 20, 30}, {15, 25, 35}}));
  ok(c.cs_on(CsFamily::cs, 2, CsValues{{-5, 0, 2}, {0, 30, 0}}));
  ok(c.rotation_on(17, 3, -4));
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-1000, 1000);
  for (int i = 0; i < 200; ++i) {
    PcsPoint p = pcs(u(rng), u(rng), u(rng), u(rng));
    expect_point(c.to_pcs(c.to_mcs(p)).pos_mm, p.pos_mm, 1e-9);
    for (std::uint8_t bits : {std::uint8_t{1}, std::uint8_t{16}, std::uint8_t{127}}) {
      SuppressMask m{bits};
      expect_point(c.to_pcs(c.to_mcs(p, m), m).pos_mm, p.pos_mm, 1e-9);
    }
  }
}

TEST(OffsetKinds, ActiveOffsetsListsKindsWithValues) {
  OffsetChain c = make_chain();
  ok(c.select_zero_offset(zero_table(), 1));
  ok(c.set_g92(0, 10, false));
  ok(c.cs_on(CsFamily::cs, 3, CsValues{{0, 0, 10}, {0, 0, 45}}));
  ok(c.rotation_on(30, 10, 5));
  c.commit_axis(0);
  ActiveOffsets a = c.active_offsets();
  ASSERT_EQ(a.size(), 4u);
  EXPECT_EQ(a[0].kind, OffsetKind::rotation);
  EXPECT_DOUBLE_EQ(a[0].angle_deg[2], 30);
  EXPECT_DOUBLE_EQ(a[0].values_mm[1], 5);  // CENTER2 on Y in G17
  EXPECT_EQ(a[1].kind, OffsetKind::cs);
  EXPECT_EQ(a[1].id, 3);
  EXPECT_DOUBLE_EQ(a[1].values_mm[2], 10);
  EXPECT_DOUBLE_EQ(a[1].angle_deg[2], 45);
  EXPECT_EQ(a[2].kind, OffsetKind::zero);
  EXPECT_EQ(a[2].id, 1);
  EXPECT_DOUBLE_EQ(a[2].values_mm[0], 10);  // X committed
  EXPECT_DOUBLE_EQ(a[2].values_mm[1], 0);   // Y still waits for G90 Y..
  EXPECT_EQ(a[2].pending_axes, 1u << 1);
  EXPECT_EQ(a[3].kind, OffsetKind::g92);
  EXPECT_EQ(to_string(a[3].kind), "g92");
}

}  // namespace
}  // namespace nck::frames::test
