// The real ISG programs of tests/data/isg-samples as a data-driven test:
// `nck parse` on every file, checked against tests/isg_samples.tsv (file ->
// "decodes", or where its first error is, with its ID and why the file is
// not a valid ISG program). A missing folder fails; nothing may hang.
#include <gtest/gtest.h>

#include <map>

#include "cli_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;

std::filesystem::path samples() {
  return (std::filesystem::path(root()) / "tests" / "data" / "isg-samples").lexically_normal();
}

struct Expected {
  std::string result;  // "decodes" or "<file>:<line> <id>"
  std::string reason;
};

// file<TAB>result<TAB>reason; '#' lines are comments.
std::map<std::string, Expected> read_table() {
  std::map<std::string, Expected> out;
  for (const std::string& line : split(read_file(root() + "/tests/isg_samples.tsv"), '\n')) {
    if (line.empty() || line[0] == '#') continue;
    const auto f = split(line, '\t');
    if (f.size() < 2) continue;
    out[f[0]] = {f[1], f.size() > 2 ? f[2] : ""};
  }
  return out;
}

// "decodes" or "<file name>:<line> <id>" of the first error nck parse prints.
std::string first_error(const std::string& output) {
  for (const std::string& line : split(output, '\n')) {
    const auto at = line.find(": error ");
    if (at == std::string::npos) continue;
    const std::string where = line.substr(0, at);  // path:line[:column]
    const auto parts = split(where, ':');
    if (parts.size() < 2) return line;
    const std::string file = std::filesystem::path(parts[0]).filename().string();
    const std::string id = line.substr(at + 8, line.find(':', at + 8) - (at + 8));
    return file + ":" + parts[1] + " " + id;
  }
  return "decodes";
}

// `timeout` turns a hang into exit code 124 instead of a test that never ends.
// 300 s: docHover2.nc runs into the loop limit (10 million iterations), 6 s
// in a plain build and about 60 s under ASan on a loaded 2-core machine.
CliResult parse_with_timeout(const std::filesystem::path& file) {
  return run_shell("timeout 300 " + std::string(NCK_BINARY) + " parse '" + file.string() + "' 2>&1");
}

TEST(IsgSamplesCorpus, EveryFileMatchesTheTable) {
  ASSERT_TRUE(std::filesystem::is_directory(samples()))
      << samples() << " is missing: the corpus test needs tests/data/isg-samples";
  auto table = read_table();
  ASSERT_FALSE(table.empty());
  int files = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(samples())) {
    if (!e.is_regular_file() || e.path().extension() != ".nc") continue;
    const std::string rel = std::filesystem::relative(e.path(), samples()).generic_string();
    ++files;
    const CliResult r = parse_with_timeout(e.path());
    ASSERT_NE(r.exit_code, 124) << rel << " did not finish within 300 s";
    const std::string got = first_error(r.output);
    auto it = table.find(rel);
    if (it == table.end()) {
      ADD_FAILURE() << rel << " is not in tests/isg_samples.tsv; it gives: " << got;
      continue;
    }
    EXPECT_EQ(got, it->second.result) << rel << "\n" << r.output;
    EXPECT_EQ(r.exit_code, got == "decodes" ? 0 : 1) << rel << "\n" << r.output;
    if (got != "decodes") {
      EXPECT_FALSE(it->second.reason.empty()) << rel << ": the table must say why it fails";
    }
    table.erase(it);
  }
  EXPECT_GE(files, 31);
  for (const auto& [file, exp] : table) ADD_FAILURE() << "tests/isg_samples.tsv names " << file << ", which is not there";
}

}  // namespace
}  // namespace nck::app
