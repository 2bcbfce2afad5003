// Synchronous operation (issue 14; spindle_link seed, FCT-S1 2.8.3 and
// 2.2.5.2) through the nck binary: the seed's three programs on
// the twin-spindle machine, slaves following speed and M19, own overrides,
// path-axis slaves every cycle, the rules as errors, links dissolved at
// abort and program end, two channels sharing spindles.
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>

#include "spindle_path_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;

const std::string kTwin = "twin-spindle";
constexpr double kTraceMm = 2e-6;  // the trace prints 6 decimals: two roundings

std::vector<json> links(const PathRun& r) { return r.of("link"); }

const json* error_of(const PathRun& r) {
  for (const json& e : r.events)
    if (e["ev"] == "error") return &e;
  return nullptr;
}

// Every speed_reached event of spindle s.
double reached_t(const PathRun& r, const std::string& s) {
  for (const json& e : r.of("speed_reached"))
    if (e["spindle"] == s) return e["t"].get<double>();
  return -1;
}

class SeedPrograms : public ::testing::TestWithParam<const char*> {};

// S1000 M3 on the main spindle S (= S1) turns S1, S2 and S3; each runs up
// with its own acceleration (S1 15000, S2 20000, S3 10000 deg/s^2:
// rpm(t) = a t / 6), and the block after waits for the slowest.
TEST_P(SeedPrograms, RunVerbatimAndTurnAllThreeSpindles) {
  const PathRun r = run_example_program(kTwin, GetParam(), std::string("seed_") + GetParam());
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  EXPECT_EQ(error_of(r), nullptr);
  const auto l = links(r);
  ASSERT_EQ(l.size(), 2u);
  EXPECT_EQ(l[0]["group"], 1);
  EXPECT_EQ(l[0]["on"], true);
  EXPECT_EQ(l[0]["reason"], "program");
  EXPECT_EQ(l[0]["pairs"], json::parse(R"([["S2","S1"],["S3","S1"]])"));
  EXPECT_EQ(l[1]["on"], false);
  EXPECT_EQ(l[1]["reason"], "program");
  const double t30 = r.line_t(3);
  ASSERT_GE(t30, 0);
  EXPECT_NEAR(r.at(t30 + 0.2, "S1.rpm"), 15000 * 0.2 / 6, 5.0);
  EXPECT_NEAR(r.at(t30 + 0.2, "S2.rpm"), 20000 * 0.2 / 6, 5.0);
  EXPECT_NEAR(r.at(t30 + 0.2, "S3.rpm"), 10000 * 0.2 / 6, 5.0);
  // The speed waits cover every spindle of the link: N40 starts only after
  // the slowest (S3) reached its speed.
  const double s1 = reached_t(r, "S1"), s2 = reached_t(r, "S2"), s3 = reached_t(r, "S3");
  ASSERT_GT(s1, 0);
  ASSERT_GT(s2, 0);
  ASSERT_GT(s3, 0);
  EXPECT_LT(s2, s1);
  EXPECT_LT(s1, s3);
  EXPECT_GE(r.line_t(4), s3);
  // The program ends once S3 is within 10 % of its speed: S1 and S2 are at
  // 1000 rpm, S3's set point is still on its ramp (one row = one cycle).
  const double t_end = r.rows.back().at("t");
  EXPECT_DOUBLE_EQ(r.rows.back().at("S1.rpm"), 1000.0);
  EXPECT_DOUBLE_EQ(r.rows.back().at("S2.rpm"), 1000.0);
  EXPECT_NEAR(r.rows.back().at("S3.rpm"), 10000 * (t_end - t30) / 6, 2.0);
  EXPECT_GT(r.rows.back().at("S3.rpm"), 900.0);
  int waits = 0;
  for (const json& e : r.of("wait"))
    if (e["line"] == 3 && e["reason"] == "speed_reached") ++waits;
  EXPECT_EQ(waits, 3);
  EXPECT_EQ(r.cli.output.find("930001"), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(Link, SeedPrograms, ::testing::Values("link_names.nc", "link_on_off.nc", "link_nbr.nc"));

// A --plc override of one spindle acts on it alone, master or slave.
TEST(Link, OverrideOfOneSpindleDoesNotActOnTheOther) {
  for (const std::string who : {"S1", "S2"}) {
    const auto dir = temp_dir("link_ovr_" + who);
    std::ofstream(dir / "o.plc") << "0.0 override " << who << " 50\n";
    const std::string ex = root() + "/examples/twin-spindle";
    CliResult c = run_nck("run " + ex + " " + ex + "/link_names.nc --events " + (dir / "e.jsonl").string() +
                          " --trace " + (dir / "t.csv").string() + " --plc " + (dir / "o.plc").string());
    const PathRun r = read_run(std::move(c), dir);
    ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
    const Row& last = r.rows.back();
    EXPECT_DOUBLE_EQ(last.at("S1.rpm"), who == "S1" ? 500.0 : 1000.0);
    EXPECT_DOUBLE_EQ(last.at("S2.rpm"), who == "S2" ? 500.0 : 1000.0);
    // S3 is not overridden: still on its own ramp (10000 deg/s^2) at the end
    EXPECT_NEAR(last.at("S3.rpm"), 10000 * (last.at("t") - r.line_t(3)) / 6, 2.0);
  }
}

// A spindle feedhold on the master does not stop the slave, and the
// reverse: S600 is reached at 0.24 s (S1) / 0.18 s (S2); the feedhold at
// 0.5 s brakes that spindle alone to 0 within 0.24 s.
TEST(Link, FeedholdOfOneSpindleDoesNotStopTheOther) {
  for (const std::string who : {"S1", "S2"}) {
    const auto dir = temp_dir("link_hold_" + who);
    std::ofstream(dir / "h.plc") << "0.5 spindle_feedhold " << who << " on\n";
    std::ofstream(dir / "p.nc") << "#ENABLE AX LINK\nS600 M3\n#TIME 1\nM30\n";
    const std::string ex = root() + "/examples/twin-spindle";
    CliResult c = run_nck("run " + ex + " " + (dir / "p.nc").string() + " --events " + (dir / "e.jsonl").string() +
                          " --trace " + (dir / "t.csv").string() + " --plc " + (dir / "h.plc").string());
    const PathRun r = read_run(std::move(c), dir);
    ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
    EXPECT_DOUBLE_EQ(r.at(0.45, "S1.rpm"), 600.0);
    EXPECT_DOUBLE_EQ(r.at(0.45, "S2.rpm"), 600.0);
    EXPECT_DOUBLE_EQ(r.at(0.9, "S1.rpm"), who == "S1" ? 0.0 : 600.0);
    EXPECT_DOUBLE_EQ(r.at(0.9, "S2.rpm"), who == "S2" ? 0.0 : 600.0);
  }
}

// twin.nc: group 0 from the channel list (Y2=Y1, S2=S1), a gantry pair, an
// NBR group, a mirrored pair.
TEST(Link, TwinProgramCouplesAxesAndSpindles) {
  const PathRun r = run_example_program(kTwin, "twin.nc", "link_twin");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const auto l = links(r);
  ASSERT_EQ(l.size(), 8u);  // four groups on and off
  EXPECT_EQ(l[0]["group"], 0);
  EXPECT_EQ(l[0]["pairs"], json::parse(R"([["Y2","Y1"],["S2","S1"]])"));
  EXPECT_EQ(l[2]["pairs"], json::parse(R"([["Z2","Z1"]])"));
  EXPECT_EQ(l[4]["pairs"], json::parse(R"([["S3","S1"]])"));
  EXPECT_EQ(l[6]["pairs"], json::parse(R"([["C2","C1"]])"));
  for (std::size_t i = 0; i < l.size(); ++i) EXPECT_EQ(l[i]["on"], i % 2 == 0);
  auto rows_between = [&](const json& on, const json& off) {
    return std::pair{r.index(on["t"].get<double>()), r.index(off["t"].get<double>())};
  };
  // Y2 keeps its 20 mm to Y1 in every cycle of the link: 20 -> 70.
  auto [a0, b0] = rows_between(l[0], l[1]);
  for (std::size_t k = a0; k < b0; ++k) ASSERT_NEAR(r.rows[k].at("Y2") - r.rows[k].at("Y1"), 20.0, kTraceMm) << k;
  EXPECT_NEAR(r.rows[b0].at("Y2"), 70.0, 1e-9);
  // S2 turned with S1 at 800 rpm, then both went to 90 deg (M19).
  const double t40 = r.block_t(40);
  EXPECT_DOUBLE_EQ(r.at(t40, "S1.rpm"), 800.0);
  EXPECT_DOUBLE_EQ(r.at(t40, "S2.rpm"), 800.0);
  EXPECT_NEAR(r.at(r.block_t(60), "S1.pos"), 90.0, 1e-6);
  EXPECT_NEAR(r.at(r.block_t(60), "S2.pos"), 90.0, 1e-6);
  // Gantry: Z2 stood 5 mm above Z1 and keeps it: Z1 -10 -> Z2 -5.
  auto [a2, b2] = rows_between(l[2], l[3]);
  for (std::size_t k = a2; k < b2; ++k) ASSERT_NEAR(r.rows[k].at("Z2") - r.rows[k].at("Z1"), 5.0, kTraceMm) << k;
  EXPECT_NEAR(r.rows[b2].at("Z2"), -5.0, 1e-9);
  // NBR 17=6: S3 turns with S1 at M4 1200 rpm.
  const double t130 = r.block_t(130), t140 = r.block_t(140);
  int m4 = 0;
  for (const json& e : r.of("spindle"))
    if (e["t"] == t130 && e["mode"] == "rotate" && e["rpm"] == -1200.0) ++m4;
  EXPECT_EQ(m4, 2);  // S1 and S3
  // M5 comes when S3 (10000 deg/s^2, the slower) is within 10 %: S1 is at
  // speed, S3 still on its ramp; S2 was left at M19, it is not in group 3.
  const double before_m5 = t140 - kDt;
  EXPECT_DOUBLE_EQ(r.at(before_m5, "S1.rpm"), -1200.0);
  EXPECT_NEAR(r.at(before_m5, "S3.rpm"), -10000 * (before_m5 - t130) / 6, 2.0);
  EXPECT_LT(r.at(before_m5, "S3.rpm"), -1080.0);
  EXPECT_DOUBLE_EQ(r.at(before_m5, "S2.rpm"), 0.0);
  // Mirrored C2 = -C1: C1 0 -> 90, C2 0 -> -90.
  auto [a4, b4] = rows_between(l[6], l[7]);
  for (std::size_t k = a4; k < b4; ++k) ASSERT_NEAR(r.rows[k].at("C2"), -r.rows[k].at("C1"), kTraceMm) << k;
  EXPECT_NEAR(r.rows[b4].at("C1"), 90.0, 1e-9);
  EXPECT_NEAR(r.rows[b4].at("C2"), -90.0, 1e-9);
}

// The report lists the coupling periods: group 2 (gantry) from its link on
// to its link off, its pair as "Z2 ← Z1".
TEST(Link, ReportMarksCouplingPeriods) {
  const auto dir = temp_dir("link_report");
  const std::string ex = root() + "/examples/twin-spindle";
  const CliResult c = run_nck("run " + ex + " " + ex + "/twin.nc --events " + (dir / "e.jsonl").string() +
                              " --report " + (dir / "r.html").string());
  ASSERT_EQ(c.exit_code, 0) << c.output;
  double on = -1, off = -1;
  for (const json& e : read_jsonl(dir / "e.jsonl"))
    if (e["ev"] == "link" && e["group"] == 2) (e["on"] ? on : off) = e["t"].get<double>();
  const std::string html = read_file(dir / "r.html");
  EXPECT_NE(html.find("coupling periods"), std::string::npos);
  // the pairs as slave ← master, as the event table writes them (issue 48 item 5: not raw JSON)
  const std::string row = fmt::format("<tr><td>1</td><td>2</td><td>Z2 \u2190 Z1</td><td>{:.3f}</td><td>{:.3f}</td><td>program</td></tr>", on, off);
  EXPECT_NE(html.find(row), std::string::npos) << row;
}

// M19 sends master and slave to the same absolute position, each with its
// own dynamics: from 800 rpm S2 (20000 deg/s^2) is in position before S1
// (15000 deg/s^2).
TEST(Link, M19TakesMasterAndSlaveToTheSamePosition) {
  const PathRun r = run_text(kTwin, "N10 #ENABLE AX LINK\nN20 S800 M3\nN30 S.POS=200 M19 S300\nN40 M30\n", "link_m19");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const double t40 = r.block_t(40);
  EXPECT_NEAR(r.at(t40, "S1.pos"), 200.0, 1e-6);
  EXPECT_NEAR(r.at(t40, "S2.pos"), 200.0, 1e-6);
  int in_position = 0;
  for (const json& e : r.of("wait"))
    if (e["line"] == 3 && e["reason"] == "in_position") ++in_position;
  EXPECT_EQ(in_position, 2);
  // The spindles stop turning at different times.
  std::size_t s1_stop = 0, s2_stop = 0;
  for (std::size_t k = r.index(r.block_t(30)); k < r.rows.size(); ++k) {
    if (!s1_stop && r.rows[k].at("S1.pos") == 200.0) s1_stop = k;
    if (!s2_stop && r.rows[k].at("S2.pos") == 200.0) s2_stop = k;
  }
  EXPECT_NE(s1_stop, s2_stop);
}

// A copy of the twin-spindle machine with a linear axis B (logical 9).
std::string machine_with_b(const std::string& name) {
  const auto dir = temp_dir(name) / "twin";
  std::filesystem::copy(root() + "/examples/twin-spindle", dir, std::filesystem::copy_options::recursive);
  std::string b = read_file(dir / "y2.lis");
  b.replace(b.find("kopf.achs_nr                      4"), 35, "kopf.achs_nr                      9");
  b.replace(b.find("Y2 "), 3, "B  ");
  std::ofstream(dir / "b.lis") << b;
  std::string st = read_file(dir / "startup.lis");
  st.replace(st.find("zahl_mds              10"), 24, "zahl_mds              11");
  st.insert(st.rfind("Ende"), "achs_mds[10]          b.lis\n");
  std::ofstream(dir / "startup.lis") << st;
  std::string ch = read_file(dir / "channel1.lis");
  ch.insert(ch.find("#\n# S is"), "gruppe[0].achse[7].bezeichnung    B\ngruppe[0].achse[7].log_achs_nr    9\n");
  std::ofstream(dir / "channel1.lis") << ch;
  return dir.string();
}

// The seed: within one pair no mixed axis types; mixed pairs in one group are fine.
TEST(Link, MixedPairRejectedMixedGroupAccepted) {
  const std::string m = machine_with_b("link_mixed");
  const PathRun bad = run_text(m, "N10 G0 X0\n#SET AX LINK [1, B=S, S2=X]\nM30\n", "link_mixed_bad");
  EXPECT_EQ(bad.cli.exit_code, 1);
  ASSERT_NE(error_of(bad), nullptr) << bad.cli.output;
  EXPECT_EQ((*error_of(bad))["id"], 20469);
  EXPECT_EQ((*error_of(bad))["line"], 2);
  // The allowed one, enabled: B follows X, S2 follows S.
  const PathRun ok = run_text(m, "#SET AX LINK [1, B=X, S2=S]\n#ENABLE AX LINK[1]\nG1 X30 F3000\nS500 M3\nM30\n",
                              "link_mixed_ok");
  ASSERT_EQ(ok.cli.exit_code, 0) << ok.cli.output;
  EXPECT_NEAR(ok.rows.back().at("B"), 30.0, 1e-9);
  EXPECT_DOUBLE_EQ(ok.rows.back().at("S2.rpm"), 500.0);
}

struct RuleCase {
  const char* name;
  const char* program;
  int id;
  int line;
};

class LinkRules : public ::testing::TestWithParam<RuleCase> {};

TEST_P(LinkRules, AnswerTheirErrorWithLine) {
  const RuleCase& c = GetParam();
  const PathRun r = run_text(kTwin, c.program, std::string("link_rule_") + c.name);
  EXPECT_EQ(r.cli.exit_code, 1) << r.cli.output;
  const json* e = error_of(r);
  ASSERT_NE(e, nullptr) << r.cli.output;
  EXPECT_EQ((*e)["id"], c.id) << r.cli.output;
  EXPECT_EQ((*e)["line"], c.line);
  EXPECT_EQ(r.cli.output.find("930001"), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(
    Link, LinkRules,
    ::testing::Values(
        RuleCase{"slave_axis", "#ENABLE AX LINK\nG1 Y2=10 F1000\nM30\n", 930406, 2},
        RuleCase{"slave_spindle", "#ENABLE AX LINK\nS2[M3 REV100]\nM30\n", 930406, 2},
        RuleCase{"main_spindle_linked", "#ENABLE AX LINK\n#MAIN SPINDLE [S2]\nM30\n", 930404, 2},
        RuleCase{"names_changed", "#SET AX LINK[1, S2=S]\n#MAIN SPINDLE [S3]\n#ENABLE AX LINK[1]\nM30\n", 930405, 3},
        RuleCase{"undefined", "#ENABLE AX LINK[5]\nM30\n", 930400, 1},
        RuleCase{"not_enabled", "#DISABLE AX LINK[3]\nM30\n", 930408, 1},
        RuleCase{"enabled_twice", "#ENABLE AX LINK\n#ENABLE AX LINK[0]\nM30\n", 930401, 2},
        RuleCase{"redefine_enabled", "#SET AX LINK[1, S3=S]\n#AX LINK ON[1]\n#SET AX LINK[1, S2=S]\nM30\n", 930401, 3},
        RuleCase{"group_range", "#SET AX LINK[40, S3=S]\nM30\n", 930402, 1},
        RuleCase{"slave_twice", "#SET AX LINK[1, S3=S, S3=S2]\nM30\n", 20476, 1},
        RuleCase{"slave_main_axis", "#SET AX LINK[1, Z1=Y2]\n#ENABLE AX LINK[1]\nM30\n", 20467, 2},
        RuleCase{"nbr_unknown", "#AX LINK NBR[1, 12=6]\nM30\n", 930403, 1},
        RuleCase{"slave_already_slave", "#AX LINK[1, S2=S3]\n#AX LINK ON\n#AX LINK ON[1]\nM30\n", 21283, 3},
        RuleCase{"gantry_limits", "#SET AX LINK[1, [Z2=Z1, G, 0.5, 0.1]]\nM30\n", 930409, 1},
        RuleCase{"spindle_scaled", "#SET AX LINK[1, [S2=S, 2, 1]]\nM30\n", 930409, 1}),
    [](const ::testing::TestParamInfo<RuleCase>& p) { return std::string(p.param.name); });

// Group 0 belongs to the channel list: the program cannot define it.
TEST(Link, GroupZeroCannotBeRedefined) {
  const PathRun r = run_text(kTwin, "#SET AX LINK[0, S3=S]\nM30\n", "link_group0");
  EXPECT_EQ(r.cli.exit_code, 1);
  const json* e = error_of(r);
  ASSERT_NE(e, nullptr) << r.cli.output;
  EXPECT_EQ((*e)["line"], 1);
  EXPECT_NE((*e)["msg"].get<std::string>().find("group 0"), std::string::npos) << (*e)["msg"];
  EXPECT_NE((*e)["id"], 930001);
}

// An abort dissolves the links: the error, then the link off with "abort".
TEST(Link, AbortDissolvesTheLink) {
  const PathRun r = run_text(kTwin, "#ENABLE AX LINK\nS500 M3\nS2[M5]\nM30\n", "link_abort");
  EXPECT_EQ(r.cli.exit_code, 1);
  const auto l = links(r);
  ASSERT_EQ(l.size(), 2u);
  EXPECT_EQ(l[1]["on"], false);
  EXPECT_EQ(l[1]["reason"], "abort");
  EXPECT_EQ(l[1]["group"], 0);
  ASSERT_NE(error_of(r), nullptr);
  EXPECT_LE((*error_of(r))["t"].get<double>(), l[1]["t"].get<double>());
}

// M30 dissolves the links, unless P-CHAN-00105 keeps them (then --final lists them).
TEST(Link, ProgramEndDissolvesUnlessPreserved) {
  const std::string program = "#AX LINK NBR[2, 17=6]\n#AX LINK ON[2]\nS300 M3\nM30\n";
  const PathRun plain = run_text(kTwin, program, "link_end");
  ASSERT_EQ(plain.cli.exit_code, 0) << plain.cli.output;
  ASSERT_EQ(links(plain).size(), 2u);
  EXPECT_EQ(links(plain)[1]["reason"], "program_end");
  const auto m = patched_example(kTwin, "link_keep", "channel1.lis", "synchro_data.preserve_coupling_after_prog_end 1");
  const auto dir = temp_dir("link_keep_run");
  const PathRun kept = run_text(m.dir.string(), program, "link_keep_run2", "--final " + (dir / "f.json").string());
  ASSERT_EQ(kept.cli.exit_code, 0) << kept.cli.output;
  ASSERT_EQ(links(kept).size(), 1u);
  const json f = json::parse(read_file(dir / "f.json"));
  ASSERT_EQ(f["links"].size(), 1u);
  EXPECT_EQ(f["links"][0]["group"], 2);
  EXPECT_EQ(f["links"][0]["ch"], 1);
  EXPECT_EQ(f["links"][0]["pairs"], json::parse(R"([["S3","S1"]])"));
  EXPECT_DOUBLE_EQ(kept.rows.back().at("S3.rpm"), 300.0);
}

// Two programs side by side on the two-channel example, outputs into dir.
PathRun run_two_channels(const std::filesystem::path& dir, const std::string& program1, const std::string& program2) {
  const std::string ex = root() + "/examples/two-channel";
  CliResult c = run_nck("run " + ex + " " + program1 + " " + program2 + " --events " + (dir / "e.jsonl").string() +
                        " --trace " + (dir / "t.csv").string());
  return read_run(std::move(c), dir);
}

// FCT-S1 2.2.5.2: two channels share S1 and S2. Channel 1 links S3 to its
// main spindle S (= S2); channel 2 commands S1 (not linked) meanwhile.
TEST(Link, TwoChannelsShareUnlinkedSpindles) {
  const auto dir = temp_dir("link_two");
  const std::string ex = root() + "/examples/two-channel";
  const PathRun r = run_two_channels(dir, ex + "/link_ch1.nc", ex + "/link_ch2.nc");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  EXPECT_EQ(error_of(r), nullptr);
  ASSERT_EQ(links(r).size(), 2u);
  EXPECT_EQ(links(r)[0]["ch"], 1);
  EXPECT_EQ(links(r)[0]["pairs"], json::parse(R"([["S3","S2"]])"));
  // S3 is a PLC spindle: its M3 goes out in channel 1 with S2's.
  bool s3_m3 = false;
  for (const json& e : r.of("plc_out"))
    if (e["spindle"] == "S3" && e["fn"] == "M3") s3_m3 = e["ch"] == 1;
  EXPECT_TRUE(s3_m3);
  // channel 2 ran S1 at M4 600 while channel 1's link was on
  const double on = links(r)[0]["t"], off = links(r)[1]["t"];
  bool s1_in_link = false;
  for (std::size_t k = r.index(on); k < r.index(off); ++k)
    if (r.rows[k].at("S1.rpm") == -600.0) s1_in_link = true;
  EXPECT_TRUE(s1_in_link);
  // S3 (6000 deg/s^2) needs 6000 deg/s / 6000 deg/s^2 = 1 s to 1000 rpm
  EXPECT_LT(r.at(on + 0.5, "S3.rpm"), 1000.0);
  EXPECT_DOUBLE_EQ(r.at(on + 1.1, "S3.rpm"), 1000.0);
}

// A linked spindle may only be commanded by the channel that enabled the link.
TEST(Link, LinkedSpindleFromOtherChannelIsAnError) {
  const auto dir = temp_dir("link_other");
  std::ofstream(dir / "c1.nc") << "#SET AX LINK[1, S1=S]\n#ENABLE AX LINK[1]\nS400 M3\n#TIME 1\nM30\n";
  std::ofstream(dir / "c2.nc") << "#TIME 0.3\nS1[M4 REV200]\nM30\n";
  const PathRun r = run_two_channels(dir, (dir / "c1.nc").string(), (dir / "c2.nc").string());
  EXPECT_EQ(r.cli.exit_code, 1);
  const json* e = error_of(r);
  ASSERT_NE(e, nullptr) << r.cli.output;
  EXPECT_EQ((*e)["id"], 930407);
  EXPECT_EQ((*e)["ch"], 2);
  EXPECT_EQ((*e)["line"], 2);
  EXPECT_EQ((*e)["spindle"], "S1");
  // channel 1 went on: S1 kept 400 rpm
  EXPECT_DOUBLE_EQ(r.rows.back().at("S1.rpm"), 400.0);
}

// Nor may another channel couple it while the link is on.
TEST(Link, CouplingASpindleLinkedInAnotherChannelIsAnError) {
  const auto dir = temp_dir("link_other_enable");
  std::ofstream(dir / "c1.nc") << "#SET AX LINK[1, S1=S]\n#ENABLE AX LINK[1]\n#TIME 1\nM30\n";
  std::ofstream(dir / "c2.nc") << "#TIME 0.3\n#SET AX LINK[2, S1=S]\n#ENABLE AX LINK[2]\nM30\n";
  const PathRun r = run_two_channels(dir, (dir / "c1.nc").string(), (dir / "c2.nc").string());
  EXPECT_EQ(r.cli.exit_code, 1);
  const json* e = error_of(r);
  ASSERT_NE(e, nullptr) << r.cli.output;
  EXPECT_EQ((*e)["id"], 930407);
  EXPECT_EQ((*e)["ch"], 2);
  EXPECT_EQ((*e)["line"], 3);
  // channel 1's link stays until its M30
  const auto l = links(r);
  ASSERT_EQ(l.size(), 2u);
  EXPECT_EQ(l[1]["ch"], 1);
  EXPECT_EQ(l[1]["reason"], "program_end");
  EXPECT_NEAR(l[1]["t"].get<double>(), 1.0, 0.01);
}

}  // namespace
}  // namespace nck::app
