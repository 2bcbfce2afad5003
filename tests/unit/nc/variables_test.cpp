// P parameters, #VAR program variables and the kernel variables.
#include "nc_test_util.hpp"

namespace nck::nc::test {
namespace {

TEST(NcVariables, PParameters) {
  auto d = decode("P1 = 10\nP2 = P1 * 2\nP[3] = P2 + 1\nX[P1 + P2] YP3 Z-P1\nM30\n");
  ASSERT_EQ(d.blocks.size(), 2u) << dump(d);
  EXPECT_DOUBLE_EQ(*d.blocks[0].axes[0], 30);
  EXPECT_DOUBLE_EQ(*d.blocks[0].axes[1], 21);
  EXPECT_DOUBLE_EQ(*d.blocks[0].axes[2], -10);
  EXPECT_EQ(d.blocks[0].line, 4u);
}

TEST(NcVariables, AssignmentTakesEffectAfterTheBlock) {
  auto d = decode("P1 = 1\nP1 = 5 X[P1]\nX[P1]\nM30\n");
  ASSERT_EQ(d.blocks.size(), 3u) << dump(d);
  EXPECT_DOUBLE_EQ(*d.blocks[0].axes[0], 1);
  EXPECT_DOUBLE_EQ(*d.blocks[1].axes[0], 5);
}

TEST(NcVariables, VarDeclarations) {
  auto d = decode(
      "%main\n#VAR\n  V.P.VAR_2 = 10.67\n  V.L.CNT : UNS32 = 3 ; comment\n"
      "  V.L.NAME : STRING[20] = \"PLATE\"\n  V.P.ARR[2][3] = [10,11,12, \\\n 20,21,22]\n"
      "  V.L.FLAG : BOOLEAN\n#ENDVAR\n"
      "X[V.P.VAR_2] Y[V.L.CNT] Z[V.P.ARR[1][2]] C1=V.L.FLAG\n"
      "V.L.CNT = V.L.CNT + 1\nX[V.L.CNT]\nM30\n");
  ASSERT_EQ(d.blocks.size(), 3u) << dump(d);
  EXPECT_DOUBLE_EQ(*d.blocks[0].axes[0], 10.67);
  EXPECT_DOUBLE_EQ(*d.blocks[0].axes[1], 3);
  EXPECT_DOUBLE_EQ(*d.blocks[0].axes[2], 22);
  EXPECT_DOUBLE_EQ(*d.blocks[0].axes[3], 0);
  EXPECT_DOUBLE_EQ(*d.blocks[1].axes[0], 4);
}

TEST(NcVariables, DeclarationErrors) {
  EXPECT_TRUE(decode("V.L.X = 5\n").has(ErrorId::NcVarDeclaration));
  EXPECT_TRUE(decode("#VAR\nV.P.A[2] = [1,2,3]\n#ENDVAR\n").has(ErrorId::NcIndexOutOfRange));
  EXPECT_TRUE(decode("#VAR\nV.P.A[2]\n#ENDVAR\nX[V.P.A[2]]\n").has(ErrorId::NcIndexOutOfRange));
  EXPECT_TRUE(decode("#VAR\nV.P.S : STRING = \"a\"\n#ENDVAR\nX[V.P.S]\n").has(ErrorId::NcTypeMismatch));
  EXPECT_TRUE(decode("#VAR\nV.P.S : WEIRD\n#ENDVAR\n").has(ErrorId::NcVarDeclaration));
  EXPECT_TRUE(decode("#VAR\nV.P.S = 1\n").has(ErrorId::NcVarDeclaration));  // never closed
  EXPECT_TRUE(decode("V.L.X\n").has(ErrorId::NcVariableWithoutAssignment));
  EXPECT_TRUE(decode("P5\n").has(ErrorId::NcVariableWithoutAssignment));
}

TEST(NcVariables, KernelVariablesAreBlocks) {
  auto d = decode("V.G.NP[1].V.X = 10\nV.A.MANUAL_OFFSETS.Z = 0.5\nG54 X[V.G.NP[1].V.X + V.A.MESS.X]\n"
                  "V.G.AKT_PLATZ = 3\nM30\n");
  ASSERT_EQ(d.blocks.size(), 5u) << dump(d);
  ASSERT_EQ(d.blocks[0].kernel_writes.size(), 1u);
  EXPECT_EQ(d.blocks[0].kernel_writes[0].name, "V.G.NP[1].V.X");
  EXPECT_DOUBLE_EQ(d.blocks[0].kernel_writes[0].value, 10);
  EXPECT_EQ(d.blocks[1].kernel_writes[0].name, "V.A.MANUAL_OFFSETS.Z");
  EXPECT_DOUBLE_EQ(*d.blocks[2].axes[0], 10);
  EXPECT_EQ(d.blocks[3].kernel_writes[0].name, "V.G.AKT_PLATZ");
}

TEST(NcVariables, UnknownKernelVariable) {
  EXPECT_TRUE(decode("X[V.A.MESS.Q]\n").has(ErrorId::NcUnknownKernelVariable));
  EXPECT_TRUE(decode("V.G.NP[97].V.X = 1\n").has(ErrorId::NcUnknownKernelVariable));
  EXPECT_TRUE(decode("V.G.FOO = 1\n").has(ErrorId::NcUnknownKernelVariable));
}

TEST(NcVariables, KernelApiGetSet) {
  auto p = write_file(temp_dir() / "k.nc", "X[V.A.MESS.X]\nV.G.NP[2].V.Y = 7\nY1\nM30\n");
  Decoder dec(p, default_config());
  EXPECT_TRUE(dec.set_variable("V.A.MESS.X", 12.5));
  EXPECT_FALSE(dec.set_variable("V.A.MESS.Q", 1));
  EXPECT_FALSE(dec.set_variable("garbage", 1));
  auto r = dec.next();
  ASSERT_EQ(r.status, Decoder::Status::block);
  EXPECT_DOUBLE_EQ(*r.block.axes[0], 12.5);
  ASSERT_EQ(dec.next().status, Decoder::Status::block);
  EXPECT_EQ(dec.get_variable("V.G.NP[2].V.Y"), 7.0);
  EXPECT_EQ(dec.get_variable("V.G.AKT_PLATZ"), 0.0);
  EXPECT_FALSE(dec.get_variable("V.G.NOPE").has_value());
  EXPECT_TRUE(dec.set_variable("P10", 3));
  EXPECT_EQ(dec.get_variable("P10"), 3.0);
}

TEST(NcVariables, LocalVariablesPerCallLevel) {
  auto d = decode("%L SUB\n#VAR\nV.L.A = 2\n#ENDVAR\nX[V.L.A]\nM17\n%MAIN\n#VAR\nV.L.A = 1\n#ENDVAR\n"
                  "LL SUB\nY[V.L.A]\nM30\n");
  ASSERT_EQ(d.blocks.size(), 3u) << dump(d);
  EXPECT_DOUBLE_EQ(*d.blocks[0].axes[0], 2);
  EXPECT_DOUBLE_EQ(*d.blocks[1].axes[1], 1);
}

}  // namespace
}  // namespace nck::nc::test
