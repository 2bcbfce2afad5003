// $IF / $WHILE / $FOR / $DO / $REPEAT / $SWITCH and their errors.
#include "nc_test_util.hpp"

namespace nck::nc::test {
namespace {

TEST(NcControlFlow, IfElseIfElse) {
  auto d = decode(
      "P1 = 2\n"
      "N010 $IF P1 == 1\nX1\n$ELSEIF P1 == 2\nX2\n  $IF 1 > 2\n  X99\n  $ELSE\n  X3\n  $ENDIF\n"
      "$ELSE\nX4\n$ENDIF\n"
      "$IF 0\nX5\n$ENDIF\n$IF TRUE\nX6\n$ELSE\nX7\n$ENDIF\nM30\n");
  EXPECT_EQ(xs(d), (std::vector<double>{2, 3, 6})) << dump(d);
  EXPECT_EQ(d.errors(), 0u);
}

TEST(NcControlFlow, SkippedBranchIsNotChecked) {
  auto d = decode("$IF 0\n garbage !!! G999\n$ENDIF\nX1\nM30\n");
  EXPECT_EQ(xs(d), std::vector<double>{1}) << dump(d);
}

TEST(NcControlFlow, WhileLoop) {
  auto d = decode("P1 = 0\n$WHILE P1 < 5\nX[P1]\nP1 = P1 + 1\n$ENDWHILE\nY1\nM30\n");
  EXPECT_EQ(xs(d), (std::vector<double>{0, 1, 2, 3, 4})) << dump(d);
  EXPECT_EQ(d.blocks.size(), 7u);
}

TEST(NcControlFlow, NestedLoopsAndFor) {
  auto d = decode("$FOR P1 = 1, 3, 1\n  $FOR P2 = 0, 1\n  X[P1 * 10 + P2]\n  $ENDFOR\n$ENDFOR\n"
                  "$FOR P3 = 3, 1, -1\nX[P3]\n$ENDFOR\nM30\n");
  EXPECT_EQ(xs(d), (std::vector<double>{10, 11, 20, 21, 30, 31, 3, 2, 1})) << dump(d);
}

TEST(NcControlFlow, ForWithVariableCounter) {
  auto d = decode("#VAR\nV.P.I = 0\n#ENDVAR\n$FOR V.P.I = 0, 4, 2\nX[V.P.I]\n$ENDFOR\nM30\n");
  EXPECT_EQ(xs(d), (std::vector<double>{0, 2, 4})) << dump(d);
}

TEST(NcControlFlow, DoLoop) {
  auto d = decode("P1 = 0\n$DO\nX[P1]\nP1 = P1 + 1\n$ENDDO P1 < 3\nM30\n");
  EXPECT_EQ(xs(d), (std::vector<double>{0, 1, 2})) << dump(d);
}

TEST(NcControlFlow, BreakAndContinue) {
  auto d = decode("$FOR P1 = 0, 10\n  $IF P1 == 1\n    $CONTINUE\n  $ENDIF\n  $IF P1 == 3\n    $BREAK\n  $ENDIF\n"
                  "  X[P1]\n$ENDFOR\nY1\nM30\n");
  EXPECT_EQ(xs(d), (std::vector<double>{0, 2})) << dump(d);
  EXPECT_EQ(d.errors(), 0u);
}

TEST(NcControlFlow, Switch) {
  std::string prog =
      "$SWITCH P1\n$CASE 0\nX0\n$BREAK\n$CASE 1\nX1\n$CASE 2\nX2\n$BREAK\n$DEFAULT\nX9\n$ENDSWITCH\nM30\n";
  EXPECT_EQ(xs(decode("P1=0\n" + prog)), std::vector<double>{0});
  EXPECT_EQ(xs(decode("P1=1\n" + prog)), (std::vector<double>{1, 2}));  // falls through
  EXPECT_EQ(xs(decode("P1=5\n" + prog)), std::vector<double>{9});
}

// TF5200 "The IF - ELSE branch": a condition is TRUE when |value| >= 0.5, so
// decimal values can be conditions (tests/manual_programs/if_else.nc).
TEST(NcControlFlow, ConditionsAreTrueFromOneHalf) {
  auto d = decode("P1 = 0.4\n$IF P1\nX1\n$ELSE\nX2\n$ENDIF\n$IF -0.5\nX3\n$ENDIF\n$IF 0.49 $GOTO N50\nX4\n"
                  "N50: P2 = 1.5\n$WHILE P2\nX[P2]\nP2 = P2 - 0.5\n$ENDWHILE\n"
                  "P3 = 0\n$DO\nP3 = P3 + 1\n$ENDDO 0.3\nX[P3 * 10]\nM30\n");
  EXPECT_EQ(xs(d), (std::vector<double>{2, 3, 4, 1.5, 1, 0.5, 10})) << dump(d);
  EXPECT_EQ(d.errors(), 0u);
}

// TF5200 "Verification of running condition at loop end ($DO), ($REPEAT)":
// $REPEAT ... $UNTIL c runs at least once and until c is TRUE.
TEST(NcControlFlow, RepeatUntil) {
  auto d = decode("P1 = 0\n$REPEAT\nX[P1]\nP1 = P1 + 1\n$UNTIL P1 >= 3\n"
                  "$REPEAT\nY1\n$UNTIL 1\n"
                  "P2 = 0\n$REPEAT\n  P2 = P2 + 1\n  $IF P2 == 2\n    $CONTINUE\n  $ENDIF\n  $IF P2 == 4\n    $BREAK\n"
                  "  $ENDIF\n  X[P2 * 10]\n$UNTIL P2 > 5\nM30\n");
  EXPECT_EQ(xs(d), (std::vector<double>{0, 1, 2, 10, 30})) << dump(d);
  EXPECT_EQ(d.errors(), 0u);
  EXPECT_TRUE(decode("$REPEAT\nX1\n$ENDDO 0\n").has(ErrorId::NcControlStructure));
  EXPECT_TRUE(decode("$DO\nX1\n$UNTIL 1\n").has(ErrorId::NcControlStructure));
  EXPECT_TRUE(decode("$UNTIL 1\n").has(ErrorId::NcControlStructure));
}

// TF5200 "Switch branching": "$SWITCH P1=INT[..]" assigns the value before
// switching on it; $CASE values match within 0.001.
TEST(NcControlFlow, SwitchAssignsItsValueAndMatchesWithinAThousandth) {
  auto d = decode("P1 = 3 P2 = 4 P3 = 2\n$SWITCH P1=INT [P1*P2/P3]\n$CASE 1\nX1\n$BREAK\n$CASE P2 + 2\nX6\n$BREAK\n"
                  "$DEFAULT\nX9\n$ENDSWITCH\nX[P1]\n"
                  "$SWITCH 4 / 3\n$CASE 1.33\nX13\n$BREAK\n$CASE 1.3335\nX14\n$BREAK\n$ENDSWITCH\n"
                  "$SWITCH P1 == 6\n$CASE 1\nX7\n$ENDSWITCH\nM30\n");
  EXPECT_EQ(xs(d), (std::vector<double>{6, 6, 14, 7})) << dump(d);
  EXPECT_EQ(d.errors(), 0u);
}

TEST(NcControlFlow, EndlessWhileHitsTheGuard) {
  auto cfg = default_config();
  cfg.max_loop_iterations = 1000;
  auto d = decode("$WHILE 1\n$ENDWHILE\nM30\n", cfg);
  EXPECT_TRUE(d.has(ErrorId::NcLoopLimit)) << dump(d);
  EXPECT_EQ(d.last, Decoder::Status::error);
  auto e = decode("$WHILE TRUE\nX1\n$ENDWHILE\n", cfg);
  EXPECT_TRUE(e.has(ErrorId::NcLoopLimit));
  EXPECT_EQ(e.blocks.size(), 1001u);
  EXPECT_TRUE(decode("$FOR P1 = 0, 1, 0\n$ENDFOR\n").has(ErrorId::NcLoopLimit));
}

TEST(NcControlFlow, StructureErrors) {
  EXPECT_TRUE(decode("$ENDIF\n").has(ErrorId::NcControlStructure));
  EXPECT_TRUE(decode("$ELSE\n").has(ErrorId::NcControlStructure));
  EXPECT_TRUE(decode("$ENDWHILE\n").has(ErrorId::NcControlStructure));
  EXPECT_TRUE(decode("$WHILE 1\n$ENDFOR\n").has(ErrorId::NcControlStructure));
  EXPECT_TRUE(decode("$IF 1\nX1\n").has(ErrorId::NcUnclosedControl));
  EXPECT_TRUE(decode("$IF 0\nX1\n").has(ErrorId::NcUnclosedControl));
  EXPECT_TRUE(decode("$BREAK\n").has(ErrorId::NcControlStructure));
  EXPECT_TRUE(decode("$FOO\n").has(ErrorId::NcUnknownControl));
  EXPECT_TRUE(decode("$GOTO N10\n").has(ErrorId::NcLabelNotFound));  // $GOTO runs now (goto_test.cpp)
  EXPECT_TRUE(decode("$IF 1 +\n").has(ErrorId::NcExprSyntax));
}

}  // namespace
}  // namespace nck::nc::test
