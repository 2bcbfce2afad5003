// to_json for `nck parse --json`.
#include "nc_test_util.hpp"
#include "nck/nc/block_json.hpp"

namespace nck::nc::test {
namespace {

TEST(NcBlockJson, BlockFields) {
  auto p = write_file(temp_dir() / "j.nc", "N10 G1 X1.5 C1=90 F200 M8 S2[M3 REV100]\n#CS ON [1][0,0,10]\nM30\n");
  Decoder dec(p, default_config());
  auto r = dec.next();
  ASSERT_EQ(r.status, Decoder::Status::block);
  auto j = to_json(r.block, dec);
  EXPECT_EQ(j["n"], 10);
  EXPECT_EQ(j["line"], 1);
  EXPECT_EQ(j["file"], p.string());
  EXPECT_DOUBLE_EQ(j["axes"]["X"].get<double>(), 1.5);
  EXPECT_DOUBLE_EQ(j["axes"]["C1"].get<double>(), 90);
  EXPECT_EQ(j["m"], nlohmann::json::array({8}));
  EXPECT_EQ(j["modal"]["motion"], "G1");
  EXPECT_EQ(j["spindles"][0]["name"], "S2");
  EXPECT_EQ(j["spindles"][0]["m"], "M3");
  auto h = to_json(dec.next().block, dec);
  EXPECT_EQ(h["hash"]["command"], "#CS ON");
  EXPECT_EQ(h["hash"]["id"], 1);
  EXPECT_DOUBLE_EQ(h["hash"]["values"][2].get<double>(), 10);
  EXPECT_TRUE(j["n"].is_number());
  EXPECT_TRUE(to_json(dec.next().block, dec)["program_end"].get<bool>());
}

}  // namespace
}  // namespace nck::nc::test
