// `nck check MACHINE PROGRAM`: every mistake of a program in one call, with
// the ID and line `nck run` gives each, as text and as JSON (--json).
#include <gtest/gtest.h>

#include <cstdlib>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <utility>

#include "cli_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;

const std::string kMistakes = "/examples/mill/check_mistakes.nc";

// The six mistakes of examples/mill/check_mistakes.nc: ID and line.
const std::vector<std::pair<std::string, int>> kSix = {
    {"930002", 6}, {"930004", 8}, {"920005", 9}, {"920022", 10}, {"930003", 11}, {"920044", 13}};

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

TEST(CheckCommand, ListsAllSixMistakesWithValues) {
  const std::string prog = root() + kMistakes;
  CliResult r = run_nck("check " + mill() + " " + prog);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  for (const auto& [id, line] : kSix)
    EXPECT_NE(r.output.find(prog + ":" + std::to_string(line) + ":"), std::string::npos) << id << "\n" << r.output;
  for (const auto& [id, line] : kSix) EXPECT_NE(r.output.find("error " + id + ":"), std::string::npos) << id;
  EXPECT_NE(r.output.find("start radius 5.0000 mm, end radius 15.0000 mm, difference 10.0000 mm"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("X 650.0000 is outside the software limits [-500.0000, 500.0000]: 150.0000 mm beyond"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("6 error(s), 0 warning(s)"), std::string::npos) << r.output;
}

// Each mistake alone (the other five lines made comments, so the lines stay
// where they are): `nck run` stops with the same ID at the same line.
TEST(CheckCommand, EachMistakeHasTheIdAndLineOfTheRun) {
  const std::vector<std::string> text = lines_of(read_file(root() + kMistakes));
  const auto dir = temp_dir("check_vs_run");
  for (const auto& [id, line] : kSix) {
    std::string alone;
    for (std::size_t i = 0; i < text.size(); ++i) {
      bool other = false;
      for (const auto& [other_id, other_line] : kSix) other = other || (other_line != line && other_line == int(i) + 1);
      alone += (other ? "; (another mistake)" : text[i]) + "\n";
    }
    const std::string prog = write(dir / ("alone_" + id + ".nc"), alone).string();
    CliResult run = run_nck("run " + mill() + " " + prog + " --no-progress");
    EXPECT_EQ(run.exit_code, 1) << run.output;
    const std::string where = prog + ":" + std::to_string(line) + ": error " + id + ":";
    EXPECT_NE(run.output.find(where), std::string::npos) << where << "\n" << run.output;
    CliResult check = run_nck("check " + mill() + " " + prog);
    EXPECT_EQ(check.exit_code, 1) << check.output;
    EXPECT_NE(check.output.find(prog + ":" + std::to_string(line)), std::string::npos) << check.output;
    EXPECT_NE(check.output.find("error " + id + ":"), std::string::npos) << check.output;
    EXPECT_NE(check.output.find("1 error(s)"), std::string::npos) << check.output;
  }
}

TEST(CheckCommand, JsonListsTheDiagnosticsForCi) {
  const std::string prog = root() + kMistakes;
  CliResult r = run_nck_raw("check --json " + mill() + " " + prog + " 2>/dev/null");
  EXPECT_EQ(r.exit_code, 1);
  const nlohmann::json list = nlohmann::json::parse(r.output, nullptr, false);
  ASSERT_TRUE(list.is_array()) << r.output;
  ASSERT_EQ(list.size(), kSix.size()) << r.output;
  for (std::size_t i = 0; i < kSix.size(); ++i) {
    const nlohmann::json& d = list[i];
    EXPECT_EQ(std::to_string(d.at("id").get<int>()), kSix[i].first) << d;
    EXPECT_EQ(d.at("line").get<int>(), kSix[i].second) << d;
    EXPECT_EQ(d.at("severity"), "error") << d;
    EXPECT_EQ(d.at("file"), prog) << d;
    // a column is there only where it is known (the diagnostic's one shape: absent fields left out)
    EXPECT_GE(d.value("column", 1), 1) << d;
    EXPECT_FALSE(d.at("remedy").get<std::string>().empty()) << d;
    EXPECT_FALSE(d.at("message").get<std::string>().empty()) << d;
  }
  // docs/cli.md describes every field the binary writes.
  const std::string doc = read_file(root() + "/docs/cli.md");
  for (const auto& [key, value] : list[0].items())
    EXPECT_NE(doc.find("| `" + key + "` |"), std::string::npos) << key << " is not in docs/cli.md";
}

TEST(CheckCommand, ACleanProgramExitsZero) {
  CliResult r = run_nck("check " + mill() + " " + mill() + "/contour.nc");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  CliResult json = run_nck_raw("check --json " + mill() + " " + mill() + "/contour.nc 2>/dev/null");
  EXPECT_EQ(json.exit_code, 0);
  EXPECT_EQ(nlohmann::json::parse(json.output, nullptr, false), nlohmann::json::array()) << json.output;
}

TEST(CheckCommand, BadUsageExitsTwo) {
  CliResult missing = run_nck("check " + mill() + " /nonexistent/prog.nc");
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
  EXPECT_NE(missing.output.find("940001"), std::string::npos) << missing.output;
  const std::string p = mill() + "/contour.nc";
  CliResult too_many = run_nck("check " + mill() + " " + p + " " + p + " " + p);
  EXPECT_EQ(too_many.exit_code, 2) << too_many.output;
  CliResult no_machine = run_nck("check");
  EXPECT_EQ(no_machine.exit_code, 2) << no_machine.output;
}

// "line severity id" of every diagnostic line of a program file ("x.nc:12:5:
// warning 20685: ..." -> "12 warning 20685"); the column is the decoder's
// in the check and unknown in the run's events.
std::set<std::string> program_diagnostics(const std::string& output) {
  std::set<std::string> out;
  static const std::regex line(R"(\.nc:(\d+)(:\d+)?: (error|warning) (\d+):)");
  for (auto it = std::sregex_iterator(output.begin(), output.end(), line); it != std::sregex_iterator(); ++it)
    out.insert((*it)[1].str() + " " + (*it)[3].str() + " " + (*it)[4].str());
  return out;
}

// No false alarm: on every example of tests/golden (a clean program each),
// the check finds exactly what the run reports.
TEST(CheckCommand, ExamplesCheckAsTheyRun) {
  std::istringstream list(read_file(root() + "/tests/golden/examples.txt"));
  int compared = 0;
  for (std::string row; std::getline(list, row);) {
    std::vector<std::string> cell;
    std::istringstream cells(row);
    for (std::string c; std::getline(cells, c, '|');) cell.push_back(c);
    if (row.empty() || row[0] == '#' || cell.size() < 3 || cell[2].find("common:") != std::string::npos) continue;
    const std::string args = " " + cell[1] + " " + cell[2] + " ";
    const std::string extra = cell.size() > 3 ? cell[3] : "";
    // examples.txt's paths are relative to the repository.
    const std::string in_root = "cd '" + root() + "' && " + NCK_BINARY + " ";
    CliResult check = run_shell(in_root + "check" + args + " 2>&1");
    CliResult run = run_shell(in_root + "run" + args + extra + " --no-progress 2>&1");
    EXPECT_EQ(check.exit_code, run.exit_code) << row << "\n" << check.output << run.output;
    EXPECT_EQ(program_diagnostics(check.output), program_diagnostics(run.output)) << row << "\n" << check.output;
    ++compared;
  }
  EXPECT_GE(compared, 25);
}

// Seeded programs of good blocks with one to three mistakes among them
// (NCK_CHECK_PROGRAMS=N for more): whatever the run reports, error or
// warning, the check reports too, with the same ID and line.
TEST(CheckCommand, WhatARunReportsTheCheckReportsAtTheSameLine) {
  const std::vector<std::string> good = {"G17 G90 G71", "G0 X0 Y0 Z10", "G1 X10 F600", "G2 X20 Y0 I5 J0",
                                         "G1 Y10", "G3 X10 Y20 R10", "G41 D1", "G1 X30", "G1 Y30",
                                         "G40 G1 X0 Y0", "P1 = 5", "G1 X[P1]", "M3 S1000", "G4 X0.1", "M5"};
  const std::vector<std::string> bad = {"G1 X10", "G2 X40 Y0 I5 J0", "G444 X3", "G1 Y[P77]", "G0 X900",
                                        "L nosub.nc", "G2 X20 Y0 R2", "M3 S99999", "G41 D99", "G0 Y-800",
                                        "Z-9999", "G1 Q5"};
  const char* env = std::getenv("NCK_CHECK_PROGRAMS");
  const int count = env ? std::atoi(env) : 30;
  const auto dir = temp_dir("check_property");
  for (int seed = 0; seed < count; ++seed) {
    std::mt19937 rng(static_cast<unsigned>(seed));
    auto pick = [&](const std::vector<std::string>& from) { return from[rng() % from.size()]; };
    std::vector<std::string> lines;
    for (int i = 0, n = 3 + static_cast<int>(rng() % 10); i < n; ++i) lines.push_back(pick(good));
    for (int i = 0, n = 1 + static_cast<int>(rng() % 3); i < n; ++i)
      lines.insert(lines.begin() + static_cast<long>(rng() % (lines.size() + 1)), pick(bad));
    if (rng() % 10 != 0) lines.push_back("M30");
    std::string text;
    for (const std::string& l : lines) text += l + "\n";
    const std::string prog = write(dir / ("p" + std::to_string(seed) + ".nc"), text).string();
    CliResult run = run_nck("run " + mill() + " " + prog + " --no-progress --max-time 200");
    CliResult check = run_nck("check " + mill() + " " + prog);
    ASSERT_LE(check.exit_code, 2) << text << check.output;
    const std::set<std::string> in_run = program_diagnostics(run.output), in_check = program_diagnostics(check.output);
    for (const std::string& d : in_run)
      EXPECT_TRUE(in_check.count(d)) << "seed " << seed << ": the run's " << d << " is not in the check's list\n"
                                     << text << check.output;
    EXPECT_EQ(run.exit_code == 0, check.exit_code == 0) << "seed " << seed << "\n" << text << run.output
                                                        << check.output;
  }
}

// Two channels: each program is checked in its channel; the JSON says which.
TEST(CheckCommand, EachChannelsProgramInItsChannel) {
  const std::string two = root() + "/examples/two-channel";
  const auto dir = temp_dir("check_two_channels");
  const std::string bad = write(dir / "bad.nc", "G0 X0\nG1 X5\nM30\n").string();
  CliResult r = run_nck_raw("check --json " + two + " " + two + "/channel1.nc " + bad + " 2>/dev/null");
  EXPECT_EQ(r.exit_code, 1);
  const nlohmann::json list = nlohmann::json::parse(r.output, nullptr, false);
  ASSERT_TRUE(list.is_array() && list.size() == 1) << r.output;
  EXPECT_EQ(list[0].at("channel"), 2);
  EXPECT_EQ(list[0].at("id"), 930002);
  EXPECT_EQ(list[0].at("line"), 2);
}

// Machine data with errors: they are the check's errors (exit 1), in the
// JSON without a channel (they belong to none), and the programs are not checked.
TEST(CheckCommand, MachineErrorsComeFirstAndStopTheCheck) {
  const auto [dir, line] = patched_example("mill", "check_prog_err", "x.lis", "kenngr.ref_ohne_nocken 1");
  CliResult r = run_nck_raw("check --json " + dir.string() + " " + root() + kMistakes + " 2>/dev/null");
  EXPECT_EQ(r.exit_code, 1);
  const nlohmann::json list = nlohmann::json::parse(r.output, nullptr, false);
  ASSERT_TRUE(list.is_array() && !list.empty()) << r.output;
  bool found = false;
  for (const nlohmann::json& d : list) {
    EXPECT_FALSE(d.contains("channel")) << d;
    found = found || (d.at("id") == 910018 && d.at("line") == line);
  }
  EXPECT_TRUE(found) << list;
}

// A program that keeps the check busy ends at --max-wall (940006, exit 1).
TEST(CheckCommand, MaxWallEndsALongCheck) {
  const auto p = write(temp_dir("check_max_wall") / "p.nc", "P1 = 0\n$WHILE P1 < 1\nG1 X1 F100\nG1 X2\n$ENDWHILE\nM30\n");
  CliResult r = run_nck("check --max-wall 0.2 " + mill() + " " + p.string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("error 940006"), std::string::npos) << r.output;
}

// Without programs `nck check` checks the machine data alone, as before.
TEST(CheckCommand, MachineAloneIsCheckedAsBefore) {
  CliResult r = run_nck("check " + mill());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("0 error(s)"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace nck::app
