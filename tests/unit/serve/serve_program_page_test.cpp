// GET /api/v1/program's pages (issue 45, item 8): the answer's size is the
// bound — a 4 MiB file of empty lines made 12.6 MB of JSON — and the pages
// together give every line once.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "nck/serve/program_page.hpp"

namespace nck::app::serve {
namespace {

namespace fs = std::filesystem;

TEST(ServeProgramPage, TheAnswerIsBoundedAndThePagesGiveEveryLine) {
  const fs::path p = fs::temp_directory_path() / "nck_serve_program_page_test.nc";
  const std::size_t kLines = 4 * 1024 * 1024;
  std::ofstream(p, std::ios::binary) << std::string(kLines, '\n');
  std::size_t seen = 0, pages = 0;
  for (nlohmann::json next = 1; !next.is_null(); ++pages) {
    const std::string page = program_page(1, p, next.get<std::size_t>());
    ASSERT_LE(page.size(), kMaxProgramPageBytes + 4096);
    const auto j = nlohmann::json::parse(page);
    EXPECT_EQ(j["first_line"], seen + 1);
    seen += j["lines"].size();
    next = j["next_line"];
    ASSERT_LT(pages, 20u);
  }
  EXPECT_EQ(seen, kLines);
  EXPECT_GT(pages, 1u);
  fs::remove(p);
}

TEST(ServeProgramPage, LinesAsTheyAreAndALongOneCut) {
  const fs::path p = fs::temp_directory_path() / "nck_serve_program_page_long.nc";
  std::ofstream(p, std::ios::binary) << "N10 G0 X1 (\"q\")\r\n" << std::string(200'000, 'X') << "\nM30";
  const auto j = nlohmann::json::parse(program_page(2, p, 1));
  EXPECT_EQ(j["channel"], 2);
  EXPECT_EQ(j["file"], "nck_serve_program_page_long.nc");
  ASSERT_EQ(j["lines"].size(), 3u);
  EXPECT_EQ(j["lines"][0], "N10 G0 X1 (\"q\")");
  EXPECT_EQ(j["lines"][1].get<std::string>().size(), kMaxShownLineBytes);
  EXPECT_EQ(j["lines"][2], "M30");
  EXPECT_TRUE(j["next_line"].is_null());
  const auto none = nlohmann::json::parse(program_page(1, {}, 1));
  EXPECT_TRUE(none["lines"].empty());
  fs::remove(p);
}

}  // namespace
}  // namespace nck::app::serve
