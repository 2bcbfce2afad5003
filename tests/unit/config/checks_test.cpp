// Every plausibility check (docs/errors.md, 9100xx), provoked in a small machine folder:
// asserts the ID, the file and the line of the offending key.
#include <gtest/gtest.h>

#include "machine_folder.hpp"

namespace nck::config {
namespace {

using test::dump;
using test::MachineFolder;
using test::minimal_machine;
using test::with_id;

// minimal ch.lis: 1 achse[0] name, 2 achse[0] nr, 3 spdl_anzahl, 4 main_spindle_ax_nr,
//                 5 spindel[0] name, 6 spindel[0] nr
std::string replace(std::string s, const std::string& from, const std::string& to) {
  auto p = s.find(from);
  EXPECT_NE(p, std::string::npos) << from;
  return p == std::string::npos ? s : s.replace(p, from.size(), to);
}

struct Expect {
  ErrorId id;
  std::string file;
  std::uint32_t line;
};

void expect_one(const MachineFolder& f, const LoadResult& r, Expect e) {
  auto found = with_id(r.diagnostics, e.id);
  ASSERT_FALSE(found.empty()) << "no " << number(e.id) << "\n" << dump(r.diagnostics);
  EXPECT_EQ(found[0].loc.file, f.file(e.file)) << dump(r.diagnostics);
  EXPECT_EQ(found[0].loc.line, e.line) << dump(r.diagnostics);
}

LoadResult with_channel_change(MachineFolder& f, const std::string& from, const std::string& to) {
  f.write("ch.lis", replace(minimal_machine()["ch.lis"], from, to));
  return f.load();
}

TEST(Checks, MinimalMachineIsClean) {
  MachineFolder f;
  auto r = f.load();
  EXPECT_TRUE(r.diagnostics.empty()) << dump(r.diagnostics);
}

TEST(Checks, SpindleNameStartsWithS) {
  MachineFolder f;
  auto r = with_channel_change(f, "bezeichnung S1", "bezeichnung T1");
  expect_one(f, r, {ErrorId::ConfigSpindleName, "ch.lis", 5});
}

TEST(Checks, MainSpindleNameStartsWithS) {
  MachineFolder f;
  f.append("ch.lis", "main_spindle_name H\n");
  expect_one(f, f.load(), {ErrorId::ConfigSpindleName, "ch.lis", 7});
}

TEST(Checks, PathAxisNameLetters) {
  MachineFolder f;
  auto r = with_channel_change(f, "bezeichnung X", "bezeichnung K");
  expect_one(f, r, {ErrorId::ConfigAxisName, "ch.lis", 1});
}

TEST(Checks, NamesUniqueInChannel) {
  MachineFolder f;
  f.append("ch.lis", "gruppe[0].achse[1].bezeichnung X\ngruppe[0].achse[1].log_achs_nr 3\n");
  f.append("startup.lis", "achs_mds[2] y.lis\n");
  f.write("y.lis", "kopf.achs_nr 3\n");
  expect_one(f, f.load(), {ErrorId::ConfigDuplicateName, "ch.lis", 7});
}

TEST(Checks, LogicalAxisNumberNotZero) {
  MachineFolder f;
  auto r = with_channel_change(f, "achse[0].log_achs_nr 1", "achse[0].log_achs_nr 0");
  expect_one(f, r, {ErrorId::ConfigAxisNrZero, "ch.lis", 2});
}

TEST(Checks, LogicalAxisNumberUniqueAcrossAxisLists) {
  MachineFolder f;
  f.write("s1.lis", "kopf.achs_nr 1\nkenngr.achs_typ 4\n");
  expect_one(f, f.load(), {ErrorId::ConfigAxisNrDuplicate, "s1.lis", 1});
}

TEST(Checks, NotBothPathAxisAndSpindle) {
  MachineFolder f;
  auto r = with_channel_change(f, "spindel[0].log_achs_nr 2", "spindel[0].log_achs_nr 1");
  expect_one(f, r, {ErrorId::ConfigAxisNrPathAndSpindle, "ch.lis", 6});
}

TEST(Checks, SpindleCountMustMatch) {
  MachineFolder f;
  auto r = with_channel_change(f, "spdl_anzahl 1", "spdl_anzahl 2");
  expect_one(f, r, {ErrorId::ConfigSpindleCount, "ch.lis", 3});
  MachineFolder g;
  auto r2 = with_channel_change(g, "spdl_anzahl 1", "spdl_anzahl 17");
  expect_one(g, r2, {ErrorId::ConfigOutOfRange, "ch.lis", 3});  // at most 16
}

TEST(Checks, MainSpindleMustBeConfigured) {
  MachineFolder f;
  auto r = with_channel_change(f, "main_spindle_ax_nr 2", "main_spindle_ax_nr 7");
  expect_one(f, r, {ErrorId::ConfigMainSpindle, "ch.lis", 4});
  // Even with one spindle the main spindle must be named.
  MachineFolder g;
  auto r2 = with_channel_change(g, "main_spindle_ax_nr 2\n", "");
  expect_one(g, r2, {ErrorId::ConfigMainSpindle, "ch.lis", 4});  // first spindel[0] key
}

TEST(Checks, RefWithoutCamNeedsWithoutReversal) {
  MachineFolder f;
  f.append("s1.lis", "kenngr.ref_ohne_nocken 1\n");
  expect_one(f, f.load(), {ErrorId::ConfigRefWithoutCam, "s1.lis", 3});
  f.append("s1.lis", "kenngr.ref_ohne_rev 1\n");
  EXPECT_TRUE(with_id(f.load().diagnostics, ErrorId::ConfigRefWithoutCam).empty());
}

TEST(Checks, EncoderZeroIsWarnedAndCorrected) {
  MachineFolder f;
  f.append("s1.lis", "getriebe[0].wegaufz 0\ngetriebe[1].wegaufn 0\n");
  auto r = f.load();
  expect_one(f, r, {ErrorId::ConfigWegaufzZero, "s1.lis", 3});
  expect_one(f, r, {ErrorId::ConfigWegaufnZero, "s1.lis", 4});
  EXPECT_FALSE(r.diagnostics.has_errors()) << dump(r.diagnostics);
  EXPECT_EQ(r.machine->axes[1].gear(1).encoder_ratio_num, 1u);
  EXPECT_EQ(r.machine->axes[1].gear(2).encoder_ratio_denom, 1u);
}

TEST(Checks, DistanceControlNeedsAMax) {
  MachineFolder f;
  f.append("ch.lis", "configuration.decoder.function FCT_3D_DIST_CTRL\n");
  expect_one(f, f.load(), {ErrorId::ConfigDistCtrlAMaxMissing, "ch.lis", 7});
  f.append("ch.lis", "dist_ctrl[0].a_max 0\n");
  expect_one(f, f.load(), {ErrorId::ConfigDistCtrlAMaxMissing, "ch.lis", 8});
  f.append("ch.lis", "dist_ctrl[0].a_max 500\n");
  EXPECT_TRUE(with_id(f.load().diagnostics, ErrorId::ConfigDistCtrlAMaxMissing).empty());
  // Enabled only under a start condition counts as enabled, too.
  MachineFolder g;
  g.append("ch.lis", "configuration.decoder.fct_enable[0] FCT_3D_DIST_CTRL\n");
  EXPECT_EQ(with_id(g.load().diagnostics, ErrorId::ConfigDistCtrlAMaxMissing).size(), 1u);
}

TEST(Checks, ParameterRelations) {
  MachineFolder f;
  f.append("x.lis", "getriebe[0].dynamik.vb_max 100000\ngetriebe[0].vb_eilgang 200000\n");
  expect_one(f, f.load(), {ErrorId::ConfigCrossRange, "x.lis", 4});
  MachineFolder g;
  g.append("x.lis", "getriebe[0].slope_profil.a_beschl 5000\n");  // a_max default 1000
  expect_one(g, g.load(), {ErrorId::ConfigCrossRange, "x.lis", 3});
  MachineFolder h;
  h.append("s1.lis", "getriebe[0].moduloo 0\ngetriebe[0].modulou 3600000\n");
  expect_one(h, h.load(), {ErrorId::ConfigCrossRange, "s1.lis", 4});
  MachineFolder k;
  k.append("s1.lis", "kenngr.vb_prozent 1001\n");
  expect_one(k, k.load(), {ErrorId::ConfigOutOfRange, "s1.lis", 3});
  MachineFolder n;
  n.append("ch.lis", "spindel[0].range_table[1].min_speed 900\nspindel[0].range_table[1].max_speed 800\n");
  expect_one(n, n.load(), {ErrorId::ConfigCrossRange, "ch.lis", 8});
}

TEST(Checks, PlcControlSpindleNeedsNoAxisList) {
  MachineFolder f;
  f.write("ch.lis", replace(minimal_machine()["ch.lis"], "spdl_anzahl 1", "spdl_anzahl 2") +
                        "spindel[1].plc_control 1\nspindel[1].bezeichnung S2\nspindel[1].log_achs_nr 9\n");
  auto r = f.load();
  EXPECT_TRUE(r.ok()) << dump(r.diagnostics);
  EXPECT_EQ(r.machine->channels[0].spindles[1].axis_index, -1);
  // The same spindle without plc_control needs an axis list.
  f.write("ch.lis", replace(minimal_machine()["ch.lis"], "spdl_anzahl 1", "spdl_anzahl 2") +
                        "spindel[1].bezeichnung S2\nspindel[1].log_achs_nr 9\n");
  expect_one(f, f.load(), {ErrorId::ConfigNoAxisList, "ch.lis", 8});
}

TEST(Checks, PathAxisWithoutAxisList) {
  MachineFolder f;
  auto r = with_channel_change(f, "achse[0].log_achs_nr 1", "achse[0].log_achs_nr 8");
  expect_one(f, r, {ErrorId::ConfigNoAxisList, "ch.lis", 2});
}

TEST(Checks, SpindleEntryNeedsSpindleAxisList) {
  MachineFolder f;
  f.write("s1.lis", "kopf.achs_nr 2\nkenngr.achs_typ ACHSTYP_ROTATOR\n");
  expect_one(f, f.load(), {ErrorId::ConfigAxisKindMismatch, "ch.lis", 6});
  MachineFolder g;
  g.write("x.lis", "kopf.achs_nr 1\nkenngr.achs_typ 4\n");
  expect_one(g, g.load(), {ErrorId::ConfigAxisKindMismatch, "ch.lis", 2});
}

TEST(Checks, CountsInStartupMustMatch) {
  MachineFolder f;
  f.append("startup.lis", "kanal_anzahl 2\nzahl_mds 3\n");
  auto r = f.load();
  auto e = with_id(r.diagnostics, ErrorId::ConfigCountMismatch);
  ASSERT_EQ(e.size(), 2u) << dump(r.diagnostics);
  EXPECT_EQ(e[0].loc.line, 5u);  // zahl_mds (axes are read first)
  EXPECT_EQ(e[1].loc.line, 4u);  // kanal_anzahl
  EXPECT_EQ(e[0].loc.file, f.file("startup.lis"));
}

TEST(Checks, NoSynchSpindleFunctionWarns) {
  MachineFolder f;
  f.append("ch.lis", "spindel[0].m4_synch NO_SYNCH\n");
  auto r = f.load();
  expect_one(f, r, {ErrorId::ConfigNoSynchSpindle, "ch.lis", 7});
  EXPECT_FALSE(r.diagnostics.has_errors());
}

TEST(Checks, SpindleKnownToTwoChannelsIsFine) {
  auto files = minimal_machine();
  files["startup.lis"] += "sda_mds[1] ch2.lis\nachs_mds[2] y.lis\n";
  files["y.lis"] = "kopf.achs_nr 3\n";
  files["ch2.lis"] = replace(replace(files["ch.lis"], "bezeichnung X", "bezeichnung Y"), "log_achs_nr 1", "log_achs_nr 3");
  MachineFolder f(files);
  auto r = f.load();
  EXPECT_TRUE(r.ok()) << dump(r.diagnostics);
  EXPECT_EQ(r.machine->channels.size(), 2u);
  // ... but a path axis belongs to one channel only.
  f.write("ch2.lis", files["ch.lis"]);
  expect_one(f, f.load(), {ErrorId::ConfigAxisNrDuplicate, "ch2.lis", 2});
}

TEST(Checks, MisspeltKeyInAxisListHasFileAndLine) {
  MachineFolder f;
  f.append("x.lis", "getriebe[0].dynamik.vb_mx 1000\n");
  auto r = f.load();
  expect_one(f, r, {ErrorId::ConfigKeyTypo, "x.lis", 3});
  EXPECT_NE(with_id(r.diagnostics, ErrorId::ConfigKeyTypo)[0].message.find("getriebe[0].dynamik.vb_max"),
            std::string::npos);
  EXPECT_FALSE(r.ok());
}

TEST(Checks, LinkPairMustNameChannelSpindles) {
  MachineFolder f;
  f.append("ch.lis", "synchro_data.koppel_gruppe[0].paar[0].log_achs_nr_slave 9\n"
                     "synchro_data.koppel_gruppe[0].paar[0].log_achs_nr_master 2\n"
                     "synchro_data.koppel_gruppe[0].paar[0].mode 1\n");
  expect_one(f, f.load(), {ErrorId::ConfigLinkPair, "ch.lis", 7});
}

TEST(Checks, GapsInSpindleNumbering) {
  MachineFolder f;
  f.append("ch.lis", "spindel[2].bezeichnung S3\n");
  expect_one(f, f.load(), {ErrorId::ConfigAxisGap, "ch.lis", 5});
}

TEST(Checks, OffsetForMissingChannelAxisWarns) {
  MachineFolder f;
  f.append("startup.lis", "nullp_data[0] zero.lis\n");
  f.write("zero.lis", "np_grp[1].achse[0].versch 10000\nnp_grp[1].achse[4].versch 10000\n");
  auto r = f.load();
  expect_one(f, r, {ErrorId::ConfigUnusedAxisIndex, "zero.lis", 2});
  EXPECT_DOUBLE_EQ(r.machine->channel_data[0].zero.versch[1][0], 1.0);
}

TEST(Checks, DefaultAxisNameOfSpindle) {
  MachineFolder f;
  f.append("ch.lis", "default_ax_name_of_spindle X\n");
  expect_one(f, f.load(), {ErrorId::ConfigDuplicateName, "ch.lis", 7});
  MachineFolder g;
  g.append("ch.lis", "default_ax_name_of_spindle S9\n");
  expect_one(g, g.load(), {ErrorId::ConfigAxisName, "ch.lis", 7});
}

// P-CHAN-00148 needs P-CHAN-00116: alone it is taken as 0 (TF5200 21404).
TEST(Checks, MultiAxesNeedsMultiDimension) {
  MachineFolder f;
  f.append("ch.lis", "multi_axes_in_block 1\n");
  auto r = f.load();
  expect_one(f, r, {ErrorId::ConfigMultiAxesWithoutMultiDimension, "ch.lis", 7});
  EXPECT_FALSE(r.machine->channels[0].multi_axes_in_block);
  MachineFolder g;
  g.append("ch.lis", "multi_axes_in_block 1\nmulti_dimension_in_block 1\n");
  auto both = g.load();
  EXPECT_TRUE(both.diagnostics.empty()) << dump(both.diagnostics);
  EXPECT_TRUE(both.machine->channels[0].multi_axes_in_block);
}

}  // namespace
}  // namespace nck::config
