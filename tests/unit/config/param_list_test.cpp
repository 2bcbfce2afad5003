#include "nck/config/param_list.hpp"

#include <gtest/gtest.h>

#include "nck/config/machine.hpp"

namespace nck::config {
namespace {

ParamList parse(std::string_view text, ListKind kind, Diagnostics& d) {
  return ParamList::parse(read_list_text(text, "t.lis", d), kind, d);
}

TEST(ParamList, SeedOredSyncExampleEqualsHex) {
  Diagnostics d;
  auto l = parse("spindel[0].m3_synch   PLC_INFO   MVS_SVS     0x00020002\n"
                 "spindel[0].m4_synch   PLC_INFO | MVS_SNS\n"
                 "spindel[0].m5_synch   PLC_INFO|MVS_SVS\n"
                 "spindel[0].m19_synch  MNS_SNS  0x00000008\n"
                 "spindel[0].s_synch    0x00000001 MOS\n"
                 "m_synch[48]           0x00000008      MNS_SNS\n",
                 ListKind::channel, d);
  EXPECT_TRUE(d.empty());
  EXPECT_EQ(l.u32("spindel[0].m3_synch", 0), 0x00020002u);
  EXPECT_EQ(l.u32("spindel[0].m4_synch", 0), 0x00020004u);
  EXPECT_EQ(l.u32("spindel[0].m5_synch", 0), 0x00020002u);
  EXPECT_EQ(l.u32("spindel[0].m19_synch", 0), 0x00000008u);
  EXPECT_EQ(l.u32("spindel[0].s_synch", 0), 0x00000001u);
  EXPECT_EQ(l.u32("m_synch[48]", 0), 0x8u);
}

TEST(ParamList, SymbolicAxisTypeAndShortForms) {
  Diagnostics d;
  auto l = parse("kopf.achs_nr 1\nachs_typ 0x00004 Spindel\nachs_mode 0x40000 Externally controlled\n"
                 "antr_typ 0x00004 Simulation\nantr.operation_mode OPEN_POSITION_LOOP_MODE\n",
                 ListKind::axis, d);
  EXPECT_TRUE(d.empty()) << d.items().size();
  EXPECT_EQ(l.u32("kenngr.achs_typ", 0), 4u);
  EXPECT_EQ(l.u32("kenngr.achs_mode", 0), 0x40000u);
  EXPECT_EQ(l.u32("kenngr.antr_typ", 0), 4u);
  EXPECT_EQ(l.text("antr.operation_mode", ""), "OPEN_POSITION_LOOP_MODE");
  Diagnostics d2;
  auto l2 = parse("kenngr.achs_typ ACHSTYP_ROTATOR\n", ListKind::axis, d2);
  EXPECT_EQ(l2.u32("kenngr.achs_typ", 0), 2u);
}

TEST(ParamList, SeedMisspellingsAreAcceptedWithWarningNamingTheKey) {
  Diagnostics d;
  auto l = parse("spindle[0].log_achs_no 6\n"
                 "koppelgruppe[0].paar[0].log_achs_nr_slave 6\n"
                 "spindle[0].m3_synch PLC_INFO MVS_SVS\n",
                 ListKind::channel, d);
  EXPECT_EQ(l.u32("spindel[0].log_achs_nr", 0), 6u);
  EXPECT_EQ(l.u32("synchro_data.koppel_gruppe[0].paar[0].log_achs_nr_slave", 0), 6u);
  EXPECT_EQ(l.u32("spindel[0].m3_synch", 0), 0x20002u);
  ASSERT_EQ(d.items().size(), 3u);
  EXPECT_EQ(d.items()[0].id, ErrorId::ConfigKeyAlias);
  EXPECT_EQ(d.items()[0].severity, Severity::warning);
  EXPECT_NE(d.items()[0].message.find("spindel[0].log_achs_nr"), std::string::npos);
  EXPECT_EQ(d.items()[1].loc.line, 2u);

  Diagnostics da;
  auto a = parse("getriebe[1].mulit_gain_n 3\nbeschl_kennlinie.b3 -1.92901234E-10 [s/deg^2]\n", ListKind::axis, da);
  EXPECT_EQ(a.u32("getriebe[1].multi_gain_n", 0), 3u);
  EXPECT_DOUBLE_EQ(a.num("getriebe[0].beschl_kennlinie.b3", 0), -1.92901234e-10);
  EXPECT_EQ(da.items().size(), 2u);
}

TEST(ParamList, SeedAnnotationsAfterNumbersAreIgnored) {
  Diagnostics d;
  auto l = parse("synchro_data.koppel_gruppe[0].paar[1].mode 1 ->SPDL_LINK\n"
                 "main_spindle_gear_change      1      0: OFF 1: ON\n"
                 "spindel[0].range_table[0].min_speed  50      (M40)\n",
                 ListKind::channel, d);
  EXPECT_TRUE(d.empty());
  EXPECT_EQ(l.u32("synchro_data.koppel_gruppe[0].paar[1].mode", 0), 1u);
  EXPECT_TRUE(l.flag("main_spindle_gear_change", false));
  EXPECT_DOUBLE_EQ(l.num("spindel[0].range_table[0].min_speed", 0), 50.0);
}

TEST(ParamList, MisspeltKeyIsAnErrorNamingTheKeyItMeans) {
  Diagnostics d;
  parse("kopf.achs_nr 1\nkenngr.achs_tpy 4\n", ListKind::axis, d);
  ASSERT_EQ(d.items().size(), 1u);
  const auto& x = d.items()[0];
  EXPECT_EQ(x.id, ErrorId::ConfigKeyTypo);
  EXPECT_EQ(x.severity, Severity::error);
  EXPECT_EQ(x.loc.file, "t.lis");
  EXPECT_EQ(x.loc.line, 2u);
  EXPECT_NE(x.message.find("kenngr.achs_typ"), std::string::npos) << x.message;

  Diagnostics d2;
  parse("spindel[3].bezeichnug S4\n", ListKind::channel, d2);
  ASSERT_EQ(d2.items().size(), 1u);
  EXPECT_NE(d2.items()[0].message.find("'spindel[3].bezeichnung'"), std::string::npos) << d2.items()[0].message;
}

TEST(ParamList, UnknownKeyNamesNearestKnownKey) {
  Diagnostics d;
  parse("kopf.achs_nr 1\nkenngr.achs_typ_ext 4\n", ListKind::axis, d);
  ASSERT_EQ(d.items().size(), 1u);
  const auto& x = d.items()[0];
  EXPECT_EQ(x.id, ErrorId::ConfigUnknownKey);
  EXPECT_EQ(x.severity, Severity::warning);
  EXPECT_EQ(x.loc.line, 2u);
  EXPECT_NE(x.message.find("no effect; nearest known key: 'kenngr.achs_typ'"), std::string::npos) << x.message;

  Diagnostics strict;
  ParamList::parse(read_list_text("kenngr.achs_typ_ext 4\n", "t.lis", strict), ListKind::axis, strict,
                   KeyPolicy::strict);
  ASSERT_EQ(strict.items().size(), 1u);
  EXPECT_EQ(strict.items()[0].id, ErrorId::ConfigUnknownKeyStrict);
  EXPECT_EQ(strict.items()[0].severity, Severity::error);
}

TEST(ParamList, WrongTypeAndOutOfRange) {
  Diagnostics d;
  auto l = parse("kopf.achs_nr X\n"              // 910003
                 "kenngr.vb_prozent 1001\n"      // 910004 (0..1000)
                 "kenngr.getriebe_stufe 1.5\n"   // 910003 (whole number)
                 "kenngr.achs_typ 3\n"           // 910004 (1, 2, 4)
                 "getriebe[6].kv 100\n"          // 910004 index (6 stages: 0..5)
                 "antr.operation_mode FAST\n"    // 910003 not a choice
                 "kenngr.vorz_richtung 2\n",     // 910003 boolean
                 ListKind::axis, d);
  std::vector<std::pair<ErrorId, std::uint32_t>> got;
  for (const auto& x : d.items()) got.emplace_back(x.id, x.loc.line);
  std::vector<std::pair<ErrorId, std::uint32_t>> want = {
      {ErrorId::ConfigBadValue, 1}, {ErrorId::ConfigOutOfRange, 2}, {ErrorId::ConfigBadValue, 3},
      {ErrorId::ConfigOutOfRange, 4}, {ErrorId::ConfigOutOfRange, 5}, {ErrorId::ConfigBadValue, 6},
      {ErrorId::ConfigBadValue, 7}};
  EXPECT_EQ(got, want);
  EXPECT_TRUE(l.values().empty());  // rejected values are not taken
}

TEST(ParamList, ValueReferringToAnotherParameter) {
  Diagnostics d;
  auto l = parse("getriebe[0].dynamik.vb_max 500000\n"
                 "getriebe[0].vb_eilgang P-AXIS-00212.0\n"
                 "getriebe[1].slope_profil.a_beschl P-AXIS-00008.0\n",
                 ListKind::axis, d);
  EXPECT_TRUE(d.empty());
  EXPECT_DOUBLE_EQ(l.num("getriebe[0].vb_eilgang", 0), 500.0);            // as max_speed_mm_s, in mm/s
  EXPECT_DOUBLE_EQ(l.num("getriebe[1].slope_profil.a_beschl", 0), 1000.0);  // a_max default
}

TEST(ParamList, DuplicateKeyWarnsAndLaterWins) {
  Diagnostics d;
  auto l = parse("kopf.achs_nr 1\nkopf.achs_nr 2\n", ListKind::axis, d);
  EXPECT_EQ(l.u32("kopf.achs_nr", 0), 2u);
  ASSERT_EQ(d.items().size(), 1u);
  EXPECT_EQ(d.items()[0].id, ErrorId::ConfigDuplicateKey);
  EXPECT_EQ(d.items()[0].loc.line, 2u);
}

TEST(ParamList, UnitConversionOnce) {
  Diagnostics d;
  auto a = parse("getriebe[0].dynamik.vb_max 500000\n"  // um/s -> 500 mm/s
                 "getriebe[0].kv 1000\n"                 // 0.01/s -> 10 1/s
                 "getriebe[0].moduloo 3600000\n"         // 0.0001 deg -> 360 deg
                 "kenngr.swe_neg -100000000\n"           // 0.1 um -> -10000 mm
                 "getriebe[0].beschl_kennlinie.n_grenz 12000000\n",  // 0.001 deg/s -> 12000 deg/s
                 ListKind::axis, d);
  EXPECT_DOUBLE_EQ(a.num("getriebe[0].dynamik.vb_max", 0), 500.0);
  EXPECT_DOUBLE_EQ(a.num("getriebe[0].kv", 0), 10.0);
  EXPECT_DOUBLE_EQ(a.num("getriebe[0].moduloo", 0), 360.0);
  EXPECT_DOUBLE_EQ(a.num("kenngr.swe_neg", 0), -10000.0);
  EXPECT_DOUBLE_EQ(a.num("getriebe[0].beschl_kennlinie.n_grenz", 0), 12000.0);
  auto t = parse("wz[5].vb_min 60000\nwz[5].vb_max 3000000\n", ListKind::tool, d);
  EXPECT_DOUBLE_EQ(t.num("wz[5].vb_min", 0), 10.0);   // 60 deg/s = 10 rpm
  EXPECT_DOUBLE_EQ(t.num("wz[5].vb_max", 0), 500.0);  // 3000 deg/s = 500 rpm
  auto c = parse("spindel[0].m3_prozess_zeit 2000000\ndist_ctrl[0].v_max 5000\n", ListKind::channel, d);
  EXPECT_DOUBLE_EQ(c.num("spindel[0].m3_prozess_zeit", 0), 2.0);
  EXPECT_DOUBLE_EQ(c.num("dist_ctrl[0].v_max", 0), 5.0);
  EXPECT_TRUE(d.empty());
}

TEST(ParamList, DecoderFunctionSymbols) {
  Diagnostics d;
  auto c = parse("configuration.decoder.function FCT_USE_CACHED_FILES | FCT_3D_DIST_CTRL\n", ListKind::channel, d);
  EXPECT_TRUE(d.empty());
  EXPECT_EQ(c.u32("configuration.decoder.function", 0),
            decoder_fct::FCT_USE_CACHED_FILES | decoder_fct::FCT_3D_DIST_CTRL);
  auto bad = parse("configuration.decoder.function FCT_UNKNOWN\n", ListKind::channel, d);
  ASSERT_EQ(d.items().size(), 1u);
  EXPECT_EQ(d.items()[0].id, ErrorId::ConfigBadValue);
}

}  // namespace
}  // namespace nck::config
