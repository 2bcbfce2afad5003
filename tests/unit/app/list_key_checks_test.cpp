// Unknown list keys through the binary (issue 44 item 13): a misspelt key
// is error 910031 naming the key it misspells, so `nck check` fails and
// `nck run` refuses to start; any other unknown key stays warning 910002
// (no effect), and error 910032 under --strict. The seeds' spellings stay
// accepted and `nck params` finds a key by them.
#include <gtest/gtest.h>

#include <string>

#include "cli_helpers.hpp"

namespace nck::app::testing {
namespace {

std::string at_line(const std::string& file, std::size_t line, const std::string& what) {
  return file + ":" + std::to_string(line) + ": " + what;
}

std::string contour() { return mill() + "/contour.nc"; }

TEST(ListKeys, AMisspeltKeyIsAnErrorNamingTheKeyItMeans) {
  const auto m = patched_example("mill", "key_typo", "x.lis", "kenngr.swe_poss 1000000");
  const CliResult check = run_nck("check " + m.dir.string());
  EXPECT_EQ(check.exit_code, 1) << check.output;
  EXPECT_NE(check.output.find(at_line("x.lis", m.line, "error 910031")), std::string::npos) << check.output;
  EXPECT_NE(check.output.find("'kenngr.swe_poss' misspells 'kenngr.swe_pos' (P-AXIS-00178)"), std::string::npos)
      << check.output;
  const CliResult run = run_nck("run " + m.dir.string() + " " + contour() + " --no-progress");
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find(at_line("x.lis", m.line, "error 910031")), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("program_end"), std::string::npos) << run.output;
}

// In every list, with indices, and against the seeds' spellings as well.
TEST(ListKeys, MisspellingsOfIndexedKeysAndOfSeedSpellings) {
  struct Case {
    std::string file, line, meant;
  } cases[] = {
      {"tools.lis", "wz[5].radiuss 50000", "'wz[5].radius'"},
      {"channel1.lis", "spindel[1].bezeichnug S2", "'spindel[1].bezeichnung'"},
      {"channel1.lis", "spindle[1].log_achs_nn 5", "'spindel[1].log_achs_nr'"},  // seed form spindle[i].log_achs_no
      {"s1.lis", "getriebe[0].mulit_gain_m 1", "'getriebe[0].multi_gain_n'"},    // seed form mulit_gain_n
      {"s1.lis", "achs_tpy 4", "'kenngr.achs_typ'"},                             // short form achs_typ
      {"zero.lis", "np_grp[1].achse[0].verschh 0", "'np_grp[1].achse[0].versch'"},
      {"startup.lis", "kanal_anzal 1", "'kanal_anzahl'"},
  };
  int n = 0;
  for (const Case& c : cases) {
    const auto m = patched_example("mill", "key_typo_" + std::to_string(n++), c.file, c.line);
    const CliResult r = run_nck("check " + m.dir.string());
    EXPECT_EQ(r.exit_code, 1) << c.line << "\n" << r.output;
    EXPECT_NE(r.output.find(at_line(c.file, m.line, "error 910031")), std::string::npos) << c.line << "\n" << r.output;
    EXPECT_NE(r.output.find("misspells " + c.meant), std::string::npos) << c.line << "\n" << r.output;
  }
}

// Keys nck does not model stay a warning with no effect: far from every
// key, a numbered sibling of a known one (only digits differ), another
// number of indices, a one- or two-letter name (docs/decisions.md).
TEST(ListKeys, KeysNckDoesNotModelStayAWarning) {
  const std::string lines[] = {
      "kenngr.abs_pos_gueltig 1",         // P-AXIS-00014, far from every key nck knows
      "kenngr.swe_pos_2 1000000",         // only a number more than kenngr.swe_pos
      "getriebe[0].slope_profil.a_grenz_stufe_1 500",
      "getriebe[0].dynamik.a_max2 500",   // a numbered sibling of dynamik.a_max
      "getriebe[0].kw 100",               // a short name: kv with one letter changed
  };
  int n = 0;
  for (const std::string& line : lines) {
    const auto m = patched_example("mill", "key_unknown_" + std::to_string(n++), "x.lis", line);
    const CliResult r = run_nck("check " + m.dir.string());
    EXPECT_EQ(r.exit_code, 0) << line << "\n" << r.output;
    EXPECT_NE(r.output.find(at_line("x.lis", m.line, "warning 910002")), std::string::npos) << line << "\n" << r.output;
    EXPECT_NE(r.output.find("in the axis list, no effect; nearest known key"), std::string::npos) << r.output;
  }
  // Another number of indices than the key it resembles: ax_versatz[j] without j.
  const auto m = patched_example("mill", "key_unknown_index", "tools.lis", "wz[5].ax_versatz 10");
  const CliResult r = run_nck("check " + m.dir.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find(at_line("tools.lis", m.line, "warning 910002")), std::string::npos) << r.output;
}

TEST(ListKeys, StrictMakesEveryUnknownKeyAnError) {
  const auto m = patched_example("mill", "key_strict", "x.lis", "kenngr.abs_pos_gueltig 1");
  const CliResult check = run_nck("check --strict " + m.dir.string());
  EXPECT_EQ(check.exit_code, 1) << check.output;
  EXPECT_NE(check.output.find(at_line("x.lis", m.line, "error 910032")), std::string::npos) << check.output;
  const CliResult run = run_nck("run --strict " + m.dir.string() + " " + contour() + " --no-progress");
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find(at_line("x.lis", m.line, "error 910032")), std::string::npos) << run.output;
  const CliResult serve = run_nck("serve --strict " + m.dir.string() + " --port 0 --no-realtime --max-wall 5");
  EXPECT_EQ(serve.exit_code, 2) << serve.output;  // refused before it listens
  EXPECT_NE(serve.output.find(at_line("x.lis", m.line, "error 910032")), std::string::npos) << serve.output;
  // Without --strict the run starts, warned.
  const CliResult lenient = run_nck("run " + m.dir.string() + " " + contour() + " --no-progress");
  EXPECT_EQ(lenient.exit_code, 0) << lenient.output;
  EXPECT_NE(lenient.output.find("warning 910002"), std::string::npos) << lenient.output;
  // The examples know no key nck does not.
  EXPECT_EQ(run_nck("check --strict " + mill()).exit_code, 0);
  EXPECT_NE(run_nck("check --help").output.find("--strict"), std::string::npos);
  EXPECT_NE(run_nck("run --help").output.find("--strict"), std::string::npos);
  EXPECT_NE(run_nck("serve --help").output.find("--strict"), std::string::npos);
  EXPECT_NE(read_file(root() + "/docs/cli.md").find("`--strict`"), std::string::npos);
}

// Past the first 200 diagnostics of a file unknown keys are only counted;
// a misspelt one among them still makes the check fail, at its line.
TEST(ListKeys, AMisspellingPastTheDiagnosticCapStillFails) {
  std::string lines;
  for (int i = 0; i < 250; ++i) lines += "unbekannter_schluessel_" + std::to_string(i) + " 1\n";
  lines += "main_spindle_nmae S1";
  const auto m = patched_example("mill", "key_typo_capped", "channel1.lis", lines);
  const CliResult r = run_nck("check " + m.dir.string());
  EXPECT_EQ(r.exit_code, 1) << r.output.substr(r.output.size() > 2000 ? r.output.size() - 2000 : 0);
  EXPECT_NE(r.output.find(at_line("channel1.lis", m.line + 250, "error 910031")), std::string::npos)
      << r.output.substr(r.output.size() > 2000 ? r.output.size() - 2000 : 0);
  EXPECT_NE(r.output.find("'main_spindle_nmae' misspells 'main_spindle_name'"), std::string::npos);
}

TEST(ListKeys, SeedSpellingsStayAcceptedAndParamsFindsThem) {
  const auto m = patched_example("mill", "key_seed", "channel1.lis", "spindle[1].log_achs_no 5\nkoppelgruppe[0].paar[0].mode 1");
  const CliResult r = run_nck("check " + m.dir.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(count(r.output, "warning 910005"), 2u) << r.output;
  EXPECT_EQ(r.output.find("910031"), std::string::npos) << r.output;
  struct Lookup {
    const char* word;
    const char* id;
  } lookups[] = {{"log_achs_no", "P-CHAN-00036"},  {"koppelgruppe", "P-CHAN-00061"},
                 {"mulit_gain_n", "P-AXIS-00128"}, {"wrkz_data", "P-STUP-00010"},
                 {"np_grp[i].achse[j].versatz", "P-ZERO-00003"}};
  for (const Lookup& l : lookups) {
    const CliResult p = run_nck_raw(std::string("params ") + l.word);
    EXPECT_EQ(p.exit_code, 0) << l.word;
    EXPECT_NE(p.output.find(l.id), std::string::npos) << l.word << "\n" << p.output;
  }
  // log_achs_no is spindel[i]'s only: gruppe[0].achse[j].log_achs_nr is not its seed form.
  EXPECT_EQ(run_nck_raw("params log_achs_no").output.find("P-CHAN-00035"), std::string::npos);
}

// Every machine folder of the repository is free of misspelt keys.
TEST(ListKeys, ExampleAndTestMachinesHaveNoMisspeltKey) {
  std::vector<std::filesystem::path> folders;
  for (const char* parent : {"/examples", "/bench/machines"})
    for (const auto& d : std::filesystem::directory_iterator(root() + parent))
      if (std::filesystem::exists(d.path() / "startup.lis")) folders.push_back(d.path());
  for (const auto& d : std::filesystem::directory_iterator(root() + "/tests/scenarios"))
    if (std::filesystem::exists(d.path() / "machine" / "startup.lis")) folders.push_back(d.path() / "machine");
  EXPECT_GE(folders.size(), 8u);
  for (const auto& f : folders) {
    const CliResult r = run_nck("check --strict " + f.string());
    EXPECT_EQ(r.exit_code, 0) << f << "\n" << r.output;
    EXPECT_EQ(r.output.find("9100"), std::string::npos) << f << "\n" << r.output;
  }
}

}  // namespace
}  // namespace nck::app::testing
