#include "nck/config/parameter_registry.hpp"

#include <fstream>
#include <gtest/gtest.h>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace nck::config {
namespace {

TEST(ParameterRegistry, DocsFileIsTheRenderedRegistry) {
  std::ifstream in(std::string(NCK_SOURCE_DIR) + "/docs/parameters.md");
  ASSERT_TRUE(in) << "docs/parameters.md missing; write it from parameters_markdown()";
  std::stringstream ss;
  ss << in.rdbuf();
  EXPECT_EQ(ss.str(), parameters_markdown()) << "regenerate docs/parameters.md (nck params > docs/parameters.md)";
}

TEST(ParameterRegistry, HoldsEveryFactsSheetKeyWithItsId) {
  // A sample of TF5200 parameters across all lists: key -> ID (docs/parameters.md).
  const std::pair<ListKind, std::pair<const char*, const char*>> rows[] = {
      {ListKind::startup, {"kanal_anzahl", "P-STUP-00001"}},
      {ListKind::startup, {"ads_32_bit_comp_mode", "P-STUP-00175"}},
      {ListKind::channel, {"spindel[].range_table[].max_speed", "P-CHAN-00055"}},
      {ListKind::channel, {"synchro_data.koppel_gruppe[].paar[].mode", "P-CHAN-00061"}},
      {ListKind::channel, {"dist_ctrl[].smoothing_factor", "P-CHAN-00827"}},
      {ListKind::channel, {"thread_cutting.thread_chain", "P-CHAN-00837"}},
      {ListKind::axis, {"getriebe[].slope_profil.a_beschl", "P-AXIS-00001"}},
      {ListKind::axis, {"getriebe[].beschl_kennlinie.n2", "P-AXIS-00242"}},
      {ListKind::axis, {"antr.secondary_encoder", "P-AXIS-00824"}},
      {ListKind::tool, {"wz[].a_max", "P-TOOL-00015"}},
      {ListKind::zero, {"np_grp[].achse[].inaktiv", "P-ZERO-00004"}},
      {ListKind::clamp, {"pzv_grp[].achse[].versatz", "P-CLMP-00001"}},
  };
  for (const auto& [list, kv] : rows) {
    const ParamInfo* p = find_parameter(list, kv.first);
    ASSERT_NE(p, nullptr) << kv.first;
    EXPECT_EQ(p->id, kv.second) << kv.first;
  }
  std::set<std::string_view> ids;
  for (const auto& p : all_parameters())
    if (p.id.starts_with("P-")) ids.insert(p.id);
  EXPECT_GE(ids.size(), 175u);  // at least the 175 TF5200 parameters nck started with, each its own ID
}

TEST(ParameterRegistry, KeysAreUniquePerListAndLowerCase) {
  std::set<std::pair<int, std::string_view>> seen;
  for (const auto& p : all_parameters()) {
    EXPECT_TRUE(seen.emplace(static_cast<int>(p.list), p.key).second) << p.key;
    for (char c : p.key) EXPECT_FALSE(c >= 'A' && c <= 'Z') << p.key;
    EXPECT_FALSE(p.meaning.empty()) << p.key;
  }
}

TEST(ParameterRegistry, DefaultsLieInsideTheirRange) {
  for (const auto& p : all_parameters()) {
    if (p.type != ParamType::integer && p.type != ParamType::real && p.type != ParamType::boolean) continue;
    if (p.def == 0 && p.min == 1) continue;  // ISG default 0 = "not set" (e.g. log_achs_nr)
    if (p.key == "dist_ctrl[].a_max") continue;  // default 0 = "not set" (315001)
    EXPECT_GE(p.def, p.min) << p.key;
    EXPECT_LE(p.def, p.max) << p.key;
  }
}

TEST(ParameterRegistry, SymbolValuesOfFactsSheetB0) {
  EXPECT_EQ(symbol_value(ParamType::sync, "MVS_SVS"), 0x2u);
  EXPECT_EQ(symbol_value(ParamType::sync, "MNE_SNS"), 0x20u);
  EXPECT_EQ(symbol_value(ParamType::sync, "MVS_SLP"), 0x8000u);
  EXPECT_EQ(symbol_value(ParamType::sync, "PLC_INFO"), 0x20000u);
  EXPECT_EQ(symbol_value(ParamType::sync, "NOT_VALID"), 0x80000000u);
  EXPECT_EQ(symbol_value(ParamType::achstyp, "ACHSTYP_SPINDEL"), 0x4u);
  EXPECT_FALSE(symbol_value(ParamType::sync, "MVS_XYZ"));
}

TEST(ParameterRegistry, NearestKey) {
  EXPECT_EQ(nearest_key(ListKind::channel, "spindel[].log_achs_no"), "spindel[].log_achs_nr");
  EXPECT_EQ(nearest_key(ListKind::startup, "cycle_time"), "cycle_time_us");
}

// Issue 44 item 13: what is taken for a misspelling (docs/decisions.md).
TEST(ParameterRegistry, MisspeltKeys) {
  EXPECT_EQ(misspelt_key(ListKind::axis, "kenngr.swe_poss"), "kenngr.swe_pos");
  EXPECT_EQ(misspelt_key(ListKind::axis, "getriebe[3].dynamik.vb_mx"), "getriebe[3].dynamik.vb_max");
  // Near a seed spelling or short form: the key it stands for, with the key's indices.
  EXPECT_EQ(misspelt_key(ListKind::channel, "spindle[2].log_achs_nn"), "spindel[2].log_achs_nr");
  EXPECT_EQ(misspelt_key(ListKind::axis, "beschl_kennlinie.a_konts"), "getriebe[0].beschl_kennlinie.a_konst");
  EXPECT_EQ(misspelt_key(ListKind::axis, "achs_tpy"), "kenngr.achs_typ");
  // Not misspellings: far from every key, only numbers differ (m6_synch is
  // also 2 from s_synch), other indices, a name of two letters.
  EXPECT_EQ(misspelt_key(ListKind::axis, "kenngr.abs_pos_gueltig"), std::nullopt);
  EXPECT_EQ(misspelt_key(ListKind::channel, "spindel[0].m6_synch"), std::nullopt);
  EXPECT_EQ(misspelt_key(ListKind::axis, "kenngr.swe_pos_2"), std::nullopt);
  EXPECT_EQ(misspelt_key(ListKind::tool, "wz[1].ax_versatz"), std::nullopt);
  EXPECT_EQ(misspelt_key(ListKind::axis, "getriebe[0].kw"), std::nullopt);
}

TEST(ParameterRegistry, AliasPatternsAreEverySpellingThatResolves) {
  const ParamInfo* p = find_parameter(ListKind::channel, "spindel[].log_achs_nr");
  ASSERT_NE(p, nullptr);
  const std::vector<std::string> aliases = alias_patterns(*p);
  EXPECT_EQ(std::set<std::string>(aliases.begin(), aliases.end()),
            (std::set<std::string>{"spindle[].log_achs_nr", "spindel[].log_achs_no", "spindle[].log_achs_no"}));
  for (std::string a : aliases) {
    a.replace(a.find("[]"), 2, "[1]");
    EXPECT_TRUE(rewrite_alias(ListKind::channel, a)) << a;
  }
  EXPECT_TRUE(alias_patterns(*find_parameter(ListKind::channel, "gruppe[].achse[].log_achs_nr")).empty());
}

}  // namespace
}  // namespace nck::config
