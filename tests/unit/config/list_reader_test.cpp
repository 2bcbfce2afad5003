#include "nck/config/list_reader.hpp"

#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <random>

#include "nck/config/param_list.hpp"

namespace nck::config {
namespace {

ListText read(std::string_view text, Diagnostics& d) { return read_list_text(text, "t.lis", d); }

TEST(ListReader, KeyValueCommentsAndRemarks) {
  Diagnostics d;
  auto t = read("# comment line\n"
                "kopf.achs_nr   7   # trailing comment\n"
                "\n"
                "g53_verfuegbar 1 ( offsets are additive\n"
                "achs_typ 0x0004 Spindel\n"
                "\tspindel[0].bezeichnung\tS1\n"
                "#spindel[0].range_way 0\n",
                d);
  EXPECT_TRUE(d.empty());
  ASSERT_EQ(t.lines.size(), 4u);
  EXPECT_EQ(t.lines[0].key, "kopf.achs_nr");
  EXPECT_EQ(t.lines[0].value, "7");
  EXPECT_EQ(t.lines[0].line, 2u);
  EXPECT_EQ(t.lines[1].value, "1");
  EXPECT_EQ(t.lines[2].value, "0x0004 Spindel");  // remark stays; numeric keys take the first token
  EXPECT_EQ(t.lines[3].key, "spindel[0].bezeichnung");
  EXPECT_EQ(t.lines[3].value, "S1");
  EXPECT_EQ(t.lines[3].line, 6u);
}

TEST(ListReader, EndeStopsReadingAndCrLfIsAccepted) {
  Diagnostics d;
  auto t = read("kopf.achs_nr 1\r\nEnde\r\nkopf.achs_nr 2\r\n", d);
  ASSERT_EQ(t.lines.size(), 1u);
  EXPECT_EQ(t.lines[0].value, "1");
}

TEST(ListReader, KeysAreCaseInsensitive) {
  Diagnostics d;
  auto t = read("Wz[5].laenge 600000\n", d);
  ASSERT_EQ(t.lines.size(), 1u);
  EXPECT_EQ(t.lines[0].key, "wz[5].laenge");
  auto l = ParamList::parse(t, ListKind::tool, d);
  EXPECT_TRUE(d.empty());
  EXPECT_DOUBLE_EQ(l.num("wz[5].laenge", 0), 60.0);  // 600000 x 0.1 um = 60 mm
}

TEST(ListReader, Numbers) {
  EXPECT_EQ(parse_number("42"), 42.0);
  EXPECT_EQ(parse_number("-100000000"), -100000000.0);
  EXPECT_EQ(parse_number("0x400001"), 4194305.0);
  EXPECT_EQ(parse_number("0X0004"), 4.0);
  EXPECT_DOUBLE_EQ(*parse_number("-1.92901234E-10"), -1.92901234e-10);
  EXPECT_DOUBLE_EQ(*parse_number("2.08333333E-5"), 2.08333333e-5);
  EXPECT_DOUBLE_EQ(*parse_number("+1.5"), 1.5);
  EXPECT_FALSE(parse_number("S1"));
  EXPECT_FALSE(parse_number("12abc"));
  EXPECT_FALSE(parse_number("inf"));
  EXPECT_FALSE(parse_number("nan"));
  EXPECT_FALSE(parse_number("0x"));
  EXPECT_FALSE(parse_number(""));
  EXPECT_FALSE(parse_number("-"));
}

TEST(ListReader, ValueTokensSplitAtBar) {
  auto t = value_tokens("PLC_INFO|MVS_SVS  0x2");
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[0], "PLC_INFO");
  EXPECT_EQ(t[1], "MVS_SVS");
  EXPECT_EQ(t[2], "0x2");
}

TEST(ListReader, BinaryAndOverlongLinesAreDiagnosedNotFatal) {
  Diagnostics d;
  std::string text = "kopf.achs_nr 3\n";
  text += std::string("bad\0\x01\x02 line\n", 12);
  text += std::string(100000, 'x') + "\n";
  text += "kenngr.achs_typ 4\n";
  auto t = read(text, d);
  ASSERT_EQ(t.lines.size(), 2u);
  EXPECT_EQ(t.lines[1].key, "kenngr.achs_typ");
  EXPECT_EQ(t.lines[1].line, 4u);
  ASSERT_EQ(d.items().size(), 2u);
  EXPECT_EQ(d.items()[0].id, ErrorId::ConfigBadLine);
  EXPECT_EQ(d.items()[0].loc.line, 2u);
  EXPECT_EQ(d.items()[1].loc.line, 3u);
}

TEST(ListReader, GarbageStopsAfterTooManyErrors) {
  Diagnostics d;
  std::string text;
  for (int i = 0; i < 100000; ++i) text += "\x7f\x01garbage\n";
  auto t = read(text, d);
  EXPECT_TRUE(t.lines.empty());
  EXPECT_LE(d.items().size(), kMaxDiagnosticsPerList + 1);
  EXPECT_EQ(d.items().back().id, ErrorId::ConfigTooManyErrors);
}

TEST(ListReader, EveryByteValueNeverCrashes) {
  std::string text;
  for (int i = 0; i < 256; ++i) {
    text.push_back(static_cast<char>(i));
    if (i % 17 == 0) text += " [1]] [ 0x 1e999 -\n";
  }
  for (auto kind : {ListKind::startup, ListKind::channel, ListKind::axis, ListKind::tool,
                    ListKind::zero, ListKind::clamp, ListKind::sim}) {
    Diagnostics d;
    auto t = read(text, d);
    auto l = ParamList::parse(t, kind, d);
    EXPECT_TRUE(l.values().empty());
  }
}

TEST(ListReader, NotAKey) {
  Diagnostics d;
  auto t = read("%%% 1\n1abc 2\nkey-with-dash 3\n", d);
  EXPECT_TRUE(t.lines.empty());
  ASSERT_EQ(d.items().size(), 3u);
  EXPECT_EQ(d.items()[0].id, ErrorId::ConfigBadLine);
  EXPECT_EQ(d.items()[2].loc.line, 3u);
}

TEST(ListReader, MissingFileIs910001WithPath) {
  Diagnostics d;
  auto t = read_list_file("/nonexistent/dir/x.lis", "/nonexistent/dir/x.lis", d);
  EXPECT_FALSE(t);
  ASSERT_EQ(d.items().size(), 1u);
  EXPECT_EQ(d.items()[0].id, ErrorId::ConfigFileUnreadable);
  EXPECT_NE(d.items()[0].message.find("/nonexistent/dir/x.lis"), std::string::npos);
}

}  // namespace
}  // namespace nck::config

namespace nck::config {
namespace {

// Seeded mutations of a real example list: every result parses without a crash.
TEST(ListReader, MutatedExampleListsNeverCrash) {
  std::ifstream in(std::string(NCK_SOURCE_DIR) + "/examples/mill/channel1.lis", std::ios::binary);
  ASSERT_TRUE(in);
  std::string base((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_FALSE(base.empty());
  std::mt19937 rng(12345);
  const char alphabet[] = "[]().#|-+0123456789xXeE_ \t\n\r\x7f\x80\xff";
  for (int round = 0; round < 150; ++round) {
    std::string text = base;
    for (int k = 0; k < 20; ++k) {
      std::size_t pos = rng() % text.size();
      switch (rng() % 3) {
        case 0: text[pos] = alphabet[rng() % (sizeof(alphabet) - 1)]; break;
        case 1: text.erase(pos, 1 + rng() % 5); break;
        default: text.insert(pos, std::string(1 + rng() % 8, alphabet[rng() % (sizeof(alphabet) - 1)]));
      }
      if (text.empty()) text = "x";
    }
    for (auto kind : {ListKind::channel}) {
      Diagnostics d;
      EXPECT_NO_THROW(ParamList::parse(read_list_text(text, "m.lis", d), kind, d));
    }
  }
}

}  // namespace
}  // namespace nck::config
