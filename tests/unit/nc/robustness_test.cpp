// Bad input never crashes or hangs: garbage, huge lines, unterminated
// brackets, and a seeded random fuzz over mutated isg-samples.
#include <random>

#include "nc_test_util.hpp"

namespace nck::nc::test {
namespace {

TEST(NcRobustness, BinaryGarbage) {
  std::string g;
  for (int i = 0; i < 512; ++i) g.push_back(static_cast<char>(i * 37 % 256));
  auto d = decode(g);
  EXPECT_GT(d.errors(), 0u);
  auto nul = decode(std::string("X1\0\x01Y2\n", 7));
  EXPECT_TRUE(nul.has(ErrorId::NcUnexpectedCharacter)) << dump(nul);
}

TEST(NcRobustness, HugeLineIsAnError) {
  auto d = decode("X1\nX" + std::string(100000, '1') + "\nM30\n");
  const Diagnostic* e = d.find(ErrorId::NcBlockTooLong);
  ASSERT_NE(e, nullptr) << dump(d);
  EXPECT_EQ(e->loc.line, 2u);
  EXPECT_EQ(d.blocks.size(), 1u);
  // Exactly 4000 characters is still fine.
  std::string ok = "X1 ;" + std::string(3996, 'c');
  ASSERT_EQ(ok.size(), 4000u);
  EXPECT_EQ(decode(ok + "\nM30\n").errors(), 0u);
  // Continuation lines count together.
  std::string cont;
  for (int i = 0; i < 50; ++i) cont += "(" + std::string(98, 'c') + ") \\\n";
  EXPECT_TRUE(decode(cont + "X1\n").has(ErrorId::NcBlockTooLong));
}

TEST(NcRobustness, UnterminatedThings) {
  EXPECT_EQ(decode("X1 (open comment runs to the end\nM30\n").errors(), 0u);
  EXPECT_TRUE(decode("X[1+[2\n").has(ErrorId::NcExprSyntax));
  EXPECT_TRUE(decode("S2[M3\n").has(ErrorId::NcExprSyntax));
  EXPECT_TRUE(decode("#CS ON [1][1,2\n").has(ErrorId::NcHashArguments));
  EXPECT_TRUE(decode("#VAR\nV.P.A = [1,2\n#ENDVAR\n").has(ErrorId::NcExprSyntax));
  EXPECT_TRUE(decode("#VAR\nV.P.S : STRING = \"abc\n#ENDVAR\n").has(ErrorId::NcVarDeclaration));
  EXPECT_TRUE(decode("X1 \\").has(ErrorId::NcMissingProgramEnd));
}

TEST(NcRobustness, LintModeContinuesAfterErrors) {
  auto cfg = default_config();
  cfg.continue_after_error = true;
  auto d = decode("X1\nG999\nY2\nQ3\nZ3\nM30\n", cfg);
  EXPECT_EQ(d.errors(), 2u) << dump(d);
  EXPECT_EQ(d.blocks.size(), 4u);
}

std::vector<std::string> sample_texts() {
  std::vector<std::string> r;
  auto dir = std::filesystem::path(NCK_SOURCE_DIR) / "tests" / "data" / "isg-samples";
  std::error_code ec;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir, ec)) {
    if (!e.is_regular_file() || e.path().extension() != ".nc") continue;
    std::ifstream in(e.path(), std::ios::binary);
    r.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  r.push_back("N10 G1 X[SIN[30]*P1] S2[M3 REV=1000] #CS ON [1][1,2,3]\n$WHILE P1 < 3\nP1=P1+1\n$ENDWHILE\nM30\n");
  return r;
}

TEST(NcRobustness, SeededFuzzNeverCrashesOrHangs) {
  auto seeds = sample_texts();
  ASSERT_FALSE(seeds.empty());
  std::mt19937 rng(20240601);
  const std::string alphabet = "GXYZMS[]()$#%;/\\=.-+*,01234567890 \n\"@PVLNIFKR\t";
  auto dir = temp_dir();
  auto cfg = default_config();
  cfg.max_loop_iterations = 200;
  cfg.max_subroutine_depth = 4;
  int runs = 0;
  for (int i = 0; i < 3000; ++i) {
    std::string t;
    if (i % 10 == 0) {
      std::uniform_int_distribution<int> len(0, 300), byte(0, 255);
      for (int k = len(rng); k > 0; --k) t.push_back(static_cast<char>(byte(rng)));
    } else {
      t = seeds[rng() % seeds.size()];
      int mutations = 1 + static_cast<int>(rng() % 8);
      for (int k = 0; k < mutations && !t.empty(); ++k) {
        std::size_t at = rng() % t.size();
        switch (rng() % 4) {
          case 0: t[at] = alphabet[rng() % alphabet.size()]; break;
          case 1: t.insert(at, 1, alphabet[rng() % alphabet.size()]); break;
          case 2: t.erase(at, 1 + rng() % 5); break;
          default: t.insert(at, t.substr(rng() % t.size(), rng() % 40)); break;
        }
      }
    }
    auto p = write_file(dir / "fuzz.nc", t);
    Decoder dec(p, cfg);
    for (int n = 0; n < 2000; ++n) {
      auto r = dec.next();
      if (r.status != Decoder::Status::block) break;
    }
    ++runs;
  }
  EXPECT_EQ(runs, 3000);
}

}  // namespace
}  // namespace nck::nc::test
