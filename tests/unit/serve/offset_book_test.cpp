// Offsets and tools edited from the HMI (issue 48 item 8): the list loader's
// range rules on every edit, a list file rewritten value by value with its
// comments, a backup, and no save over a file that changed on disk. The
// machine folder is copied to a folder of the test's own.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "nck/config/load.hpp"
#include "nck/serve/list_rewrite.hpp"
#include "nck/serve/offset_book.hpp"

namespace nck::app::serve {
namespace {

namespace fs = std::filesystem;

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(ListRewrite, ReplacesTheValueKeepsTheRemarkColumn) {
  const std::string text = "# head\nnp_grp[1].achse[0].versch    1000000    # G54 X\nNp_Grp[1].achse[1].versch 5\nEnde\n";
  const std::string out = rewrite_list(text, {{"np_grp[1].achse[0].versch", "-25"}, {"np_grp[1].achse[1].versch", "123456789"}});
  EXPECT_EQ(out, "# head\nnp_grp[1].achse[0].versch    -25        # G54 X\nNp_Grp[1].achse[1].versch 123456789\nEnde\n");
}

TEST(ListRewrite, AddsAMissingKeyBeforeEnde) {
  const std::string out = rewrite_list("a 1\nEnde\n# after\n", {{"b[2].c", "7"}});
  EXPECT_EQ(out, "a 1\nb[2].c                       7\nEnde\n# after\n");
  EXPECT_EQ(rewrite_list("a 1", {{"b", "2"}}), "a 1\nb                            2\n");
}

TEST(ListRewrite, CrLfLinesStayCrLf) {
  EXPECT_EQ(rewrite_list("a 1 # x\r\nEnde\r\n", {{"a", "22"}}), "a 22 # x\r\nEnde\r\n");
}

// A tool edit of one field.
ToolEdit tool_edit(std::optional<double> ToolEdit::*field, double value) {
  ToolEdit e;
  e.*field = value;
  return e;
}

class OffsetBookTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("nck-offsets-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::copy(fs::path(NCK_SOURCE_DIR) / "examples" / "mill", dir_, fs::copy_options::recursive);
    auto loaded = config::load_machine(dir_);
    ASSERT_TRUE(loaded.ok());
    m_ = *loaded.machine;
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
  config::Machine m_;
};

TEST_F(OffsetBookTest, AnEditIsCheckedByTheListRules) {
  OffsetBook book(m_);
  EXPECT_FALSE(book.set_zero(m_, 0, "G56", "Z", -12.3456));
  EXPECT_DOUBLE_EQ(m_.channel_data[0].zero.versch[3][2], -12.3456);
  EXPECT_TRUE(book.unsaved());
  const auto far = book.set_zero(m_, 0, "G54", "X", 300000);  // beyond 2^31 0.1 um
  ASSERT_TRUE(far);
  EXPECT_EQ(far->id, ErrorId::OffsetOutOfRange);
  EXPECT_DOUBLE_EQ(m_.channel_data[0].zero.versch[1][0], 100);
  EXPECT_EQ(book.set_zero(m_, 0, "G53", "X", 1)->id, ErrorId::OffsetNotFound);
  EXPECT_EQ(book.set_zero(m_, 0, "G54", "A", 1)->id, ErrorId::OffsetNotFound);
  EXPECT_EQ(book.set_clamp(m_, 0, 5, "X", 1)->id, ErrorId::OffsetNotFound);
  EXPECT_EQ(book.set_tool(m_, 0, 4, tool_edit(&ToolEdit::length_mm, 1.0))->id, ErrorId::OffsetNotFound);  // no wz[4]
  EXPECT_EQ(book.set_tool(m_, 0, 5, tool_edit(&ToolEdit::vb_min_rpm, 600.0))->id, ErrorId::OffsetOutOfRange);  // above vb_max 500
  EXPECT_DOUBLE_EQ(m_.channel_data[0].tools[5].vb_min_rpm, 10);
  EXPECT_FALSE(book.set_tool(m_, 0, 5, tool_edit(&ToolEdit::vb_max_rpm, 800.0)));
  EXPECT_DOUBLE_EQ(m_.channel_data[0].tools[5].vb_max_rpm, 800);
}

TEST_F(OffsetBookTest, SaveWritesTheValuesAndABackup) {
  OffsetBook book(m_);
  const std::string old = read_all(dir_ / "zero.lis");
  ASSERT_FALSE(book.set_zero(m_, 0, "G54", "Z", -149.5));
  ASSERT_FALSE(book.set_tool(m_, 0, 5, tool_edit(&ToolEdit::vb_max_rpm, 800.0)));
  const auto written = book.save();
  ASSERT_TRUE(written) << written.error().message;
  EXPECT_EQ(written->size(), 2u);
  EXPECT_EQ(read_all(dir_ / "zero.lis.bak"), old);
  EXPECT_NE(read_all(dir_ / "zero.lis").find("np_grp[1].achse[2].versch    -1495000   # G54 Z -150 mm"), std::string::npos);
  EXPECT_NE(read_all(dir_ / "tools.lis").find("wz[5].vb_max          4800000   # P-TOOL-00014"), std::string::npos);
  EXPECT_FALSE(book.unsaved());
  // The file as saved loads to the edited value.
  auto again = config::load_machine(dir_);
  ASSERT_TRUE(again.ok());
  EXPECT_DOUBLE_EQ(again.machine->channel_data[0].zero.versch[1][2], -149.5);
  EXPECT_DOUBLE_EQ(again.machine->channel_data[0].tools[5].vb_max_rpm, 800);
}

TEST_F(OffsetBookTest, NoSaveOverAFileThatChangedOnDisk) {
  OffsetBook book(m_);
  ASSERT_FALSE(book.set_zero(m_, 0, "G54", "Z", -149.5));
  { std::ofstream(dir_ / "zero.lis", std::ios::app) << "# changed\n"; }
  const std::string changed = read_all(dir_ / "zero.lis");
  const auto refused = book.save();
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.error().id, ErrorId::OffsetListChanged);
  EXPECT_EQ(read_all(dir_ / "zero.lis"), changed);
  EXPECT_FALSE(fs::exists(dir_ / "zero.lis.bak"));
}

TEST_F(OffsetBookTest, NoSaveOfAFileOutsideTheMachineFolder) {
  const fs::path outside = dir_.string() + "-outside.lis";
  fs::copy_file(dir_ / "zero.lis", outside, fs::copy_options::overwrite_existing);
  m_.channels[0].zero_list = outside;
  OffsetBook book(m_);
  ASSERT_FALSE(book.set_zero(m_, 0, "G54", "Z", -1));
  const auto refused = book.save();
  fs::remove(outside);
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.error().id, ErrorId::OffsetListNotSaved);
}

}  // namespace
}  // namespace nck::app::serve
