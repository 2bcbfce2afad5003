// nck diff pairs blocks by identity (issue 48 item 3): lines inserted into
// a program shift no block onto another.
#include <gtest/gtest.h>

#include "cli_helpers.hpp"

namespace nck::app::testing {
namespace {

using nlohmann::json;

std::string contour() { return read_file(mill() + "/contour.nc"); }

// `text` with `lines` inserted before its line `before` (1-based).
std::string inserted(const std::string& text, std::size_t before, const std::string& lines) {
  std::size_t at = 0;
  for (std::size_t n = 1; n < before; ++n) at = text.find('\n', at) + 1;
  return text.substr(0, at) + lines + text.substr(at);
}

// nck diff --run of two programs on the mill, --json.
json diff_run(const std::filesystem::path& dir, const std::string& a, const std::string& b) {
  const auto pa = write(dir / "a.nc", a), pb = write(dir / "b.nc", b);
  const CliResult r = run_nck_raw("diff --run " + mill() + " " + pa.string() + " " + mill() + " " + pb.string() +
                                  " --json 2>" + (dir / "err.txt").string());
  EXPECT_EQ(r.exit_code, 0) << r.output << read_file(dir / "err.txt");
  return json::parse(r.output, nullptr, false);
}

json row(const json& diff, const std::string& key) {
  for (const json& r : diff["channels"][0]["blocks"])
    if (r["key"] == key) return r;
  return json::object();
}

// contour.nc and the same program with two comment lines before its local
// subroutine: every block (HOLE's included) is paired with its twin, two
// lines further down, and nothing differs. Before, the blocks were paired
// by line: "line 33" (the helix in A) against a rapid of B.
TEST(DiffIdentity, InsertedLinesPairEveryBlockWithItsTwin) {
  const auto dir = temp_dir("diff_identity_twins");
  const json d = diff_run(dir, contour(), inserted(contour(), 3, "; one more comment\n; and another\n"));
  ASSERT_TRUE(d.is_object());
  const json& blocks = d["channels"][0]["blocks"];
  ASSERT_GE(blocks.size(), 20u) << blocks.dump(1);
  for (const json& r : blocks) {
    EXPECT_TRUE(r["a_s"].is_number() && r["b_s"].is_number()) << r.dump();
    EXPECT_EQ(r["delta_s"].get<double>(), 0) << r.dump();
    EXPECT_EQ(r["line_b"].get<int>(), r["line_a"].get<int>() + 2) << r.dump();
    EXPECT_FALSE(r.contains("text_b")) << r.dump();
  }
  const json helix = row(d, "N190 G3 X15 Y0 Z-3 I-15 J0 F900");
  EXPECT_EQ(helix["line_a"], 33) << blocks.dump(1);
  EXPECT_EQ(helix["n"], 190) << helix.dump();
  EXPECT_GT(helix["a_s"].get<double>(), 6) << helix.dump();
  // HOLE's two `G0 Z2` are told apart by their pass
  EXPECT_EQ(row(d, "HOLE: G0 Z2")["line_a"], 4) << blocks.dump(1);
  EXPECT_EQ(row(d, "HOLE: G0 Z2 #2")["line_a"], 7) << blocks.dump(1);
  EXPECT_EQ(d["delta_s"].get<double>(), 0);
  EXPECT_LE(d["path"]["max_mm"].get<double>(), 1e-3) << d["path"].dump(1);
}

// A --final of `program` on the mill.
std::string final_of(const std::filesystem::path& dir, const std::string& name, const std::string& program) {
  const auto prog = write(dir / (name + ".nc"), program);
  const std::string out = (dir / (name + ".json")).string();
  const CliResult r = run_nck("run " + mill() + " " + prog.string() + " --final " + out);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return out;
}

// A block whose text changed pairs by its N number (one without stays
// alone); the table names blocks by N and text.
TEST(DiffIdentity, ChangedBlockPairsByItsNumberAndRowsShowText) {
  const auto dir = temp_dir("diff_identity_n");
  const std::string a = final_of(dir, "a", "N10 G90 G0 X0 Y0 Z0\nN20 G1 X100 F1200\nN30 G1 Y50 F1200\nG1 X0 F1200\nM30\n");
  const std::string b = final_of(dir, "b", "N10 G90 G0 X0 Y0 Z0\n; slower\nN20 G1 X100 F600 ; half\nN30 G1 Y50 F1200\nG1 X0 F2400\nM30\n");
  const CliResult r = run_nck_raw("diff " + a + " " + b + " --json 2>/dev/null");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const json d = json::parse(r.output, nullptr, false);
  const json n20 = row(d, "N20 G1 X100 F1200");
  EXPECT_EQ(n20["text_b"], "N20 G1 X100 F600") << d.dump(1);
  EXPECT_EQ(n20["line_a"], 2) << n20.dump();
  EXPECT_EQ(n20["line_b"], 3) << n20.dump();
  EXPECT_NEAR(n20["delta_s"].get<double>(), 5.0, 0.1) << "100 mm at 10 mm/s instead of 20";
  const json n30 = row(d, "N30 G1 Y50 F1200");
  EXPECT_EQ(n30["line_b"], 4) << d.dump(1);
  EXPECT_NEAR(n30["delta_s"].get<double>(), 0, 1e-9) << n30.dump();
  // a changed block without N number: each side shows it alone
  EXPECT_TRUE(row(d, "G1 X0 F1200")["b_s"].is_null()) << d.dump(1);
  EXPECT_TRUE(row(d, "G1 X0 F2400")["a_s"].is_null()) << d.dump(1);
  const CliResult table = run_nck_raw("diff " + a + " " + b + " 2>/dev/null");
  EXPECT_NE(table.output.find("  N20 G1 X100 F1200 "), std::string::npos) << table.output;
  EXPECT_EQ(table.output.find("line 2"), std::string::npos) << table.output;
}

// Final states without identities (an older nck) still pair by line.
TEST(DiffIdentity, FinalStatesWithoutTextPairByLine) {
  const auto dir = temp_dir("diff_identity_old");
  const std::string program = "G90 G0 X0 Y0 Z0\nG1 X100 F1200\nM30\n";
  json f = json::parse(read_file(final_of(dir, "a", program)));
  for (json& b : f["time_by_cause"]["channels"][0]["blocks"]) b.erase("text"), b.erase("pass"), b.erase("sub");
  const auto old = write(dir / "old.json", f.dump());
  const CliResult r = run_nck_raw("diff " + old.string() + " " + old.string() + " --json 2>/dev/null");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const json d = json::parse(r.output, nullptr, false);
  EXPECT_NEAR(row(d, "line 2")["a_s"].get<double>(), 5.0, 0.2) << d.dump(1);
  EXPECT_EQ(row(d, "line 2")["line_b"], 2) << d.dump(1);
}

}  // namespace
}  // namespace nck::app::testing
