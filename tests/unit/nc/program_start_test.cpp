// Where a file's program starts (TF5200 diagnosis 20193): code before any %
// header starts an unnamed main program at the first line, %name a named
// one; a % line inside the main program is 20193; a file of local
// subroutines only has no program (920053). Called files follow the same rule.
#include "nc_test_util.hpp"

namespace nck::nc::test {
namespace {

TEST(NcProgramStart, TrailingPercentAfterM30IsHarmless) {
  auto d = decode("G0 X10\nM30\n%\n");
  EXPECT_EQ(d.diags.size(), 0u) << dump(d);
  EXPECT_EQ(xs(d), (std::vector<double>{10}));
  EXPECT_EQ(d.last, Decoder::Status::end);
}

TEST(NcProgramStart, CommentsBeforeTheHeaderAreNoCode) {
  auto d = decode("; title\n( note )\n\n#COMMENT BEGIN\nX99\n#COMMENT END\n(c) %part\nX3\nM30\n");
  EXPECT_EQ(d.diags.size(), 0u) << dump(d);
  EXPECT_EQ(xs(d), (std::vector<double>{3}));
}

TEST(NcProgramStart, CodeBeforeTheHeaderRunsAndTheHeaderIs20193) {
  auto d = decode("; title\nN10 X5\n%MAIN\nX10\nM30\n");
  EXPECT_EQ(xs(d), (std::vector<double>{5}));
  const Diagnostic* e = d.find(ErrorId::NcPercentInMainProgram);
  ASSERT_NE(e, nullptr) << dump(d);
  EXPECT_EQ(e->loc.line, 3u);
  EXPECT_NE(e->message.find("line 2"), std::string::npos) << e->message;
  EXPECT_EQ(d.last, Decoder::Status::error);
}

TEST(NcProgramStart, PercentInsideANamedMainProgramIs20193) {
  for (const char* header : {"%L SUB", "%OTHER", "%"}) {
    auto d = decode(std::string("%MAIN\nX1\n") + header + "\nX2\nM17\n");
    const Diagnostic* e = d.find(ErrorId::NcPercentInMainProgram);
    ASSERT_NE(e, nullptr) << header << "\n" << dump(d);
    EXPECT_EQ(e->loc.line, 3u);
    EXPECT_NE(e->message.find("%MAIN of line 1"), std::string::npos) << e->message;
    EXPECT_EQ(xs(d), (std::vector<double>{1}));
  }
}

// 20193 stops decoding also in lint mode: the next section is no main code.
TEST(NcProgramStart, TwentyOneNinetyThreeIsFatalInLintMode) {
  auto cfg = default_config();
  cfg.continue_after_error = true;
  auto d = decode("X1\n%L SUB\nX2\nM17\n", cfg);
  EXPECT_EQ(d.errors(), 1u) << dump(d);
  EXPECT_TRUE(d.has(ErrorId::NcPercentInMainProgram));
}

TEST(NcProgramStart, OnlyLocalSubroutinesIsNoProgram) {
  auto d = decode("; library\n%L A\nX1\nM17\n%L B\nX2\nM17\n");
  const Diagnostic* e = d.find(ErrorId::NcNoMainProgram);
  ASSERT_NE(e, nullptr) << dump(d);
  EXPECT_EQ(e->loc.line, 2u);
  EXPECT_NE(e->message.find("%L A (line 2), %L B (line 5)"), std::string::npos) << e->message;
  EXPECT_TRUE(d.blocks.empty());
}

TEST(NcProgramStart, EmptyFileRunsNothingAndSaysNoM30) {
  auto d = decode("; nothing\n");
  EXPECT_TRUE(d.has(ErrorId::NcMissingProgramEnd)) << dump(d);
  EXPECT_EQ(d.errors(), 0u);
}

TEST(NcProgramStart, CalledFilesFollowTheSameRule) {
  auto dir = temp_dir();
  write_file(dir / "cam.nc", "X7\nM17\n%\n");  // code first: from line 1, not after the %
  write_file(dir / "lib.nc", "%L A\nX8\nM17\n");
  auto d = decode_file(write_file(dir / "main.nc", "L cam.nc\nM30\n"));
  EXPECT_EQ(d.diags.size(), 0u) << dump(d);
  EXPECT_EQ(xs(d), (std::vector<double>{7}));
  auto e = decode_file(write_file(dir / "main2.nc", "X1\nL lib.nc\nM30\n"));
  const Diagnostic* no = e.find(ErrorId::NcNoMainProgram);
  ASSERT_NE(no, nullptr) << dump(e);
  EXPECT_EQ(no->loc.line, 2u);  // at the call
}

}  // namespace
}  // namespace nck::nc::test
