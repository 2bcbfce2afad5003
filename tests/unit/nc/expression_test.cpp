// Expressions in [ ]: operators, functions (degrees), errors with position.
#include <cmath>

#include "nc_test_util.hpp"

namespace nck::nc::test {
namespace {

double x_of(const std::string& value_expr) {
  auto d = decode("X" + value_expr + "\nM30\n");
  EXPECT_EQ(d.errors(), 0u) << value_expr << "\n" << dump(d);
  if (d.blocks.empty() || !d.blocks[0].axes[0]) return NAN;
  return *d.blocks[0].axes[0];
}

TEST(NcExpression, Arithmetic) {
  EXPECT_DOUBLE_EQ(x_of("[1+2*3]"), 7);
  EXPECT_DOUBLE_EQ(x_of("[[1+2]*3]"), 9);
  EXPECT_DOUBLE_EQ(x_of("[10/4]"), 2.5);
  EXPECT_DOUBLE_EQ(x_of("[-2*-3]"), 6);
  EXPECT_DOUBLE_EQ(x_of("-[2+3]"), -5);
  EXPECT_DOUBLE_EQ(x_of("[ 2 ** 10 ]"), 1024);
  EXPECT_DOUBLE_EQ(x_of("[7 MOD 3]"), 1);
  EXPECT_DOUBLE_EQ(x_of("[1 - 2 - 3]"), -4);  // left associative
  EXPECT_DOUBLE_EQ(x_of("[8 / 2 / 2]"), 2);
}

TEST(NcExpression, FunctionsUseDegrees) {
  EXPECT_NEAR(x_of("[SIN[30]]"), 0.5, 1e-12);
  EXPECT_NEAR(x_of("[COS[60]]"), 0.5, 1e-12);
  EXPECT_NEAR(x_of("[TAN[45]]"), 1.0, 1e-12);
  EXPECT_NEAR(x_of("[ASIN[0.5]]"), 30.0, 1e-12);
  EXPECT_NEAR(x_of("[ACOS[0]]"), 90.0, 1e-12);
  EXPECT_NEAR(x_of("[ATAN[1]]"), 45.0, 1e-12);
  EXPECT_NEAR(x_of("[ATAN2[1, -1]]"), 135.0, 1e-12);
  EXPECT_DOUBLE_EQ(x_of("[SQRT[16]]"), 4);
  EXPECT_DOUBLE_EQ(x_of("[SQR[3]]"), 9);
  EXPECT_DOUBLE_EQ(x_of("[ABS[-2.5]]"), 2.5);
  EXPECT_DOUBLE_EQ(x_of("[INT[-2.7]]"), -2);
  EXPECT_NEAR(x_of("[FRACT[2.75]]"), 0.75, 1e-12);
  EXPECT_DOUBLE_EQ(x_of("[ROUND[2.5]]"), 3);
  EXPECT_NEAR(x_of("[EXP[1]]"), std::exp(1.0), 1e-12);
  EXPECT_NEAR(x_of("[LN[EXP[2]]]"), 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(x_of("[POW[2,3]]"), 8);
  EXPECT_DOUBLE_EQ(x_of("[MOD[10,4]]"), 2);
  EXPECT_DOUBLE_EQ(x_of("[MIN[3,4] + MAX[3,4]]"), 7);
}

TEST(NcExpression, ComparisonAndLogic) {
  EXPECT_DOUBLE_EQ(x_of("[1 < 2]"), 1);
  EXPECT_DOUBLE_EQ(x_of("[2 <= 1]"), 0);
  EXPECT_DOUBLE_EQ(x_of("[3 == 3]"), 1);
  EXPECT_DOUBLE_EQ(x_of("[3 != 3]"), 0);
  EXPECT_DOUBLE_EQ(x_of("[3 <> 4]"), 1);
  EXPECT_DOUBLE_EQ(x_of("[1 < 2 && 2 > 3]"), 0);
  EXPECT_DOUBLE_EQ(x_of("[1 < 2 || 2 > 3]"), 1);
  EXPECT_DOUBLE_EQ(x_of("[!0]"), 1);
  EXPECT_DOUBLE_EQ(x_of("[NOT 1 OR 1 AND 0]"), 0);
  EXPECT_DOUBLE_EQ(x_of("[TRUE AND NOT FALSE]"), 1);
  EXPECT_DOUBLE_EQ(x_of("[0.1 + 0.2 == 0.3]"), 1);  // tolerant equality
}

TEST(NcExpression, DivisionByZeroHasLineAndColumn) {
  auto d = decode("X1\nN20 X[10 / [2 - 2]]\n");
  const Diagnostic* e = d.find(ErrorId::NcDivisionByZero);
  ASSERT_NE(e, nullptr) << dump(d);
  EXPECT_EQ(e->loc.line, 2u);
  EXPECT_EQ(e->loc.column, 10u);
  EXPECT_EQ(d.blocks.size(), 1u);  // the bad block never leaves the decoder
}

TEST(NcExpression, Errors) {
  EXPECT_TRUE(decode("X[1 + 2\n").has(ErrorId::NcExprSyntax));
  EXPECT_TRUE(decode("X[1 + ]\n").has(ErrorId::NcExprSyntax));
  EXPECT_TRUE(decode("X[FOO[1]]\n").has(ErrorId::NcUnknownFunction));
  EXPECT_TRUE(decode("X[SQRT[-1]]\n").has(ErrorId::NcMathDomain));
  EXPECT_TRUE(decode("X[ASIN[2]]\n").has(ErrorId::NcMathDomain));
  EXPECT_TRUE(decode("X[LN[0]]\n").has(ErrorId::NcMathDomain));
  EXPECT_TRUE(decode("X[5 MOD 0]\n").has(ErrorId::NcDivisionByZero));
  EXPECT_TRUE(decode("XP7\n").has(ErrorId::NcUndefinedVariable));
  EXPECT_TRUE(decode("X[V.L.NOPE]\n").has(ErrorId::NcUndefinedVariable));
  EXPECT_TRUE(decode("X" + std::string(200, '[') + "1" + std::string(200, ']') + "\n").has(ErrorId::NcExprTooDeep));
}

}  // namespace
}  // namespace nck::nc::test
