// A spindle's acceleration profile, getriebe[i].slope_type (P-AXIS-00270):
// 0 STEP, 1 TRAPEZ, 2 SIN2 (TF5200's data range names these three); any
// other number is TF5200's warning 60226 at its file and line, corrected to
// 0; beside a characteristic curve (beschl_kennlinie.typ 1..3, which needs
// slope type 0) a jerk-limited type is nck's warning 930900 and 0 too.
#include <gtest/gtest.h>

#include "machine_folder.hpp"

namespace nck::config {
namespace {

using test::dump;
using test::MachineFolder;
using test::with_id;

const GearStage& s1_gear(const LoadResult& r, std::size_t g = 0) { return r.machine->axes.at(1).gears.at(g); }

TEST(SpindleSlopeParams, DefaultIsStep) {
  MachineFolder f;
  const LoadResult r = f.load();
  ASSERT_TRUE(r.machine) << dump(r.diagnostics);
  EXPECT_EQ(s1_gear(r).slope_type, SlopeProfile::step);
}

TEST(SpindleSlopeParams, ZeroOneTwoAreStepTrapezSin2PerGearStage) {
  MachineFolder f;
  f.append("s1.lis", "getriebe[0].slope_type 1\ngetriebe[1].slope_type 2\ngetriebe[2].slope_type 0\n");
  const LoadResult r = f.load();
  ASSERT_TRUE(r.machine) << dump(r.diagnostics);
  EXPECT_TRUE(r.diagnostics.empty()) << dump(r.diagnostics);
  EXPECT_EQ(s1_gear(r, 0).slope_type, SlopeProfile::trapez);
  EXPECT_EQ(s1_gear(r, 1).slope_type, SlopeProfile::sin2);
  EXPECT_EQ(s1_gear(r, 2).slope_type, SlopeProfile::step);
}

TEST(SpindleSlopeParams, ThreeOrMoreIsWarning60226AtItsLineAndStep) {
  for (const char* value : {"3", "4", "65535"}) {
    MachineFolder f;
    f.append("s1.lis", std::string("getriebe[0].slope_type ") + value + "\n");
    const LoadResult r = f.load();
    ASSERT_TRUE(r.machine) << dump(r.diagnostics);  // a warning: the machine loads
    const auto found = with_id(r.diagnostics, ErrorId::ConfigSpindleSlopeType);
    ASSERT_EQ(found.size(), 1u) << value << ": " << dump(r.diagnostics);
    EXPECT_EQ(number(found[0].id), 60226u);
    EXPECT_EQ(found[0].severity, Severity::warning);
    EXPECT_EQ(found[0].loc.file, f.file("s1.lis"));
    EXPECT_EQ(found[0].loc.line, 3u);
    EXPECT_NE(found[0].message.find("axis 2"), std::string::npos) << found[0].message;  // P-AXIS-00016
    EXPECT_EQ(s1_gear(r).slope_type, SlopeProfile::step) << value;
    EXPECT_FALSE(r.diagnostics.has_errors()) << dump(r.diagnostics);
  }
}

TEST(SpindleSlopeParams, BeyondUns16IsOutOfRange) {
  MachineFolder f;
  f.append("s1.lis", "getriebe[0].slope_type 65536\n");
  const LoadResult r = f.load();
  EXPECT_FALSE(with_id(r.diagnostics, ErrorId::ConfigOutOfRange).empty()) << dump(r.diagnostics);
}

// An acceleration curve of type 3 on S1's first gear stage (four list lines).
constexpr const char* kCurveStage =
    "getriebe[0].beschl_kennlinie.typ 3\ngetriebe[0].beschl_kennlinie.a_max 800\n"
    "getriebe[0].beschl_kennlinie.n1 100000\ngetriebe[0].beschl_kennlinie.n2 150000\n";

TEST(SpindleSlopeParams, JerkLimitedTypeBesideACurveIsWarning930900AndStep) {
  MachineFolder f;
  f.append("s1.lis", std::string(kCurveStage) + "getriebe[0].slope_type 2\n");
  const LoadResult r = f.load();
  ASSERT_TRUE(r.machine) << dump(r.diagnostics);
  const auto found = with_id(r.diagnostics, ErrorId::ConfigSpindleSlopeWithCurve);
  ASSERT_EQ(found.size(), 1u) << dump(r.diagnostics);
  EXPECT_EQ(number(found[0].id), 930900u);
  EXPECT_EQ(found[0].loc.line, 7u);
  EXPECT_EQ(s1_gear(r).slope_type, SlopeProfile::step);
  EXPECT_EQ(s1_gear(r).curve.type, 3u);
}

TEST(SpindleSlopeParams, StepBesideACurveIsQuiet) {
  MachineFolder f;
  f.append("s1.lis", std::string(kCurveStage) + "getriebe[0].slope_type 0\n");
  const LoadResult r = f.load();
  ASSERT_TRUE(r.machine) << dump(r.diagnostics);
  EXPECT_TRUE(with_id(r.diagnostics, ErrorId::ConfigSpindleSlopeWithCurve).empty()) << dump(r.diagnostics);
}

}  // namespace
}  // namespace nck::config
