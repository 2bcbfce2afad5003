// Cycle calls in the decoder: parameters, @ words by plane, modal repeats,
// the search path and the errors (IDs, file and line).
#include "nc_test_util.hpp"

namespace nck::nc::test {
namespace {

struct Files {
  std::filesystem::path dir = temp_dir();
  std::filesystem::path add(const std::string& name, const std::string& text) {
    std::filesystem::create_directories((dir / name).parent_path());
    return write_file(dir / name, text);
  }
};

TEST(NcCycle, ParametersReachTheCycleAndAtAxesFollowThePlane) {
  Files f;
  f.add("c.ecy", "G1 @X=@P1 @Y=@P2 @Z=@P3\nM17\n");
  auto d = decode_file(f.add("main.nc",
                             "G18\nL CYCLE [NAME=c.ecy @P1=1 @P2=2 @P3=3]\n"
                             "G19\nL CYCLE [NAME=c.ecy @P1=1 @P2=2 @P3=3]\nM30\n"));
  ASSERT_EQ(d.errors(), 0u) << d.diags.size();
  std::vector<const Block*> moves;
  for (const Block& b : d.blocks)
    if (b.has_axis_words()) moves.push_back(&b);
  ASSERT_EQ(moves.size(), 2u);
  // G18: @X = Z, @Y = X, @Z = Y.
  EXPECT_DOUBLE_EQ(*moves[0]->axes[2], 1);
  EXPECT_DOUBLE_EQ(*moves[0]->axes[0], 2);
  EXPECT_DOUBLE_EQ(*moves[0]->axes[1], 3);
  // G19: @X = Y, @Y = Z, @Z = X.
  EXPECT_DOUBLE_EQ(*moves[1]->axes[1], 1);
  EXPECT_DOUBLE_EQ(*moves[1]->axes[2], 2);
  EXPECT_DOUBLE_EQ(*moves[1]->axes[0], 3);
  EXPECT_EQ(moves[0]->depth, 1);
}

TEST(NcCycle, ModalMoveRepeatsAfterMotionBlocksOnly) {
  Files f;
  f.add("c.ecy", "G1 Z-1\nM17\n");
  auto d = decode_file(f.add("main.nc",
                             "L CYCLE [NAME=c.ecy MODAL_MOVE]\nG0 X1\nM8\nG0 X2\n#DISABLE MODAL CYCLE\nG0 X3\nM30\n"));
  ASSERT_EQ(d.errors(), 0u);
  int cycle_blocks = 0;
  for (const Block& b : d.blocks) cycle_blocks += b.depth == 1 && b.has_axis_words();
  EXPECT_EQ(cycle_blocks, 3);  // at the call, after X1, after X2
}

TEST(NcCycle, CallerModalStateIsRestored) {
  Files f;
  f.add("c.ecy", "G91 G1 X1 F100\nM17\n");
  auto d = decode_file(f.add("main.nc", "G90 G0 X0 F500\nL CYCLE [NAME=c.ecy]\nX5\nM30\n"));
  ASSERT_EQ(d.errors(), 0u);
  const Block& after = d.blocks.at(2);
  EXPECT_TRUE(after.modal.absolute);
  EXPECT_EQ(after.modal.motion, Motion::rapid);
  EXPECT_DOUBLE_EQ(after.modal.feed_mm_min, 500);
}

TEST(NcCycle, ErrorsCarryIdFileAndLine) {
  Files f;
  f.add("c.ecy", "G0 X1\nG0 X[@P9]\nM17\n");
  auto d = decode_file(f.add("main.nc", "L CYCLE [NAME=c.ecy]\nM30\n"));
  const Diagnostic* e = d.find(ErrorId::NcCycleParamMissing);
  ASSERT_NE(e, nullptr);
  EXPECT_NE(e->loc.file.find("c.ecy"), std::string::npos);
  EXPECT_EQ(e->loc.line, 2u);
  EXPECT_NE(e->message.find("called from"), std::string::npos) << e->message;

  auto outside = decode("G0 X0\n@P1 = 2\nM30\n");
  ASSERT_NE(outside.find(ErrorId::NcCycleParamOutsideCycle), nullptr);
  EXPECT_EQ(outside.find(ErrorId::NcCycleParamOutsideCycle)->loc.line, 2u);

  auto missing = decode("L CYCLE [NAME=nowhere.ecy]\nM30\n");
  ASSERT_NE(missing.find(ErrorId::NcCycleNotFound), nullptr);
  EXPECT_NE(missing.find(ErrorId::NcCycleNotFound)->message.find("nowhere.ecy"), std::string::npos);
}

TEST(NcCycle, ConfiguredFoldersAreSearchedAfterTheProgramFolder) {
  Files f;
  f.add("lib/c.ecy", "G1 X[@P1]\nM17\n");
  f.add("near/c.ecy", "G1 X[@P1 * 10]\nM17\n");
  auto cfg = default_config();
  cfg.cycle_dirs = {f.dir / "lib"};
  auto far = decode_file(f.add("main.nc", "L CYCLE [NAME=c.ecy @P1=2]\nM30\n"), cfg);
  ASSERT_EQ(far.errors(), 0u);
  EXPECT_DOUBLE_EQ(*far.blocks.at(0).axes[0], 2);
  auto near = decode_file(f.add("near/main.nc", "L CYCLE [NAME=c.ecy @P1=2]\nM30\n"), cfg);
  ASSERT_EQ(near.errors(), 0u);
  EXPECT_DOUBLE_EQ(*near.blocks.at(0).axes[0], 20);  // the program's folder comes first
}

TEST(NcCycle, ExistTellsWhetherAParameterWasGiven) {
  Files f;
  f.add("c.ecy", "$IF EXIST[@P2]\nG1 X[@P2]\n$ELSE\nG1 X-1\n$ENDIF\nM17\n");
  auto d = decode_file(f.add("main.nc", "L CYCLE [NAME=c.ecy @P1=1]\nL CYCLE [NAME=c.ecy @P2=7]\nM30\n"));
  ASSERT_EQ(d.errors(), 0u);
  EXPECT_DOUBLE_EQ(*d.blocks.at(0).axes[0], -1);
  EXPECT_DOUBLE_EQ(*d.blocks.at(1).axes[0], 7);
}

}  // namespace
}  // namespace nck::nc::test
