// Block words, modal state and the G-code checks.
#include "nc_test_util.hpp"

namespace nck::nc::test {
namespace {

TEST(NcWords, LinearBlockWithAxesAndFeed) {
  auto d = decode("N10 G1 X10.5 Y-2 Z.5 F1000\nN20 X11 M30\n");
  ASSERT_EQ(d.blocks.size(), 2u) << dump(d);
  const Block& b = d.blocks[0];
  EXPECT_EQ(b.n, 10);
  EXPECT_EQ(b.line, 1u);
  EXPECT_EQ(b.modal.motion, Motion::linear);
  EXPECT_DOUBLE_EQ(*b.axes[0], 10.5);
  EXPECT_DOUBLE_EQ(*b.axes[1], -2.0);
  EXPECT_DOUBLE_EQ(*b.axes[2], 0.5);
  EXPECT_DOUBLE_EQ(*b.f, 1000);
  EXPECT_DOUBLE_EQ(b.modal.feed_mm_min, 1000);
  EXPECT_TRUE(d.blocks[1].program_end);
  EXPECT_EQ(d.blocks[1].line, 2u);
  EXPECT_EQ(d.blocks[1].modal.motion, Motion::linear);  // modal
  EXPECT_EQ(d.last, Decoder::Status::end);
  EXPECT_EQ(d.errors(), 0u) << dump(d);
}

TEST(NcWords, MultiLetterAxisNeedsEquals) {
  auto d = decode("G0 C1=45 X2=-3.5 X1\nM30\n");
  ASSERT_EQ(d.blocks.size(), 2u) << dump(d);
  EXPECT_DOUBLE_EQ(*d.blocks[0].axes[3], 45);
  EXPECT_DOUBLE_EQ(*d.blocks[0].axes[4], -3.5);
  EXPECT_DOUBLE_EQ(*d.blocks[0].axes[0], 1);
}

TEST(NcWords, UnknownMultiLetterNameIsAnError) {
  auto d = decode("G0 Q7=4\nM30\n");
  ASSERT_TRUE(d.has(ErrorId::NcUnknownWord)) << dump(d);
  EXPECT_EQ(d.find(ErrorId::NcUnknownWord)->loc.column, 4u);
}

TEST(NcWords, CommentsAreIgnored) {
  auto d = decode("N500 X10 (in-block (nested) comment) Y20 ; rest X99\nM30\n");
  ASSERT_EQ(d.blocks.size(), 2u) << dump(d);
  EXPECT_DOUBLE_EQ(*d.blocks[0].axes[0], 10);
  EXPECT_DOUBLE_EQ(*d.blocks[0].axes[1], 20);
  EXPECT_EQ(d.errors(), 0u);
}

TEST(NcWords, CommentBlockSkipsLines) {
  auto d = decode("#COMMENT BEGIN\nX1 garbage $$$\n#COMMENT END\nX5\nM30\n");
  ASSERT_EQ(d.blocks.size(), 2u) << dump(d);
  EXPECT_DOUBLE_EQ(*d.blocks[0].axes[0], 5);
}

TEST(NcWords, UnterminatedCommentBlockIsAnError) {
  auto d = decode("X1\n#COMMENT BEGIN\nX2\n");
  EXPECT_TRUE(d.has(ErrorId::NcCommentBlock)) << dump(d);
}

TEST(NcWords, BlockSkipLevels) {
  auto cfg = default_config();
  cfg.skip_mask = 0x1 | 0x10;  // /1 and /5 active
  auto d = decode("/ X1\n/1 X2\n/5 X3\n/2 X4\nX5\nM30\n", cfg);
  ASSERT_EQ(d.blocks.size(), 3u) << dump(d);
  EXPECT_DOUBLE_EQ(*d.blocks[0].axes[0], 4);
  EXPECT_DOUBLE_EQ(*d.blocks[1].axes[0], 5);
  auto all = decode("/ X1\n/10 X2\nM30\n");
  EXPECT_EQ(all.blocks.size(), 3u);
  auto bad = decode("/11 X1\n");
  EXPECT_TRUE(bad.has(ErrorId::NcBadSkipLevel));
}

TEST(NcWords, UnknownGCodeHasIdAndColumn) {
  auto d = decode("N10 G1 G15 X1\n");
  const Diagnostic* e = d.find(ErrorId::NcUnknownGCode);
  ASSERT_NE(e, nullptr) << dump(d);
  EXPECT_EQ(e->loc.line, 1u);
  EXPECT_EQ(e->loc.column, 8u);
  EXPECT_EQ(d.last, Decoder::Status::error);
}

TEST(NcWords, ModalGroupConflict) {
  auto d = decode("G0 G1 X1\n");
  EXPECT_TRUE(d.has(ErrorId::NcModalConflict)) << dump(d);
  EXPECT_TRUE(decode("G90 G91\n").has(ErrorId::NcModalConflict));
}

TEST(NcWords, RadiusWithCenterIs21024) {
  auto d = decode("G2 X10 Y0 R5 I5\n");
  ASSERT_TRUE(d.has(ErrorId::NcRadiusWithCenter)) << dump(d);
  EXPECT_EQ(number(ErrorId::NcRadiusWithCenter), 21024u);
  auto ok = decode("G2 X10 Y0 R5\nG3 X0 I-5 J0\nM30\n");
  ASSERT_EQ(ok.blocks.size(), 3u) << dump(ok);
  EXPECT_EQ(ok.blocks[0].modal.motion, Motion::cw);
  EXPECT_DOUBLE_EQ(*ok.blocks[0].r, 5);
  EXPECT_DOUBLE_EQ(ok.blocks[1].modal.r, 5);  // R modal
  EXPECT_EQ(ok.blocks[1].modal.motion, Motion::ccw);
  EXPECT_DOUBLE_EQ(*ok.blocks[1].ijk[0], -5);
}

// TF5200 (TwinCAT CNC programming manual) "Radius programming": R is modal,
// a circle without I/J/K or R takes the last R (tests/manual_programs/circle_radius.nc).
TEST(NcWords, CircleRadiusIsModal) {
  auto d = decode("G1 X0 Y0 F500\nG2 R=15\nX30\nG3 X60\nG2 X70 I5\nG1 X80\nG3 X90\nG2 X100 R-5\nX110\nM30\n");
  ASSERT_EQ(d.errors(), 0u) << dump(d);
  ASSERT_EQ(d.blocks.size(), 10u) << dump(d);
  EXPECT_DOUBLE_EQ(*d.blocks[1].r, 15);  // the block that programs it (no motion)
  EXPECT_DOUBLE_EQ(*d.blocks[2].r, 15);
  EXPECT_DOUBLE_EQ(*d.blocks[3].r, 15);
  EXPECT_FALSE(d.blocks[4].r.has_value());  // I/J/K: the centre, not the radius
  EXPECT_FALSE(d.blocks[5].r.has_value());  // G1
  EXPECT_DOUBLE_EQ(*d.blocks[6].r, 15);
  EXPECT_DOUBLE_EQ(*d.blocks[8].r, -5);
  EXPECT_FALSE(decode("G2 X10 Y0\nM30\n").blocks[0].r.has_value());  // no R yet: 930005 in preparation
}

TEST(NcWords, FeedBelongsToItsFeedMode) {
  // TF5200 G95 (docs/nc-language.md): G95 F1.5 then G94 X50 runs with the old G94 feed again.
  auto d = decode("G94 F500 X1\nG95 F1.5 X2\nG94 X50\nM30\n");
  ASSERT_EQ(d.blocks.size(), 4u) << dump(d);
  EXPECT_DOUBLE_EQ(d.blocks[1].modal.feed_mm_rev, 1.5);
  EXPECT_DOUBLE_EQ(d.blocks[1].modal.feed_mm_min, 500);
  EXPECT_EQ(d.blocks[2].modal.feed_mode, FeedMode::g94);
  EXPECT_DOUBLE_EQ(d.blocks[2].modal.feed_mm_min, 500);
  EXPECT_FALSE(d.blocks[2].f.has_value());
}

TEST(NcWords, ModalGroups) {
  auto d = decode("G18 G91 G95 G96 G41 G51 G70 G56 G161 S100\nG159=12 G17\nG53\nG52 G71 G40\nM30\n");
  ASSERT_EQ(d.blocks.size(), 5u) << dump(d);
  const auto& m = d.blocks[0].modal;
  EXPECT_EQ(m.plane, Plane::g18);
  EXPECT_FALSE(m.absolute);
  EXPECT_EQ(m.feed_mode, FeedMode::g95);
  EXPECT_EQ(m.speed_mode, SpeedMode::g96);
  EXPECT_DOUBLE_EQ(m.css_m_min, 100);
  EXPECT_EQ(m.radius_comp, RadiusComp::g41);
  EXPECT_TRUE(m.diameter);
  EXPECT_TRUE(m.inch);
  EXPECT_EQ(m.zero_offset, 3);
  EXPECT_TRUE(m.circle_center_absolute);
  EXPECT_EQ(d.blocks[1].modal.zero_offset, 12);
  EXPECT_EQ(d.blocks[1].modal.plane, Plane::g17);
  EXPECT_EQ(d.blocks[2].modal.zero_offset, 0);
  EXPECT_FALSE(d.blocks[3].modal.diameter);
}

TEST(NcWords, G159Range) {
  EXPECT_TRUE(decode("G159=97\n").has(ErrorId::NcZeroOffsetIndexTooLarge));
  EXPECT_TRUE(decode("G159=2.5\n").has(ErrorId::NcZeroOffsetIndexInvalid));
}

TEST(NcWords, NonModalGCodesAreListed) {
  auto d = decode("G74 X2 Y1\nG92 X10 Z30\nG100 X10 F500\nG101 X1\nG102 X0\nG201 X1\nG202\nM30\n");
  ASSERT_EQ(d.blocks.size(), 8u) << dump(d);
  EXPECT_EQ(d.blocks[0].g_nonmodal, GCodeSet{GCode::g74});
  EXPECT_DOUBLE_EQ(*d.blocks[0].axes[1], 1);
  EXPECT_EQ(d.blocks[1].g_nonmodal, GCodeSet{GCode::g92});
  EXPECT_TRUE(d.blocks[5].modal.manual_mode);
  EXPECT_FALSE(d.blocks[6].modal.manual_mode);
  EXPECT_TRUE(decode("G201\n").has(ErrorId::NcG201WithoutAxis));
}

TEST(NcWords, DwellForms) {
  auto d = decode("G4 X4.5\nG04 2.5\nG4 S10\n#TIME 1.25\nG18\nG4 X3\nM30\n");
  ASSERT_EQ(d.blocks.size(), 7u) << dump(d);
  EXPECT_DOUBLE_EQ(*d.blocks[0].dwell_s, 4.5);
  EXPECT_FALSE(d.blocks[0].has_axis_words());
  EXPECT_DOUBLE_EQ(*d.blocks[1].dwell_s, 2.5);
  EXPECT_DOUBLE_EQ(*d.blocks[2].dwell_revs, 10);
  EXPECT_DOUBLE_EQ(*d.blocks[3].dwell_s, 1.25);
  EXPECT_DOUBLE_EQ(*d.blocks[5].dwell_s, 3);  // G18: X, the channel's first axis, is still the first main axis
}

TEST(NcWords, DwellErrors) {
  EXPECT_TRUE(decode("G4 2 X3\n").has(ErrorId::NcDwellTwoValues));
  EXPECT_TRUE(decode("G4 X-1\n").has(ErrorId::NcDwellOutOfRange));
  EXPECT_TRUE(decode("G4 X1 M8\n").has(ErrorId::NcDwellNotAlone));
  EXPECT_TRUE(decode("#TIME -1\n").has(ErrorId::NcDwellOutOfRange));
  auto w = decode("G4 X1 Y2\nM30\n");
  EXPECT_TRUE(w.has(ErrorId::NcDwellExtraAxes));
  EXPECT_EQ(w.errors(), 0u);
  EXPECT_TRUE(decode("G4 Y2\n").has(ErrorId::NcDwellNotFirstAxis));      // TF5200 20014
  EXPECT_TRUE(decode("G18\nG4 Z2\n").has(ErrorId::NcDwellNotFirstAxis));  // in every plane
}

TEST(NcWords, MFunctionsAndStops) {
  auto cfg = default_config();
  auto d = decode("M0\nM1\nM8 M80 H5\nM30\n", cfg);
  ASSERT_EQ(d.blocks.size(), 4u) << dump(d);
  EXPECT_TRUE(d.blocks[0].stop);
  EXPECT_FALSE(d.blocks[1].stop);
  EXPECT_TRUE(d.blocks[1].optional_stop);  // M1: the kernel decides with the HLI switch
  EXPECT_EQ(d.blocks[2].m, (std::vector<int>{8, 80}));
  EXPECT_EQ(d.blocks[2].h, std::vector<int>{5});
  EXPECT_TRUE(decode("M-3\n").has(ErrorId::NcBadMFunction));
}

// TF5200 "M/H functions with additional information": M52=-345, a computed
// value, H as well; M30 may carry one; spindle M functions may not.
TEST(NcWords, MAndHFunctionsWithAdditionalValues) {
  auto d = decode("P2 = 345\nN10 M52=-345 M54 H10=P2\nN20 M63 = -P2 H7=[2*3]\nM30=1\n");
  ASSERT_EQ(d.blocks.size(), 3u) << dump(d);  // the assignment alone makes no block
  EXPECT_EQ(d.errors(), 0u) << dump(d);
  const Block& b = d.blocks[0];
  EXPECT_EQ(b.m, (std::vector<int>{52, 54}));
  EXPECT_EQ(value_of(b.m_values, 52), -345);
  EXPECT_EQ(value_of(b.m_values, 54), std::nullopt);
  EXPECT_EQ(value_of(b.h_values, 10), 345);
  EXPECT_EQ(value_of(d.blocks[1].m_values, 63), -345);
  EXPECT_EQ(value_of(d.blocks[1].h_values, 7), 6);
  EXPECT_TRUE(d.blocks[2].program_end);
  for (const char* spindle : {"M3=5\n", "M19=1\n", "M41=2\n", "S100 M5=0\n"})
    EXPECT_TRUE(decode(spindle).has(ErrorId::NcMValueNotAllowed)) << spindle;
  EXPECT_TRUE(decode("M52=1.5\n").has(ErrorId::NcBadMFunction));
}

TEST(NcWords, ToolWords) {
  auto d = decode("T5 D3\nM30\n");
  ASSERT_EQ(d.blocks.size(), 2u);
  EXPECT_EQ(d.blocks[0].t, 5);
  EXPECT_EQ(d.blocks[0].d, 3);
  EXPECT_EQ(d.blocks[1].modal.d, 3);
  EXPECT_TRUE(decode("D1.5\n").has(ErrorId::NcBadToolNumber));
  EXPECT_TRUE(decode("F-5\n").has(ErrorId::NcNegativeFeed));
  EXPECT_TRUE(decode("X1 X2\n").has(ErrorId::NcAxisTwice));
  EXPECT_TRUE(decode("F1 F2\n").has(ErrorId::NcDuplicateWord));
}

TEST(NcWords, ThreadAndTapping) {
  auto d = decode("G33 Z48 K1.5 S.OFFSET=180\nG0 X72\nG331 Z-20 K1.25 S500\nG332 Z5\nM30\n");
  ASSERT_EQ(d.blocks.size(), 5u) << dump(d);
  EXPECT_EQ(d.blocks[0].modal.motion, Motion::thread);
  EXPECT_DOUBLE_EQ(d.blocks[0].modal.thread_pitch_mm, 1.5);
  EXPECT_DOUBLE_EQ(*d.blocks[0].spindles.at(0).offset_deg, 180);
  EXPECT_DOUBLE_EQ(d.blocks[1].modal.thread_pitch_mm, 1.5);  // modal to program end
  EXPECT_DOUBLE_EQ(d.blocks[2].modal.tap_pitch_mm, 1.25);
  EXPECT_EQ(d.blocks[3].modal.motion, Motion::tap_retract);
  EXPECT_TRUE(decode("G33 Z10\n").has(ErrorId::NcThreadPitchZero));
  EXPECT_TRUE(decode("G33 Z10 K0\n").has(ErrorId::NcThreadPitchZero));
}

TEST(NcWords, G63Rules) {
  auto ok = decode("M5\nG63 Z-50 F300 S200\nZ100 S-200\nG1 X200 F3000\nM30\n");
  ASSERT_EQ(ok.errors(), 0u) << dump(ok);
  EXPECT_EQ(ok.blocks[2].modal.motion, Motion::tap);
  EXPECT_DOUBLE_EQ(*ok.blocks[2].spindles[0].rev_rpm, -200);
  EXPECT_EQ(number(ErrorId::NcTapSpeedZero), 20007u);
  EXPECT_TRUE(decode("G63 Z-50 F300 S0\n").has(ErrorId::NcTapSpeedZero));
  EXPECT_TRUE(decode("G95\nG63 Z-5 F1 S100\n").has(ErrorId::NcTapWithG95));
  EXPECT_TRUE(decode("G96 S100\nG63 Z-5 F1 S100\n").has(ErrorId::NcTapWithG96));
  EXPECT_TRUE(decode("G63 Z-5 F300 S100\nZ1 M3\n").has(ErrorId::NcTapSpindleM));
  EXPECT_TRUE(decode("S-100\n").has(ErrorId::NcNegativeSpeed));
}

TEST(NcWords, ConstantCuttingSpeed) {
  auto d = decode("G196 S2500\nG95 F1.5\nG96 S100\nG97 S800\nM30\n");
  ASSERT_EQ(d.blocks.size(), 5u) << dump(d);
  EXPECT_DOUBLE_EQ(d.blocks[0].modal.max_speed_rpm, 2500);
  EXPECT_TRUE(d.blocks[0].spindles.empty());
  EXPECT_DOUBLE_EQ(d.blocks[2].modal.css_m_min, 100);
  EXPECT_DOUBLE_EQ(*d.blocks[3].spindles[0].rev_rpm, 800);
  EXPECT_TRUE(decode("G196 S0\n").has(ErrorId::NcG196MaxNotPositive));
  EXPECT_TRUE(decode("G96 S0\n").has(ErrorId::NcCssZero));
}

TEST(NcWords, LowerCaseWords) {
  auto d = decode("g1 x1 y2 f100\nm30\n");
  ASSERT_EQ(d.blocks.size(), 2u) << dump(d);
  EXPECT_DOUBLE_EQ(*d.blocks[0].axes[1], 2);
}

}  // namespace
}  // namespace nck::nc::test
