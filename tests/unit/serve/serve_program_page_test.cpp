// GET /api/v1/program's pages (issue 45, item 8): the answer's size is the
// bound — a 4 MiB file of empty lines made 12.6 MB of JSON — and the pages
// together give every line once.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>
#include <memory>
#include <string>
#include <thread>

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

// Issue 45's attack campaign: a loaded program replaced by a link or a
// FIFO. The link's target was served; open() on the FIFO waited for a
// writer and held the server's one thread.
TEST(ServeProgramPage, NeitherALinkNorAFifoInThePlaceOfTheProgramIsRead) {
  const fs::path dir = fs::temp_directory_path() / "nck_serve_program_page_swap";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "secret.nc") << "SECRET\n";
  fs::create_symlink(dir / "secret.nc", dir / "link.nc");
  const auto link = nlohmann::json::parse(program_page(1, dir / "link.nc", 1));
  EXPECT_TRUE(link["lines"].empty()) << link.dump();
  ASSERT_EQ(::mkfifo((dir / "fifo.nc").c_str(), 0600), 0);
  // the thread owns the promise with the test: it may still be in set_value when the test ends
  auto answer = std::make_shared<std::promise<std::string>>();
  auto got = answer->get_future();
  std::thread([answer, p = dir / "fifo.nc"] { answer->set_value(program_page(1, p, 1)); }).detach();
  const bool in_time = got.wait_for(std::chrono::seconds(2)) == std::future_status::ready;
  if (!in_time) {  // a writer releases the reader stuck in open(), so that the test ends
    const int fd = ::open((dir / "fifo.nc").c_str(), O_WRONLY | O_NONBLOCK);
    if (fd >= 0) ::close(fd);
    got.wait();
  }
  EXPECT_TRUE(in_time) << "program_page waited on a FIFO";
  EXPECT_TRUE(nlohmann::json::parse(got.get())["lines"].empty());
  fs::remove_all(dir);
}

}  // namespace
}  // namespace nck::app::serve
