// The real ISG programs of tests/data/isg-samples: all decode without a crash
// (many contain placeholders and stop with a diagnostic); a few results.
#include "nc_test_util.hpp"

namespace nck::nc::test {
namespace {

std::filesystem::path samples() {
  return std::filesystem::path(NCK_SOURCE_DIR) / "tests" / "data" / "isg-samples";
}

class NcIsgSamples : public ::testing::Test {
 protected:
  void SetUp() override {
    // A missing corpus is a failure, never a skip (the fuzz seeds need it too).
    if (!std::filesystem::is_directory(samples())) GTEST_FAIL() << "no " << samples();
  }
};

TEST_F(NcIsgSamples, AllDecodeWithoutCrash) {
  int files = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(samples())) {
    if (!e.is_regular_file() || e.path().extension() != ".nc") continue;
    auto cfg = default_config();
    cfg.continue_after_error = true;
    cfg.max_loop_iterations = 1000;
    auto d = decode_file(e.path(), cfg, 5000);
    for (const auto& diag : d.diags) {
      EXPECT_FALSE(diag.loc.file.empty());
      EXPECT_FALSE(diag.message.empty());
    }
    ++files;
  }
  EXPECT_GE(files, 25);
}

TEST_F(NcIsgSamples, FoldingExampleTakesTheElseBranch) {
  auto d = decode_file(samples() / "Folding_examples.nc");
  ASSERT_FALSE(d.blocks.empty()) << dump(d);
  EXPECT_EQ(d.blocks[0].n, 40);  // N010 $IF 1 > 2 ... N040 G01 X10 in $ELSE
  EXPECT_DOUBLE_EQ(*d.blocks[0].axes[0], 10);
  EXPECT_EQ(d.blocks[0].modal.motion, Motion::linear);
  // Then "$SWITCH [Options]" is not an expression nck can evaluate.
  EXPECT_TRUE(d.has(ErrorId::NcUnknownFunction) || d.has(ErrorId::NcExprSyntax)) << dump(d);
}

TEST_F(NcIsgSamples, AlignEqualSignFirstBlock) {
  auto d = decode_file(samples() / "alignEqualSign_test.nc");
  ASSERT_FALSE(d.blocks.empty()) << dump(d);
  const Block& b = d.blocks[0];
  EXPECT_EQ(b.modal.motion, Motion::rapid);
  EXPECT_TRUE(b.modal.absolute);
  EXPECT_DOUBLE_EQ(b.modal.feed_mm_min, 5000);
  ASSERT_EQ(b.spindles.size(), 1u);
  EXPECT_EQ(b.spindles[0].m, SpindleM::m3);
  EXPECT_DOUBLE_EQ(*b.spindles[0].rev_rpm, 6000);
  // V.G.WZ_AKT.R is readable (0 here); the "trash line" inside #VAR is not.
  ASSERT_EQ(d.errors(), 1u) << dump(d);
  EXPECT_EQ(d.diags[0].id, ErrorId::NcVarDeclaration);
  EXPECT_EQ(d.diags[0].loc.line, 14u);
}

TEST_F(NcIsgSamples, SubProgramsSampleRunsLocalCallsFirst) {
  auto cfg = default_config();
  cfg.continue_after_error = true;
  auto d = decode_file(samples() / "subPrograms.nc", cfg);
  // %MAIN starts with "L subPrograms.nc": the file calls itself until the
  // nesting limit stops it at line 19.
  ASSERT_FALSE(d.diags.empty());
  EXPECT_EQ(d.diags[0].id, ErrorId::NcSubroutineDepth) << dump(d);
  EXPECT_EQ(d.diags[0].loc.line, 19u);
}

TEST_F(NcIsgSamples, VariablesSample) {
  auto cfg = default_config();
  cfg.continue_after_error = true;
  auto d = decode_file(samples() / "variables_test.nc", cfg);
  // The German title on line 1 ("Anlegen von Variablen ...") is the first
  // block outside comments: it starts an unnamed main program (TF5200
  // 20193), an unknown word here (A is no axis of the test channel), and
  // %test_var_def_1 on line 3 then stands inside that program (20193,
  // which stops decoding).
  ASSERT_EQ(d.diags.size(), 2u) << dump(d);
  EXPECT_EQ(d.diags[0].id, ErrorId::NcUnknownWord) << dump(d);
  EXPECT_EQ(d.diags[0].loc.line, 1u);
  EXPECT_EQ(d.diags[1].id, ErrorId::NcPercentInMainProgram) << dump(d);
  EXPECT_EQ(d.diags[1].loc.line, 3u);
}

}  // namespace
}  // namespace nck::nc::test
