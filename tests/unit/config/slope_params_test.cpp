// The jerk-limited slope's machine data (P-CHAN-00071, P-AXIS-00195...00201):
// TF5200 defaults when absent, µs read as seconds, ramp times below tr_min
// refused with the key's file and line.
#include <gtest/gtest.h>

#include "machine_folder.hpp"

namespace nck::config {
namespace {

using test::dump;
using test::MachineFolder;
using test::with_id;
using test::x_gear;

TEST(SlopeParams, DefaultsAreTheTf5200Values) {
  MachineFolder f;
  const LoadResult r = f.load();
  ASSERT_TRUE(r.machine) << dump(r.diagnostics);
  const GearStage& g = x_gear(r);
  EXPECT_DOUBLE_EQ(g.tr_acc_down_s, 0.050);  // 50,000 µs
  EXPECT_DOUBLE_EQ(g.tr_acc_up_s, 0.050);
  EXPECT_DOUBLE_EQ(g.tr_dec_down_s, 0.050);
  EXPECT_DOUBLE_EQ(g.tr_dec_up_s, 0.050);
  EXPECT_DOUBLE_EQ(g.tr_geom_s, 0.010);  // 10,000 µs
  EXPECT_DOUBLE_EQ(g.tr_rapid_s, 0.010);
  EXPECT_DOUBLE_EQ(g.tr_min_s, 0.010);
  EXPECT_EQ(r.machine->channels.at(0).slope_profile, SlopeProfile::step);
}

TEST(SlopeParams, ReadInMicroseconds) {
  MachineFolder f;
  f.append("x.lis",
           "getriebe[0].slope_profil.tr_beschl_ab 20000\ngetriebe[0].slope_profil.tr_beschl_zu 30000\n"
           "getriebe[0].slope_profil.tr_brems_ab 40000\ngetriebe[0].slope_profil.tr_brems_zu 60000\n"
           "getriebe[0].dynamik.tr_geom 5000\ngetriebe[0].slope_profil.tr_grenz 15000\n"
           "getriebe[0].dynamik.tr_min 4000\n");
  f.append("ch.lis", "prog_start.slope.profile 2\n");
  const LoadResult r = f.load();
  ASSERT_TRUE(r.machine) << dump(r.diagnostics);
  const GearStage& g = x_gear(r);
  EXPECT_DOUBLE_EQ(g.tr_acc_down_s, 0.020);
  EXPECT_DOUBLE_EQ(g.tr_acc_up_s, 0.030);
  EXPECT_DOUBLE_EQ(g.tr_dec_down_s, 0.040);
  EXPECT_DOUBLE_EQ(g.tr_dec_up_s, 0.060);
  EXPECT_DOUBLE_EQ(g.tr_geom_s, 0.005);
  EXPECT_DOUBLE_EQ(g.tr_rapid_s, 0.015);
  EXPECT_DOUBLE_EQ(g.tr_min_s, 0.004);
  EXPECT_EQ(r.machine->channels.at(0).slope_profile, SlopeProfile::sin2);
}

TEST(SlopeParams, RampBelowTrMinNamesItsLine) {
  MachineFolder f;
  f.append("x.lis", "getriebe[0].slope_profil.tr_brems_zu 9999\n");  // tr_min default 10,000 µs
  const LoadResult r = f.load();
  const auto found = with_id(r.diagnostics, ErrorId::ConfigRampBelowMin);
  ASSERT_EQ(found.size(), 1u) << dump(r.diagnostics);
  EXPECT_EQ(found[0].loc.file, f.file("x.lis"));
  EXPECT_EQ(found[0].loc.line, 3u);
  EXPECT_NE(found[0].message.find("tr_brems_zu"), std::string::npos) << found[0].message;
}

TEST(SlopeParams, RaisedTrMinAboveDefaultRampsPointsAtTrMin) {
  MachineFolder f;
  f.append("x.lis", "getriebe[0].dynamik.tr_min 20000\n");  // above tr_grenz's default 10,000 µs
  const LoadResult r = f.load();
  const auto found = with_id(r.diagnostics, ErrorId::ConfigRampBelowMin);
  ASSERT_EQ(found.size(), 1u) << dump(r.diagnostics);
  EXPECT_EQ(found[0].loc.line, 3u);
  EXPECT_NE(found[0].message.find("tr_grenz"), std::string::npos) << found[0].message;
}

TEST(SlopeParams, ProfileThreeIsHsc) {  // TF5200: 3 = trapezoidal HSC profile across blocks
  MachineFolder f;
  f.append("ch.lis", "prog_start.slope.profile 3\n");
  const LoadResult r = f.load();
  ASSERT_TRUE(r.machine) << dump(r.diagnostics);
  EXPECT_EQ(r.machine->channels.at(0).slope_profile, SlopeProfile::hsc);
}

TEST(SlopeParams, ProfileOutOfRangeIsRefused) {
  MachineFolder f;
  f.append("ch.lis", "prog_start.slope.profile 4\n");
  const LoadResult r = f.load();
  EXPECT_FALSE(with_id(r.diagnostics, ErrorId::ConfigOutOfRange).empty()) << dump(r.diagnostics);
}

}  // namespace
}  // namespace nck::config
