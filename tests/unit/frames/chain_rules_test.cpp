// Rules of the chain: G91 deferral, suppression, deselection, #MCS, errors.
#include <cmath>
#include <limits>

#include "chain_fixture.hpp"

namespace nck::frames::test {
namespace {

TEST(G91Rule, NewZeroOffsetWaitsForTheAxisAbsolutePosition) {
  OffsetChain c = make_chain();
  ok(c.select_zero_offset(zero_table(), 1));  // G54 X10 Y-5
  EXPECT_TRUE(c.is_pending(0));
  EXPECT_TRUE(c.is_pending(1));
  EXPECT_FALSE(c.is_pending(2));
  expect_point(c.to_mcs(pcs(0, 0, 0)).pos_mm, mcs(0, 0, 0).pos_mm);  // nothing moved yet
  c.commit_axis(0);                                                   // G90 X..
  expect_point(c.to_mcs(pcs(0, 0, 0)).pos_mm, mcs(10, 0, 0).pos_mm);
  EXPECT_EQ(c.pending_axes(), 1u << 1);
  c.commit_axis(1);
  expect_point(c.to_mcs(pcs(0, 0, 0)).pos_mm, mcs(10, -5, 0).pos_mm);
  EXPECT_EQ(c.pending_axes(), 0u);
}

TEST(G91Rule, G92DoesNotMoveUnderG91) {
  // TF5200 G92 (docs/coordinate-systems.md, G91 rule): G92 X10, then G0 X0 G91 does not move X.
  OffsetChain c = make_chain();
  ok(c.set_g92(0, 10, false));
  expect_point(c.to_mcs(pcs(0, 0, 0)).pos_mm, mcs(0, 0, 0).pos_mm);
  c.commit_axis(0);
  expect_point(c.to_mcs(pcs(0, 0, 0)).pos_mm, mcs(10, 0, 0).pos_mm);
}

TEST(G91Rule, PsetMeasureTlcAreDeferredManualIsNot) {
  OffsetChain c = make_chain();
  ok(c.pset(0, 20, mcs(50, 0, 0)));
  ok(c.measure_apply(1, 1, 3, 1));
  ok(c.tlc_on(15));
  ok(c.set_manual_offset(3, 1));
  EXPECT_EQ(c.pending_axes(), (1u << 0) | (1u << 1) | (1u << 2));
  expect_point(c.to_mcs(pcs(0, 0, 0)).pos_mm, mcs(0, 0, 0, 1).pos_mm);
}

TEST(G91Rule, ToolOffsetsPerMoveToolOffsetsDirectly) {
  ToolOffsets d5{5, 60, {}, false};
  OffsetChain deferred = make_chain(false);  // P-CHAN-00100 = 0 (default)
  ok(deferred.select_tool(d5));
  EXPECT_TRUE(deferred.is_pending(2));
  expect_point(deferred.to_mcs(pcs(0, 0, 0)).pos_mm, mcs(0, 0, 0).pos_mm);
  OffsetChain direct = make_chain(true);  // P-CHAN-00100 = 1: moves with D
  ok(direct.select_tool(d5));
  EXPECT_FALSE(direct.is_pending(2));
  expect_point(direct.to_mcs(pcs(0, 0, 0)).pos_mm, mcs(0, 0, 60).pos_mm);
  // Not under a kinematic transformation (P-CHAN-00100 remark).
  OffsetChain trafo = make_chain(true);
  trafo.set_rtcp_active(true);
  ok(trafo.select_tool(d5));
  EXPECT_TRUE(trafo.is_pending(2));
}

TEST(Suppress, EachOptionRemovesOnlyItsKind) {
  OffsetChain c = make_chain();
  AxisValues clamp{};
  clamp[0] = 1000;
  ok(c.set_clamp_offsets(clamp));
  ok(c.select_zero_offset(zero_table(), 1));  // X10
  ok(c.set_g92(0, 100, false));
  ok(c.pset(0, 0, mcs(-10000, 0, 0)));  // pset X = -10000 - 0 = -10000 (nothing committed yet)
  ok(c.measure_apply(0, 1, 1, 0));      // X1
  ok(c.set_manual_offset(0, 0.1));
  ToolOffsets d{1, 0, {}, false};
  d.axis_offset_mm[0] = 0.01;
  ok(c.select_tool(d));
  c.commit_all();
  ok(c.cs_on(CsFamily::cs, 1, CsValues{{100000, 0, 0}, {}}));
  const double all = 1000 + 10 + 100 - 11000 + 1 + 0.1 + 0.01 + 100000;
  struct Row {
    std::uint8_t bits;
    double removed;
  };
  const Row rows[] = {{SuppressMask::kZero, 10},      {SuppressMask::kAddZero, 100},
                      {SuppressMask::kPset, -11000},  {SuppressMask::kClamp, 1000},
                      {SuppressMask::kTool, 0.01},    {SuppressMask::kMeasure, 1},
                      {SuppressMask::kManual, 0.1},   {0, 0}};
  EXPECT_NEAR(c.to_mcs(pcs(0, 0, 0)).pos_mm[0], all, 1e-9);
  for (const Row& r : rows)
    EXPECT_NEAR(c.to_mcs(pcs(0, 0, 0), SuppressMask{r.bits}).pos_mm[0], all - r.removed, 1e-9)
        << int(r.bits);
  // Without options everything goes except the CS.
  EXPECT_NEAR(c.to_mcs(pcs(0, 0, 0), SuppressMask::all()).pos_mm[0], 100000, 1e-9);
}

TEST(Suppress, CsAcsRotationAreNeverSuppressed) {
  OffsetChain c = make_chain();
  ok(c.rotation_on(90));
  ok(c.cs_on(CsFamily::cs, 1, CsValues{{5, 0, 0}, {}}));
  ok(c.cs_on(CsFamily::acs, 1, CsValues{{0, 7, 0}, {}}));
  expect_point(c.to_mcs(pcs(1, 0, 0), SuppressMask::all()).pos_mm, mcs(5, 8, 0).pos_mm);
}

TEST(Suppress, NotAllowedUnderG91) {
  fails_with(OffsetChain::check_suppress(true), ErrorId::FrSuppressInG91);
  EXPECT_EQ(number(ErrorId::FrSuppressInG91), 20985u);
  ok(OffsetChain::check_suppress(false));
}

TEST(Rotation, PlaneChangeSwitchesRotationOffWithWarning21143) {
  OffsetChain c = make_chain();
  EXPECT_FALSE(c.set_plane(Plane::g18).has_value());  // nothing to switch off
  ok(c.rotation_on(30));
  EXPECT_FALSE(c.set_plane(Plane::g18).has_value());  // same plane: no change
  auto w = c.set_plane(Plane::g19);
  ASSERT_TRUE(w.has_value());
  EXPECT_EQ(number(w->id), 21143u);
  EXPECT_EQ(to_diagnostic(*w, {"p.nc", 7, 0}).severity, Severity::warning);
  expect_point(c.to_mcs(pcs(1, 2, 3)).pos_mm, mcs(1, 2, 3).pos_mm);
  EXPECT_EQ(c.active_offsets().size(), 0u);
}

TEST(Deselect, ZeroAndG92ProgrammedInsideCsAreDroppedAtOff) {
  OffsetChain c = make_chain();
  ZeroOffsetTable t = zero_table();
  ok(c.set_g92(2, 1, false));
  c.commit_all();
  ok(c.cs_on(CsFamily::cs, 1, CsValues{{0, 0, 0}, {0, 0, 90}}));
  ok(c.select_zero_offset(t, 1));
  ok(c.set_g92(2, 50, false));
  c.commit_all();
  EXPECT_EQ(c.zero_index(), 1);
  ok(c.cs_off(CsFamily::cs));
  EXPECT_EQ(c.zero_index(), 0);
  expect_point(c.to_mcs(pcs(0, 0, 0)).pos_mm, mcs(0, 0, 1).pos_mm);
}

TEST(Deselect, NestedCsRestoresLevelByLevelAndOffAllToTheBottom) {
  OffsetChain c = make_chain();
  ok(c.cs_on(CsFamily::cs, 1, CsValues{}));
  ok(c.set_g92(0, 1, false));
  c.commit_all();
  ok(c.cs_on(CsFamily::cs, 2, CsValues{}));
  ok(c.set_g92(0, 2, false));
  c.commit_all();
  ok(c.cs_off(CsFamily::cs));  // back to the value set inside CS 1
  EXPECT_NEAR(c.to_mcs(pcs(0, 0, 0)).pos_mm[0], 1, 1e-12);
  ok(c.cs_on(CsFamily::cs, 2, CsValues{}));
  ok(c.set_g92(0, 3, false));
  c.commit_all();
  ok(c.cs_off_all(CsFamily::cs));  // back to before CS 1
  EXPECT_NEAR(c.to_mcs(pcs(0, 0, 0)).pos_mm[0], 0, 1e-12);
  EXPECT_EQ(c.cs_store(CsFamily::cs).depth(), 0u);
}

TEST(Deselect, AcsHasItsOwnScope) {
  OffsetChain c = make_chain();
  ok(c.cs_on(CsFamily::acs, 1, CsValues{}));
  ok(c.set_g92(1, 4, false));
  c.commit_all();
  ok(c.cs_off(CsFamily::acs));
  EXPECT_NEAR(c.to_mcs(pcs(0, 0, 0)).pos_mm[1], 0, 1e-12);
}

TEST(CsStack, DefinitionsIdsAndLimits) {
  OffsetChain c = make_chain();
  for (int id = 1; id <= 5; ++id) ok(c.cs_define(CsFamily::cs, id, CsValues{{double(id), 0, 0}, {}}));
  fails_with(c.cs_define(CsFamily::cs, 6, CsValues{}), ErrorId::FrTooManyCsDefinitions);
  ok(c.cs_define(CsFamily::cs, 3, CsValues{{30, 0, 0}, {}}));  // redefinition is fine
  fails_with(c.cs_on(CsFamily::cs, 9, std::nullopt), ErrorId::FrUnknownCsId);
  fails_with(c.cs_on(CsFamily::cs, 0, std::nullopt), ErrorId::FrCsIdInvalid);
  ok(c.cs_on(CsFamily::cs, 3, std::nullopt));
  expect_point(c.to_mcs(pcs(0, 0, 0)).pos_mm, mcs(30, 0, 0).pos_mm);
  // #CS ON without an id activates the one defined last (3 again, nested).
  ok(c.cs_on(CsFamily::cs, std::nullopt, std::nullopt));
  expect_point(c.to_mcs(pcs(0, 0, 0)).pos_mm, mcs(60, 0, 0).pos_mm);
  for (int i = 0; i < 3; ++i) ok(c.cs_on(CsFamily::cs, 1, std::nullopt));
  fails_with(c.cs_on(CsFamily::cs, 1, std::nullopt), ErrorId::FrCsNestingTooDeep);
}

TEST(CsStack, OnWithoutAnythingDefinedIsUnknown) {
  OffsetChain c = make_chain();
  fails_with(c.cs_on(CsFamily::cs, std::nullopt, std::nullopt), ErrorId::FrUnknownCsId);
  fails_with(c.cs_off(CsFamily::cs), ErrorId::FrCsOffWithoutCs);
  EXPECT_EQ(find_error(ErrorId::FrCsOffWithoutCs)->severity, Severity::warning);
}

TEST(CsStack, CsWithoutIdIsGoneAfterOff) {
  OffsetChain c = make_chain();
  ok(c.cs_on(CsFamily::cs, std::nullopt, CsValues{{1, 0, 0}, {}}));
  EXPECT_EQ(c.cs_store(CsFamily::cs).definition_count(), 1u);
  EXPECT_EQ(c.cs_store(CsFamily::cs).active(0).id, 1);  // next free id
  ok(c.cs_off(CsFamily::cs));
  EXPECT_EQ(c.cs_store(CsFamily::cs).definition_count(), 0u);
}

TEST(CsStack, AddAndSelect) {
  // TF5200 #CS ADD example: #CS ADD [ICS][10,10,0,0,0,45], #CS ADD [WCS][15,20,0,0,0,0].
  OffsetChain c = make_chain();
  ok(c.cs_add("ICS", CsValues{{10, 10, 0}, {0, 0, 45}}));
  ok(c.cs_add("WCS", CsValues{{15, 20, 0}, {}}));
  const double s = 0.70710678118654752;
  ok(c.cs_select("WCS"));
  expect_point(c.to_mcs(pcs(0, 0, 0)).pos_mm, mcs(10 + (15 - 20) * s, 10 + (15 + 20) * s, 0).pos_mm);
  ok(c.cs_select("ics"));
  expect_point(c.to_mcs(pcs(0, 0, 0)).pos_mm, mcs(10, 10, 0).pos_mm);
  ok(c.cs_select("MCS"));
  expect_point(c.to_mcs(pcs(0, 0, 0)).pos_mm, mcs(0, 0, 0).pos_mm);
  fails_with(c.cs_select("NOPE"), ErrorId::FrUnknownCsName);
  fails_with(c.cs_add("ACS", CsValues{}), ErrorId::FrCsNameInvalid);
  fails_with(c.cs_add("TOOLONGNAME", CsValues{}), ErrorId::FrCsNameInvalid);
}

TEST(CsStack, CsModeChangesLaterDefinitionsOnly) {
  OffsetChain c = make_chain();
  auto mode = parse_cs_mode("ROTATION_MODE_FIXED");
  ASSERT_TRUE(mode.has_value());
  c.cs_mode_on(*mode);
  EXPECT_EQ(c.cs_convention().mode, RotationMode::extrinsic);
  ok(c.cs_on(CsFamily::cs, 1, CsValues{{}, {0, 90, 90}}));
  // Extrinsic ZYX: Ry(90)*Rz(90); the CS X axis maps to parent Y.
  expect_point(c.to_mcs(pcs(1, 0, 0)).pos_mm, mcs(0, 1, 0).pos_mm);
  c.cs_mode_off();
  EXPECT_EQ(c.cs_convention().mode, RotationMode::intrinsic);
  auto seq = parse_cs_mode("ROTATION_SEQUENCE=XYZ");
  ASSERT_TRUE(seq.has_value());
  EXPECT_EQ(seq->sequence, RotationSequence::xyz);
  EXPECT_FALSE(parse_cs_mode("ROTATION_SEQUENCE=ABC").has_value());
  EXPECT_FALSE(parse_cs_mode("").has_value());
}

TEST(Ecs, NotWithAnotherCs20774) {
  OffsetChain c = make_chain();
  ok(c.cs_on(CsFamily::cs, 1, CsValues{}));
  fails_with(c.ecs_on(), ErrorId::FrEcsWithOtherCs);
  EXPECT_EQ(number(ErrorId::FrEcsWithOtherCs), 20774u);
  ok(c.cs_off(CsFamily::cs));
  ok(c.cs_on(CsFamily::acs, 1, CsValues{}));
  fails_with(c.ecs_on(), ErrorId::FrEcsWithOtherCs);
  ok(c.cs_off(CsFamily::acs));
  ok(c.ecs_on());
  ok(c.ecs_off());
  fails_with(c.ecs_off(), ErrorId::FrCsOffWithoutCs);
}

TEST(Mcs, AllOffsetsOffInsideAndRestoredAtOff) {
  OffsetChain c = make_chain();
  ok(c.select_zero_offset(zero_table(), 1));
  ok(c.select_tool(ToolOffsets{5, 60, {}, false}));
  c.commit_all();
  ok(c.cs_on(CsFamily::cs, 1, CsValues{{1, 2, 3}, {0, 0, 30}}));
  ok(c.rotation_on(10));
  const McsPoint before = c.to_mcs(pcs(4, 5, 6));
  ok(c.mcs_on(false));
  expect_point(c.to_mcs(pcs(4, 5, 6)).pos_mm, mcs(4, 5, 6).pos_mm);
  EXPECT_EQ(c.active_offsets().size(), 0u);
  ok(c.set_g92(0, 9, false));  // temporary
  c.commit_all();
  expect_point(c.to_mcs(pcs(0, 0, 0)).pos_mm, mcs(9, 0, 0).pos_mm);
  fails_with(c.cs_on(CsFamily::cs, 1, std::nullopt), ErrorId::FrNotAllowedInMcs);
  fails_with(c.cs_on(CsFamily::acs, 1, CsValues{}), ErrorId::FrNotAllowedInMcs);
  fails_with(c.ecs_on(), ErrorId::FrNotAllowedInMcs);
  fails_with(c.tlc_on(1), ErrorId::FrNotAllowedInMcs);
  fails_with(c.mcs_on(false), ErrorId::FrMcsAlreadyActive);
  ok(c.mcs_off());
  expect_point(c.to_mcs(pcs(4, 5, 6)).pos_mm, before.pos_mm);
  EXPECT_EQ(c.cs_store(CsFamily::cs).depth(), 1u);
  fails_with(c.mcs_off(), ErrorId::FrCsOffWithoutCs);
}

TEST(Mcs, ToolChangeInsideActsUnlessExTool) {
  OffsetChain plain = make_chain(true);
  ok(plain.mcs_on(false));
  ok(plain.select_tool(ToolOffsets{2, 40, {}, false}));
  expect_point(plain.to_mcs(pcs(0, 0, 0)).pos_mm, mcs(0, 0, 40).pos_mm);
  ok(plain.mcs_off());
  expect_point(plain.to_mcs(pcs(0, 0, 0)).pos_mm, mcs(0, 0, 40).pos_mm);

  OffsetChain ex = make_chain(true);
  ok(ex.mcs_on(true));
  ok(ex.select_tool(ToolOffsets{2, 40, {}, false}));
  expect_point(ex.to_mcs(pcs(0, 0, 0)).pos_mm, mcs(0, 0, 0).pos_mm);
  ok(ex.mcs_off());  // only now the tool offsets count again
  expect_point(ex.to_mcs(pcs(0, 0, 0)).pos_mm, mcs(0, 0, 40).pos_mm);
}

TEST(Errors, TrcBlocksCsChangesAndTlc) {
  OffsetChain c = make_chain();
  ok(c.cs_define(CsFamily::cs, 1, CsValues{}));
  c.set_trc_active(true);
  fails_with(c.cs_on(CsFamily::cs, 1, std::nullopt), ErrorId::FrCsChangeWithTrc);
  fails_with(c.mcs_on(false), ErrorId::FrCsChangeWithTrc);
  fails_with(c.tlc_on(1), ErrorId::FrTlcWithTrc);
  EXPECT_EQ(number(ErrorId::FrCsChangeWithTrc), 20802u);
  EXPECT_EQ(number(ErrorId::FrTlcWithTrc), 20671u);
  c.set_trc_active(false);
  c.set_rtcp_active(true);
  fails_with(c.tlc_on(1), ErrorId::FrTlcWithRtcp);
  EXPECT_EQ(number(ErrorId::FrTlcWithRtcp), 20669u);
}

TEST(Errors, ZeroOffsetIndexAndBadInput) {
  OffsetChain c = make_chain();
  ZeroOffsetTable t = zero_table();  // 97 groups: 0..96
  ok(c.select_zero_offset(t, 96));
  fails_with(c.select_zero_offset(t, 97), ErrorId::NcZeroOffsetIndexTooLarge);
  fails_with(c.select_zero_offset(t, -1), ErrorId::NcZeroOffsetIndexInvalid);
  EXPECT_EQ(number(ErrorId::NcZeroOffsetIndexTooLarge), 20149u);
  fails_with(c.set_g92(4, 1, false), ErrorId::FrAxisOutOfRange);  // 4 axes: 0..3
  fails_with(c.set_g92(-1, 1, false), ErrorId::FrAxisOutOfRange);
  fails_with(c.set_g92(0, std::nan(""), false), ErrorId::FrValueNotFinite);
  fails_with(c.rotation_on(std::numeric_limits<double>::infinity()), ErrorId::FrValueNotFinite);
  fails_with(c.cs_on(CsFamily::cs, 1, CsValues{{std::nan(""), 0, 0}, {}}), ErrorId::FrValueNotFinite);
  fails_with(c.measure_apply(0, 1, std::nullopt, 10), ErrorId::FrNothingMeasured);
  Diagnostic d = to_diagnostic(FrameError{ErrorId::FrAxisOutOfRange, 4}, {"a.nc", 3, 5});
  EXPECT_NE(format(d).find("970007"), std::string::npos);
  EXPECT_NE(format(d).find("axis index 4"), std::string::npos);
}

TEST(Reset, ProgramStartClearsEverything) {
  OffsetChain c = make_chain();
  ok(c.cs_on(CsFamily::cs, 1, CsValues{{1, 0, 0}, {}}));
  ok(c.set_manual_offset(0, 2));
  ok(c.mcs_on(false));
  c.reset();
  EXPECT_FALSE(c.mcs_active());
  expect_point(c.to_mcs(pcs(1, 2, 3)).pos_mm, mcs(1, 2, 3).pos_mm);
  EXPECT_EQ(c.active_offsets().size(), 0u);
}

}  // namespace
}  // namespace nck::frames::test
