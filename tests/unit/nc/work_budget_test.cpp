// The decoder's reading budget and stop request (issue 26, finding 1):
// every block read beyond the main program's first pass counts, and a stop
// request ends decoding at the next block read, without a diagnostic.
#include <gtest/gtest.h>

#include "nc_test_util.hpp"

namespace nck::nc::test {
namespace {

DecoderConfig budget(std::uint64_t lines) {
  DecoderConfig c = default_config();
  c.max_lines_read = lines;
  return c;
}

std::string skipped_in_loop(int skipped) {
  std::string text = "$WHILE 1\n$IF 0\n";
  for (int i = 0; i < skipped; ++i) text += "G1 X1\n";
  return text + "$ENDIF\n$ENDWHILE\nM30\n";
}

TEST(NcWorkBudget, SkippedLinesCountAgainstTheBudget) {
  // 1,000 passes of 500 skipped lines: far below the loop budget, past a
  // reading budget of 100,000 blocks.
  const Decoded d = decode(skipped_in_loop(500), budget(100'000));
  EXPECT_EQ(d.last, Decoder::Status::error);
  ASSERT_TRUE(d.has(ErrorId::NcReadLimit)) << dump(d);
  EXPECT_EQ(d.errors(), 1u) << dump(d);  // nothing the cut-off reading made up
}

TEST(NcWorkBudget, TheMainProgramsFirstPassIsFree) {
  std::string text;
  for (int i = 0; i < 5000; ++i) text += "G1 X" + std::to_string(i % 10) + "\n";
  const Decoded d = decode(text + "M30\n", budget(100));
  EXPECT_FALSE(d.has(ErrorId::NcReadLimit)) << dump(d);
  EXPECT_EQ(d.blocks.size(), 5001u);
}

TEST(NcWorkBudget, SubroutineBodiesAndGotoSearchesCount) {
  const auto dir = temp_dir();
  std::string sub;
  for (int i = 0; i < 100; ++i) sub += "P2 = " + std::to_string(i) + "\n";
  write_file(dir / "sub.nc", sub + "M17\n");
  const Decoded calls =
      decode_file(write_file(dir / "p.nc", "$FOR P1 = 1, 1000\nL sub.nc\n$ENDFOR\nM30\n"), budget(50'000));
  EXPECT_TRUE(calls.has(ErrorId::NcReadLimit)) << dump(calls);
  std::string labels;
  for (int i = 1; i <= 12000; ++i) labels += "N" + std::to_string(i) + ": P1 = 1\n";
  const Decoded jumps = decode(labels + "$GOTO N12000\nM30\n", budget(1'000'000));
  EXPECT_TRUE(jumps.has(ErrorId::NcReadLimit)) << dump(jumps);
}

TEST(NcWorkBudget, AStopRequestEndsDecodingWithoutADiagnostic) {
  std::atomic<bool> stop{false};
  DecoderConfig c = default_config();
  c.stop = &stop;
  Decoder dec(write_file(temp_dir() / "p.nc", "G1 X1\nG1 X2\n" + skipped_in_loop(10)), c);
  EXPECT_EQ(dec.next().status, Decoder::Status::block);
  stop = true;
  EXPECT_EQ(dec.next().status, Decoder::Status::stopped);
  EXPECT_EQ(dec.next().status, Decoder::Status::stopped);
  EXPECT_TRUE(dec.diagnostics().empty());
}

}  // namespace
}  // namespace nck::nc::test
