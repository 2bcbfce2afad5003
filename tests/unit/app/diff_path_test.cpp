// nck diff --run's path comparison follows paths that revisit a place
// (issue 48 item 3): a plunge and its retract along the same line, a loop's
// next turn, are not taken for each other.
#include <gtest/gtest.h>

#include "cli_helpers.hpp"

namespace nck::app::testing {
namespace {

using nlohmann::json;

// nck diff --run of two programs on the mill, --json.
json diff_run(const std::filesystem::path& dir, const std::string& a, const std::string& b) {
  const auto pa = write(dir / "a.nc", a), pb = write(dir / "b.nc", b);
  const CliResult r = run_nck_raw("diff --run " + mill() + " " + pa.string() + " " + mill() + " " + pb.string() +
                                  " --json 2>" + (dir / "err.txt").string());
  EXPECT_EQ(r.exit_code, 0) << r.output << read_file(dir / "err.txt");
  return json::parse(r.output, nullptr, false);
}

// The bolt-hole loop plunges to Z-3 and retracts along the same line six
// times. B plunges at F600 instead of F300: the same path, so the nearest
// point along B's path is never more than a rounding away. Before, the
// search took B's retract for A's plunge: "max 2.9400 mm" where both reach
// Z-3.000.
TEST(DiffPath, PathThatRevisitsAPlaceHasNoFalseDifference) {
  const auto dir = temp_dir("diff_path_revisit");
  std::string faster = read_file(mill() + "/contour.nc");
  const std::size_t at = faster.find("G1 Z-3 F300");
  ASSERT_NE(at, std::string::npos);
  faster.replace(at, 11, "G1 Z-3 F600");
  const json d = diff_run(dir, read_file(mill() + "/contour.nc"), faster);
  ASSERT_TRUE(d.is_object());
  const json& path = d["path"];
  EXPECT_NEAR(path["length_a_mm"].get<double>(), path["length_b_mm"].get<double>(), 1e-3) << path.dump(1);
  EXPECT_LE(path["max_mm"].get<double>(), 1e-3) << path.dump(1);
  EXPECT_LE(path["mean_mm"].get<double>(), 1e-4) << path.dump(1);
  EXPECT_LT(d["delta_s"].get<double>(), -2) << "six plunges of 5 mm twice as fast";
}

// A real difference at a place the path revisits is still found: B drills
// its holes 0.5 mm less deep, so A's bottom is 0.5 mm from B's path, on the
// line of the plunge (line 5), and nowhere else does the path differ.
TEST(DiffPath, DifferenceAtARevisitedPlaceIsFound) {
  const auto dir = temp_dir("diff_path_shallow");
  std::string shallow = read_file(mill() + "/contour.nc");
  const std::size_t at = shallow.find("G1 Z-3 F300");
  ASSERT_NE(at, std::string::npos);
  shallow.replace(at, 11, "G1 Z-2.5 F300");
  const json d = diff_run(dir, read_file(mill() + "/contour.nc"), shallow);
  ASSERT_TRUE(d.is_object());
  const json& path = d["path"];
  EXPECT_NEAR(path["max_mm"].get<double>(), 0.5, 1e-3) << path.dump(1);
  ASSERT_FALSE(path["largest"].empty()) << path.dump(1);
  EXPECT_EQ(path["largest"][0]["line_a"], 5) << path.dump(1);
  EXPECT_NEAR(path["largest"][0]["a"][2].get<double>(), -3, 1e-3) << path.dump(1);
  EXPECT_NEAR(path["largest"][0]["b"][2].get<double>(), -2.5, 1e-3) << path.dump(1);
  for (std::size_t i = 1; i < path["largest"].size(); ++i) {  // the other lines of A: on B's path
    if (path["largest"][i]["line_a"] != 7 && path["largest"][i]["line_a"] != 6) {
      EXPECT_LE(path["largest"][i]["distance_mm"].get<double>(), 1e-3) << path.dump(1);
    }
  }
}

}  // namespace
}  // namespace nck::app::testing
