// $GOTO N<expr> / $GOTO [NAME]: which blocks come out, in which order, and
// the errors (unknown label, into a loop, inside a loop, endless jumps).
#include "nc_test_util.hpp"

namespace nck::nc::test {
namespace {

std::vector<std::int64_t> ns(const Decoded& d) {
  std::vector<std::int64_t> r;
  for (const auto& b : d.blocks)
    if (b.n) r.push_back(*b.n);
  return r;
}

TEST(NcGoto, ForwardJumpSkipsBlocks) {
  auto d = decode("N10 X1\nN20 $GOTO N40\nN30 X3\nN40: X4\nN50 X5\nM30\n");
  EXPECT_EQ(ns(d), (std::vector<std::int64_t>{10, 40, 50})) << dump(d);
  EXPECT_EQ(d.errors(), 0u);
}

// TF5200: commands may stand before and after $GOTO; the jump comes last.
TEST(NcGoto, CommandsBesideTheJumpMakeTheBlock) {
  auto d = decode("N10 X1 $GOTO N30\nN20 X2\nN30: X3 $GOTO [E] Y5 (not $GOTO [F])\nX9\n[E] M30\n");
  EXPECT_EQ(xs(d), (std::vector<double>{1, 3})) << dump(d);
  EXPECT_EQ(ns(d), (std::vector<std::int64_t>{10, 30}));
  ASSERT_GE(d.blocks.size(), 2u);
  ASSERT_TRUE(d.blocks[1].axes[1]);
  EXPECT_DOUBLE_EQ(*d.blocks[1].axes[1], 5);
  EXPECT_EQ(d.errors(), 0u);
}

TEST(NcGoto, StringLabelAndLeadingZeros) {
  auto d = decode("X1\n$GOTO [Skip_it]\nX2\n[SKIP_IT] X3\n$GOTO N010\nX4\nN10: X5\nM30\n");
  EXPECT_EQ(xs(d), (std::vector<double>{1, 3, 5})) << dump(d);
}

TEST(NcGoto, BlockNumberWithoutColonIsNoLabel) {
  auto d = decode("$GOTO N40\nN40 X4\nM30\n");
  const Diagnostic* e = d.find(ErrorId::NcLabelNotFound);
  ASSERT_NE(e, nullptr) << dump(d);
  EXPECT_EQ(e->loc.line, 1u);
  EXPECT_NE(e->message.find("N40"), std::string::npos) << e->message;
  EXPECT_NE(e->message.find("prog.nc"), std::string::npos) << e->message;
}

TEST(NcGoto, BackwardLoopWithCounter) {
  auto d = decode("P1 = 0\nN10: X[P1]\nP1 = P1 + 1\n$IF P1 < 3 $GOTO N10\nN20 Y1\nM30\n");
  EXPECT_EQ(xs(d), (std::vector<double>{0, 1, 2})) << dump(d);
  EXPECT_EQ(ns(d), (std::vector<std::int64_t>{10, 10, 10, 20}));
  EXPECT_EQ(d.errors(), 0u);
}

TEST(NcGoto, IfGotoFalseFallsThroughWithoutEndif) {
  auto d = decode("P1 = 5\n$IF P1 < 3 $GOTO [END]\nX1\n[END] X2\nM30\n");
  EXPECT_EQ(xs(d), (std::vector<double>{1, 2})) << dump(d);
  EXPECT_EQ(d.errors(), 0u);
  // inside a skipped $IF branch the one-liner opens nothing
  auto e = decode("$IF 0\n$IF 1 $GOTO N5\nX9\n$ENDIF\nX1\nN5: X2\nM30\n");
  EXPECT_EQ(xs(e), (std::vector<double>{1, 2})) << dump(e);
}

TEST(NcGoto, ParametricTarget) {
  auto d = decode("P7 = 30\n$GOTO N[P7]\nN20: X2\nN30: X3\nM30\n");
  EXPECT_EQ(xs(d), (std::vector<double>{3})) << dump(d);
}

TEST(NcGoto, LeavesLoopsAndIfs) {
  auto d = decode("$FOR P1 = 0, 9\n  $IF P1 == 2\n    $GOTO N90\n  $ENDIF\n  X[P1]\n$ENDFOR\nN90: Y1\n"
                  "$WHILE 1\n$GOTO [OUT]\n$ENDWHILE\n[OUT] X7\nM30\n");
  EXPECT_EQ(xs(d), (std::vector<double>{0, 1, 7})) << dump(d);
  EXPECT_EQ(d.errors(), 0u);
}

TEST(NcGoto, IntoIfBodyRunsToItsEndif) {
  // into the true branch: $ELSE ends it; into the $ELSE branch: $ENDIF ends it
  auto d = decode("$GOTO N2\n$IF 0\nX1\nN2: X2\n$ELSE\nX3\n$ENDIF\n$GOTO N5\n$IF 1\nX4\n$ELSE\nN5: X5\n$ENDIF\nX6\nM30\n");
  EXPECT_EQ(xs(d), (std::vector<double>{2, 5, 6})) << dump(d);
  EXPECT_EQ(d.errors(), 0u);
}

TEST(NcGoto, JumpToLoopOpenerFromInsideRestartsIt) {
  auto d = decode("P1 = 0\nP2 = 0\nN10: $WHILE P1 < 2\nX[P1]\nP1 = P1 + 1\n$IF P2 == 0\nP2 = 1\nP1 = 0\n$GOTO N10\n"
                  "$ENDIF\n$ENDWHILE\nM30\n");
  EXPECT_EQ(xs(d), (std::vector<double>{0, 0, 1})) << dump(d);
  EXPECT_EQ(d.errors(), 0u);
}

TEST(NcGoto, IntoLoopIsAnError) {
  auto d = decode("X1\n$GOTO N5\n$WHILE P1 < 3\nN5: X2\n$ENDWHILE\nM30\n");
  const Diagnostic* e = d.find(ErrorId::NcGotoIntoBlock);
  ASSERT_NE(e, nullptr) << dump(d);
  EXPECT_EQ(e->loc.line, 2u);
  EXPECT_EQ(xs(d), std::vector<double>{1});
  auto b = decode("$FOR P1 = 0, 1\nN5: X2\n$ENDFOR\n$GOTO N5\nM30\n");  // backward into a loop
  ASSERT_NE(b.find(ErrorId::NcGotoIntoBlock), nullptr) << dump(b);
  EXPECT_EQ(b.find(ErrorId::NcGotoIntoBlock)->loc.line, 4u);
}

TEST(NcGoto, InsideLoopIsAnError) {
  auto d = decode("$WHILE 1\n$GOTO N5\nX1\nN5: X2\n$ENDWHILE\nM30\n");
  const Diagnostic* e = d.find(ErrorId::NcGotoInLoop);
  ASSERT_NE(e, nullptr) << dump(d);
  EXPECT_EQ(e->loc.line, 2u);
  EXPECT_TRUE(decode("P1=1\n$SWITCH P1\n$CASE 1\n$GOTO N5\n$CASE 2\nN5: X2\n$ENDSWITCH\nM30\n")
                  .has(ErrorId::NcGotoInLoop));
}

TEST(NcGoto, LabelOfAnotherLevelIsNotFound) {
  auto d = decode("%L SUB\nN50: X5\nM17\n%MAIN\nLL SUB\n$GOTO N50\nM30\n");
  const Diagnostic* e = d.find(ErrorId::NcLabelNotFound);
  ASSERT_NE(e, nullptr) << dump(d);
  EXPECT_EQ(e->loc.line, 6u);
  auto s = decode("%L SUB\n$GOTO N60\nM17\n%MAIN\nN60: X6\nLL SUB\nM30\n");
  ASSERT_NE(s.find(ErrorId::NcLabelNotFound), nullptr) << dump(s);
  EXPECT_EQ(s.find(ErrorId::NcLabelNotFound)->loc.line, 2u);
  // the same label in main and subroutine: each level jumps to its own
  auto t = decode("%L SUB\n$GOTO N1\nX8\nN1: X2\nM17\n%MAIN\nLL SUB\n$GOTO N1\nX9\nN1: X1\nM30\n");
  EXPECT_EQ(xs(t), (std::vector<double>{2, 1})) << dump(t);
  EXPECT_EQ(t.errors(), 0u) << dump(t);
}

TEST(NcGoto, SyntaxErrors) {
  auto d = decode("X1\n$GOTO 20\nM30\n");
  ASSERT_NE(d.find(ErrorId::NcGotoSyntax), nullptr) << dump(d);
  EXPECT_EQ(d.find(ErrorId::NcGotoSyntax)->loc.line, 2u);
  EXPECT_TRUE(decode("$GOTO N2.5\nM30\n").has(ErrorId::NcGotoSyntax));
  EXPECT_TRUE(decode("$GOTO [A\nM30\n").has(ErrorId::NcGotoSyntax));
  EXPECT_TRUE(decode("$IF 1 $GOTO N2 X1\nN2: M30\n").has(ErrorId::NcGotoSyntax));
  EXPECT_FALSE(decode("$GOTO N2\nN2: M30\n").has(ErrorId::NcUnsupported));
}

TEST(NcGoto, EndlessBackwardJumpHitsTheLoopBudget) {
  auto cfg = default_config();
  cfg.max_loop_iterations = 1000;
  auto d = decode("N10: X1\n$GOTO N10\nM30\n", cfg);
  ASSERT_TRUE(d.has(ErrorId::NcLoopLimit)) << dump(d);
  EXPECT_EQ(d.last, Decoder::Status::error);
  EXPECT_EQ(d.blocks.size(), 1001u);  // the first pass and 1000 jumps back
  auto e = decode("N10: $GOTO N10\n", cfg);  // no block at all: still ends
  EXPECT_TRUE(e.has(ErrorId::NcLoopLimit));
  // the budget is shared with $WHILE: 600 + 600 > 1000
  auto f = decode("P1=0\n$WHILE P1 < 600\nP1=P1+1\n$ENDWHILE\nP2=0\nN5: P2=P2+1\n$IF P2 < 600 $GOTO N5\nM30\n", cfg);
  EXPECT_TRUE(f.has(ErrorId::NcLoopLimit)) << dump(f);
}

TEST(NcGoto, ForwardJumpOverCommentAndLabelsInComments) {
  auto d = decode("$GOTO N3\n#COMMENT BEGIN\nN3: X9\n#COMMENT END\nX1\nN3: X3\nM30\n");
  EXPECT_EQ(xs(d), (std::vector<double>{3})) << dump(d);
}

}  // namespace
}  // namespace nck::nc::test
