// %L local subroutines, L global subroutine files, M17/M29, nesting, cache.
#include <thread>

#include "nc_test_util.hpp"

namespace nck::nc::test {
namespace {

TEST(NcSubprograms, LocalAndGlobalCalls) {
  auto dir = temp_dir();
  std::filesystem::create_directories(dir / "sub");
  write_file(dir / "sub" / "contour.nc", "; global subroutine\nN1 X[P1 + 100]\nM17\n");
  write_file(dir / "sub" / "inner.nc", "%L LOCAL_IN_FILE\nZ7\nM29\n%INNER\nLL LOCAL_IN_FILE\nY7\nL contour.nc\n");
  auto p = write_file(dir / "main.nc",
                      "%L UP1   (1st local subroutine)\nN1 X1\nN9 M17\n"
                      "%L UP2\nN11 X2\nN19 M29\n"
                      "%L tapered thread\nX3\n"   // ends at the next % without M17
                      "%MAIN\nN100 P1 = 5\nN200 LL UP1 ; call\nN210 LL UP2\nLL tapered thread\n"
                      "N250 L sub/contour.nc\nL sub/inner.nc\nN300 M30\n");
  auto d = decode_file(p);
  ASSERT_EQ(d.errors(), 0u) << dump(d);
  std::vector<double> x;
  for (const auto& b : d.blocks)
    if (b.axes[0]) x.push_back(*b.axes[0]);
  EXPECT_EQ(x, (std::vector<double>{1, 2, 3, 105, 105}));
  ASSERT_EQ(d.blocks.size(), 8u);
  EXPECT_EQ(d.blocks[0].depth, 1);
  EXPECT_EQ(d.blocks[0].n, 1);
  EXPECT_EQ(d.blocks[3].line, 2u);
  EXPECT_EQ(d.files[d.blocks[3].file_id], (dir / "sub" / "contour.nc").string());
  EXPECT_DOUBLE_EQ(*d.blocks[4].axes[2], 7);    // local subroutine of the called file
  EXPECT_EQ(d.blocks[4].depth, 2);
  EXPECT_TRUE(d.blocks.back().program_end);
  EXPECT_EQ(d.blocks.back().depth, 0);
}

TEST(NcSubprograms, Errors) {
  EXPECT_TRUE(decode("LL NOPE\n").has(ErrorId::NcSubroutineNotFound));
  EXPECT_TRUE(decode("L missing_file.nc\n").has(ErrorId::NcSubroutineNotFound));
  EXPECT_TRUE(decode("L a.nc X1\n").has(ErrorId::NcCallSyntax));
  EXPECT_TRUE(decode("X1\nM17\n").has(ErrorId::NcReturnOutsideSubroutine));
  auto w = decode("X1\n");
  EXPECT_TRUE(w.has(ErrorId::NcMissingProgramEnd));
  EXPECT_EQ(w.last, Decoder::Status::end);
  auto e = decode("%L S\nX1 M30\n%M\nLL S\nX2\n");
  EXPECT_TRUE(e.has(ErrorId::NcEndInSubroutine));
  EXPECT_EQ(e.blocks.size(), 1u);
  EXPECT_TRUE(e.blocks[0].program_end);
}

TEST(NcSubprograms, RecursionHitsTheDepthLimit) {
  auto dir = temp_dir();
  auto p = write_file(dir / "rec.nc", "X1\nL rec.nc\n");
  auto cfg = default_config();
  cfg.max_subroutine_depth = 5;
  auto d = decode_file(p, cfg);
  EXPECT_TRUE(d.has(ErrorId::NcSubroutineDepth)) << dump(d);
  EXPECT_EQ(d.blocks.size(), 6u);
}

TEST(NcSubprograms, FileCacheIsUsedAndNoticesChanges) {
  auto dir = temp_dir();
  auto sub = write_file(dir / "sub.nc", "X1\nM17\n");
  auto p = write_file(dir / "main.nc", "$FOR P1 = 1, 50\nL sub.nc\n$ENDFOR\nM30\n");
  auto cfg = default_config();
  cfg.use_cached_files = true;
  cfg.max_cache_number = 4;
  cfg.max_cache_size_kb = 64;
  Decoder dec(p, cfg);
  auto r = dec.next();
  ASSERT_EQ(r.status, Decoder::Status::block);
  EXPECT_DOUBLE_EQ(*r.block.axes[0], 1);
  // Change the file (other size => noticed even with a coarse mtime).
  write_file(sub, "X22\nM17\n");
  r = dec.next();
  ASSERT_EQ(r.status, Decoder::Status::block);
  EXPECT_DOUBLE_EQ(*r.block.axes[0], 22);
  int n = 2;
  while ((r = dec.next()).status == Decoder::Status::block) ++n;
  EXPECT_EQ(n, 51);  // 50 calls + M30
  EXPECT_EQ(r.status, Decoder::Status::end);
}

// A local subroutine called in a loop is read from memory after the first
// call, not from its file again on every pass (which cost a file open and
// read per call: fuzz finding decoder-timeout-9f79e3f6). Proof: an edit of
// the file after the first call does not reach the later calls.
TEST(NcSubprograms, LocalSubroutineTextIsReadOncePerRun) {
  auto dir = temp_dir();
  const std::string text = "%L S\nX1\nM17\n%MAIN\n$FOR P1 = 1, 50\nLL S\n$ENDFOR\nM30\n";
  auto p = write_file(dir / "main.nc", text);
  Decoder dec(p, default_config());
  auto r = dec.next();
  ASSERT_EQ(r.status, Decoder::Status::block);
  EXPECT_DOUBLE_EQ(*r.block.axes[0], 1);
  std::string edited = text;
  edited[6] = '9';  // "%L S\nX9": same size and offsets
  write_file(p, edited);
  int n = 1;
  while ((r = dec.next()).status == Decoder::Status::block && !r.block.program_end) {
    ASSERT_TRUE(r.block.axes[0]);
    EXPECT_DOUBLE_EQ(*r.block.axes[0], 1) << "call " << n + 1;
    ++n;
  }
  EXPECT_EQ(n, 50);
}

TEST(NcSubprograms, CacheBoundsAreKept) {
  auto dir = temp_dir();
  write_file(dir / "a.nc", "X1\nM17\n");
  write_file(dir / "b.nc", "X2\nM17\n");
  write_file(dir / "big.nc", std::string(3000, ';') + "\nX3\nM17\n");
  auto p = write_file(dir / "m.nc", "L a.nc\nL b.nc\nL big.nc\nL a.nc\nM30\n");
  auto cfg = default_config();
  cfg.use_cached_files = true;
  cfg.max_cache_number = 1;
  cfg.max_cache_size_kb = 2;  // big.nc does not fit: streamed instead
  auto d = decode_file(p, cfg);
  ASSERT_EQ(d.blocks.size(), 5u) << dump(d);
  EXPECT_DOUBLE_EQ(*d.blocks[2].axes[0], 3);
  EXPECT_DOUBLE_EQ(*d.blocks[3].axes[0], 1);
}

}  // namespace
}  // namespace nck::nc::test
