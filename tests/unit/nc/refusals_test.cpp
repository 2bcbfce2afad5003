// Refusals by name: ISG functions nck does not have are 920052, never
// "unknown"; docs/nc-language.md lists every one the decoder refuses
// (refused_isg_functions()); ISO/Fanuc words get an ISG remedy.
#include <fstream>
#include <sstream>

#include "nc_test_util.hpp"

namespace nck::nc::test {
namespace {

std::string nc_language_md() {
  std::ifstream in(std::string(NCK_SOURCE_DIR) + "/docs/nc-language.md");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(NcRefusals, NcLanguageListsEveryRefusedIsgFunction) {
  const std::string doc = nc_language_md();
  ASSERT_FALSE(doc.empty());
  const auto names = refused_isg_functions();
  EXPECT_GE(names.size(), 40u);
  for (const std::string& name : names)
    EXPECT_NE(doc.find("`" + name + "`"), std::string::npos) << name << " is refused but not in docs/nc-language.md";
}

TEST(NcRefusals, IsgFunctionsAreNamed) {
  for (const char* text : {"#TOOL ORI CS [0,0,1]\n", "#TURN [THREAD_CHAIN=1]\n", "#CYL 2ROT [Z, C, X60]\n",
                           "#FACE 2ROT [X, C]\n", "#BCS ON [0, 0, 10]\n", "#OTC ON\n", "G138 X1\n", "G237\n",
                           "#mc_movepath [..]\n", "P1 = IS_STRING[2]\n"}) {
    auto d = decode(text);
    const Diagnostic* e = d.find(ErrorId::NcUnsupported);
    ASSERT_NE(e, nullptr) << text << dump(d);
    EXPECT_NE(e->message.find("is an ISG function nck does not support"), std::string::npos) << e->message;
  }
  auto tool = decode("#TOOL DATA [5]\nM30\n");  // the supported #TOOL forms are untouched
  EXPECT_EQ(tool.errors(), 0u) << dump(tool);
}

TEST(NcRefusals, ContourModeWordsAreSaidAsWhatTheyAre) {
  auto p = decode("#CONTOUR MODE [RELEVANT_TRACK=0.5]\n");
  ASSERT_EQ(p.errors(), 1u) << dump(p);
  EXPECT_NE(p.diags[0].message.find("parameter RELEVANT_TRACK"), std::string::npos) << dump(p);
  auto a = decode("#CONTOUR MODE [DEV PATH_DEV=0.1 POST_ACTION]\n");
  EXPECT_NE(dump(a).find("action POST_ACTION"), std::string::npos) << dump(a);
  auto t = decode("#CONTOUR MODE [PTP]\n");
  EXPECT_NE(dump(t).find("contouring type PTP is not supported"), std::string::npos) << dump(t);
  // Without a type the bracket holds the default type DEV's parameters.
  auto dev = decode("#CONTOUR MODE [PATH_DEV=0.05]\nG1 X1 F100\nM30\n");
  ASSERT_EQ(dev.errors(), 0u) << dump(dev);
  EXPECT_DOUBLE_EQ(dev.blocks[0].modal.contour_dev_mm, 0.05);
}

TEST(NcRefusals, IsoWordsGetTheIsgRemedy) {
  EXPECT_NE(dump(decode("G20\n")).find("for inches write G70"), std::string::npos);
  EXPECT_NE(dump(decode("G21\n")).find("for millimetres write G71"), std::string::npos);
  auto g28 = decode("G28 X0\n");
  ASSERT_TRUE(g28.has(ErrorId::NcUnknownGCode));
  EXPECT_NE(dump(g28).find("with G74"), std::string::npos) << dump(g28);
  EXPECT_NE(dump(decode("G43 H1\n")).find("D<n>"), std::string::npos);
  auto o = decode("O1234\n");
  ASSERT_TRUE(o.has(ErrorId::NcUnknownWord));
  EXPECT_NE(dump(o).find("O1234 is an ISO/Fanuc program number"), std::string::npos) << dump(o);
  EXPECT_NE(dump(decode("O\n")).find("'O' is not a word"), std::string::npos);
}

}  // namespace
}  // namespace nck::nc::test
