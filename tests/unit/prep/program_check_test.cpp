// The pre-flight check (program_check.hpp): every mistake of a program is
// found in one pass, with its values, and the check goes on after each.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "example_blocks.hpp"
#include "nck/prep/program_check.hpp"

namespace nck::prep {
namespace {

using testing::example_machine;

// Checks `text` as channel 1's program on examples/mill.
ProgramCheckResult check_text(const std::string& text, const std::string& name = "prog.nc") {
  const auto dir = std::filesystem::temp_directory_path() / ("nck_program_check_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary) << text;
  return check_program(example_machine("mill"), 0, dir / name, {});
}

// "930003@8" for each diagnostic, in the order found.
std::vector<std::string> ids_at_lines(const ProgramCheckResult& r) {
  std::vector<std::string> out;
  for (const Diagnostic& d : r.diagnostics) out.push_back(std::to_string(number(d.id)) + "@" + std::to_string(d.loc.line));
  return out;
}

const Diagnostic* find(const ProgramCheckResult& r, ErrorId id) {
  for (const Diagnostic& d : r.diagnostics)
    if (d.id == id) return &d;
  return nullptr;
}

TEST(ProgramCheck, ACleanProgramHasNoDiagnostics) {
  const ProgramCheckResult r = check_text("G0 X0 Y0 Z10\nG1 X10 F600\nG2 X20 Y0 R5\nM30\n");
  EXPECT_TRUE(r.diagnostics.empty()) << (r.diagnostics.empty() ? "" : format(r.diagnostics[0]));
  EXPECT_EQ(r.blocks, 4u);
  EXPECT_FALSE(r.stopped);
}

TEST(ProgramCheck, FindsAllSixMistakesWithTheirValues) {
  const std::string path = std::string(NCK_SOURCE_DIR) + "/examples/mill/check_mistakes.nc";
  const ProgramCheckResult r = check_program(example_machine("mill"), 0, path, {});
  EXPECT_EQ(ids_at_lines(r), (std::vector<std::string>{"930002@6", "930004@8", "920005@9", "920022@10",
                                                        "930003@11", "920044@13"}));
  const Diagnostic* arc = find(r, ErrorId::KernelArcEndNotOnCircle);
  ASSERT_NE(arc, nullptr);
  EXPECT_NE(arc->message.find("start radius 5.0000 mm, end radius 15.0000 mm, difference 10.0000 mm"),
            std::string::npos)
      << arc->message;
  const Diagnostic* limit = find(r, ErrorId::KernelSoftwareLimit);
  ASSERT_NE(limit, nullptr);
  EXPECT_NE(limit->message.find("X 650.0000 is outside the software limits [-500.0000, 500.0000]: 150.0000 mm "
                                "beyond the positive limit"),
            std::string::npos)
      << limit->message;
  for (const Diagnostic& d : r.diagnostics) EXPECT_EQ(d.loc.file, path);
}

TEST(ProgramCheck, RadiusProgrammedArcGivesRAndHalfTheChord) {
  const ProgramCheckResult r = check_text("G0 X0 Y0 Z10\nG1 F600\nG2 X20 Y0 R4\nM30\n");
  const Diagnostic* arc = find(r, ErrorId::KernelArcRadiusTooSmall);
  ASSERT_NE(arc, nullptr);
  EXPECT_NE(arc->message.find("R 4.0000 mm, half the chord 10.0000 mm, difference 6.0000 mm"), std::string::npos)
      << arc->message;
}

// The kernel's spindle would cap the speed and warn (950007): the check
// says so at the block, with the speed and the gear stage's maximum.
TEST(ProgramCheck, ASpeedAboveTheGearStageIsAWarningWithValues) {
  const ProgramCheckResult r = check_text("G0 X0 Y0 Z10\nS500 M3\nS99999\nM5\nS88888\nM30\n");
  EXPECT_EQ(ids_at_lines(r), (std::vector<std::string>{"950007@3"}));
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_EQ(r.diagnostics[0].severity, Severity::warning);
  EXPECT_NE(r.diagnostics[0].message.find("S1 99999 rpm is above the maximum of"), std::string::npos)
      << r.diagnostics[0].message;
  EXPECT_NE(r.diagnostics[0].message.find("gear stage 1"), std::string::npos) << r.diagnostics[0].message;
}

// examples/mill's tool 5 limits S1 to 500 rpm from its next start out of
// standstill; DEFAULT_DYNAMIC_DATA lifts the limit again.
TEST(ProgramCheck, TheActiveToolLimitsTheSpeed) {
  const ProgramCheckResult r =
      check_text("G0 X0 Y0 Z10\nD5\nS800 M3\nM5\nS[DEFAULT_DYNAMIC_DATA]\nS800 M3\nM5\nM30\n");
  EXPECT_EQ(ids_at_lines(r), (std::vector<std::string>{"950007@3"}));
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_NE(r.diagnostics[0].message.find("S1 800 rpm is above the maximum of 500 rpm (the active tool's"),
            std::string::npos)
      << r.diagnostics[0].message;
}

// A rejected move leaves the position where it was: the next blocks are
// planned from there, and no error follows from the one before.
TEST(ProgramCheck, AFailedMoveDoesNotMoveThePosition) {
  const ProgramCheckResult r = check_text("G0 X0 Y0 Z10\nG0 X900\nG0 Y10\nG91 G0 X100\nG90 G1 X0 F600\nM30\n");
  EXPECT_EQ(ids_at_lines(r), (std::vector<std::string>{"930003@2"}));
}

// An error met again in a loop is listed once; decoding goes on after it.
TEST(ProgramCheck, AnErrorInALoopIsListedOnce) {
  const ProgramCheckResult r = check_text(
      "G0 X0 Y0 Z10\n$FOR P1 = 1, 5, 1\nG1 X[P1] \n$ENDFOR\nG1 X1 F100\nG4444\nM30\n");
  EXPECT_EQ(ids_at_lines(r), (std::vector<std::string>{"930002@3", "920005@6"}));
}

// As in a run: the decoder's warning, then the error at the last block.
TEST(ProgramCheck, AMissingProgramEndIsReportedAtTheLastBlock) {
  const ProgramCheckResult r = check_text("G0 X0 Y0 Z10\nG0 X5\n");
  EXPECT_EQ(ids_at_lines(r), (std::vector<std::string>{"920049@2", "930007@2"}));
}

TEST(ProgramCheck, AnUnreadableMainProgramEndsTheCheck) {
  const ProgramCheckResult r = check_program(example_machine("mill"), 0, "/nonexistent/nck/prog.nc", {});
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].severity, Severity::error);
  EXPECT_EQ(r.blocks, 0u);
}

TEST(ProgramCheck, TheStopFlagEndsTheCheck) {
  std::atomic<bool> stop{true};
  const auto dir = std::filesystem::temp_directory_path() / ("nck_program_check_stop_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "p.nc") << "G0 X1\nM30\n";
  const ProgramCheckResult r = check_program(example_machine("mill"), 0, dir / "p.nc", {0, &stop});
  EXPECT_TRUE(r.stopped);
}

}  // namespace
}  // namespace nck::prep
