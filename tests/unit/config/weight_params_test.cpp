// The limits of the program's weightings (P-AXIS-00292 a_w_max, P-AXIS-00293
// tr_w_min): absent or 0 stands for a_max / tr_min, given values must lie in
// their TF5200 ranges, or 910101 at the key's file and line.
#include <gtest/gtest.h>

#include "machine_folder.hpp"

namespace nck::config {
namespace {

using test::dump;
using test::MachineFolder;
using test::with_id;
using test::x_gear;

TEST(WeightParams, AbsentLimitsAreAmaxAndTrMin) {
  MachineFolder f;
  f.append("x.lis", "getriebe[0].dynamik.a_max 3000\ngetriebe[0].dynamik.tr_min 12000\n");
  const LoadResult r = f.load();
  ASSERT_TRUE(r.machine) << dump(r.diagnostics);
  EXPECT_DOUBLE_EQ(x_gear(r).weighted_a_max(), 3000);
  EXPECT_DOUBLE_EQ(x_gear(r).weighted_tr_min_s(), 0.012);
}

TEST(WeightParams, GivenLimitsAreReadInTheirUnits) {
  MachineFolder f;
  f.append("x.lis", "getriebe[0].dynamik.a_max 3000\ngetriebe[0].dynamik.a_w_max 2000\n"
                    "getriebe[0].dynamik.tr_w_min 20000\n");
  const LoadResult r = f.load();
  ASSERT_TRUE(r.machine) << dump(r.diagnostics);
  EXPECT_TRUE(with_id(r.diagnostics, ErrorId::ConfigWeightLimit).empty()) << dump(r.diagnostics);
  EXPECT_DOUBLE_EQ(x_gear(r).weighted_a_max(), 2000);
  EXPECT_DOUBLE_EQ(x_gear(r).weighted_tr_min_s(), 0.020);
}

// a_w_max lies in [max(a_beschl, a_brems), a_max] = [1000, 3000] here.
TEST(WeightParams, AwMaxOutsideItsRangeNamesItsLine) {
  for (const char* v : {"999", "3001"}) {
    MachineFolder f;
    f.append("x.lis", std::string("getriebe[0].dynamik.a_max 3000\ngetriebe[0].dynamik.a_w_max ") + v + "\n");
    const LoadResult r = f.load();
    const auto found = with_id(r.diagnostics, ErrorId::ConfigWeightLimit);
    ASSERT_EQ(found.size(), 1u) << v << dump(r.diagnostics);
    EXPECT_EQ(found[0].loc.file, f.file("x.lis"));
    EXPECT_EQ(found[0].loc.line, 4u);
    EXPECT_NE(found[0].message.find("a_w_max"), std::string::npos) << found[0].message;
  }
}

// tr_w_min lies in [tr_min, shortest feed ramp] = [10,000, 50,000] µs by default.
TEST(WeightParams, TrWMinOutsideItsRangeNamesItsLine) {
  for (const char* v : {"9999", "50001"}) {
    MachineFolder f;
    f.append("x.lis", std::string("getriebe[0].dynamik.tr_w_min ") + v + "\n");
    const LoadResult r = f.load();
    const auto found = with_id(r.diagnostics, ErrorId::ConfigWeightLimit);
    ASSERT_EQ(found.size(), 1u) << v << dump(r.diagnostics);
    EXPECT_EQ(found[0].loc.line, 3u);
    EXPECT_NE(found[0].message.find("tr_w_min"), std::string::npos) << found[0].message;
  }
  MachineFolder edge;
  edge.append("x.lis", "getriebe[0].dynamik.tr_w_min 50000\n");
  EXPECT_TRUE(with_id(edge.load().diagnostics, ErrorId::ConfigWeightLimit).empty());
}

}  // namespace
}  // namespace nck::config
