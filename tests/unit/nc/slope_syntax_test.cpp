// #SLOPE [TYPE=..], #SLOPE DEFAULT and #SET SLOPE PROFIL[n]: the modal
// slope profile of the blocks after them, and the errors with file and line.
#include "nc_test_util.hpp"

namespace nck::nc::test {
namespace {

// The slope profile in force for the block with N number n.
SlopeProfile slope_at(const Decoded& d, std::int64_t n) {
  for (const Block& b : d.blocks)
    if (b.n == n) return b.modal.slope;
  ADD_FAILURE() << "no block N" << n << "\n" << dump(d);
  return SlopeProfile::step;
}

TEST(SlopeSyntax, TypesAreModalAndDefaultRestoresTheMachineData) {
  DecoderConfig cfg = default_config();
  cfg.slope_default = SlopeProfile::sin2;  // P-CHAN-00071 = 2
  const auto d = decode("N10 G1 X1 F100\nN20 #SLOPE [TYPE=TRAPEZ]\nN30 X2\nN40 #slope[type=step]\nN50 X3\n"
                        "N60 #SLOPE [TYPE=HSC]\nN70 X4\nN80 #SLOPE DEFAULT\nN90 X5\nN100 #SET SLOPE PROFIL[1]\n"
                        "N110 X6\nN120 #SLOPE [ TYPE = SIN2 ]\nN130 X7\nM30\n",
                        cfg);
  EXPECT_EQ(d.errors(), 0u) << dump(d);
  EXPECT_EQ(slope_at(d, 10), SlopeProfile::sin2);  // program start: the machine data
  EXPECT_EQ(slope_at(d, 30), SlopeProfile::trapez);
  EXPECT_EQ(slope_at(d, 50), SlopeProfile::step);
  EXPECT_EQ(slope_at(d, 70), SlopeProfile::hsc);
  EXPECT_EQ(slope_at(d, 90), SlopeProfile::sin2);
  EXPECT_EQ(slope_at(d, 110), SlopeProfile::trapez);
  EXPECT_EQ(slope_at(d, 130), SlopeProfile::sin2);
}

TEST(SlopeSyntax, WithoutMachineDataTheProgramStartsWithStep) {
  const auto d = decode("N10 G1 X1 F100\nN20 #SLOPE DEFAULT\nN30 X2\nM30\n");
  EXPECT_EQ(d.errors(), 0u) << dump(d);
  EXPECT_EQ(slope_at(d, 10), SlopeProfile::step);
  EXPECT_EQ(slope_at(d, 30), SlopeProfile::step);
}

TEST(SlopeSyntax, UnknownTypeNamesFileAndLine) {
  const auto d = decode("G1 X1 F100\n#SLOPE [TYPE=JERK]\nX2\nM30\n");
  const Diagnostic* e = d.find(ErrorId::NcSlopeType);
  ASSERT_NE(e, nullptr) << dump(d);
  EXPECT_EQ(e->loc.line, 2u);
  EXPECT_NE(e->loc.file.find("prog.nc"), std::string::npos);
  EXPECT_NE(e->message.find("JERK"), std::string::npos) << e->message;
  EXPECT_TRUE(decode("#SET SLOPE PROFIL[4]\n").has(ErrorId::NcSlopeType));
  EXPECT_TRUE(decode("#SET SLOPE PROFIL[-1]\n").has(ErrorId::NcSlopeType));
}

// TF5200 "#SLOPE": NO_OPT=1 is the default (no optimised use of jerk, which
// nck does not have); NO_OPT=0 asks for that optimisation and is refused.
TEST(SlopeSyntax, NoOptOneIsAcceptedNoOptZeroRefused) {
  const auto ok = decode("#SLOPE [TYPE=SIN2 NO_OPT=1]\nX1\nM30\n");
  EXPECT_EQ(ok.errors(), 0u) << dump(ok);
  EXPECT_TRUE(decode("#SLOPE [TYPE=SIN2 NO_OPT=0]\n").has(ErrorId::NcSlopeSyntax));
  EXPECT_TRUE(decode("#SLOPE [TYPE=SIN2 NO_OPT]\n").has(ErrorId::NcSlopeSyntax));
}

TEST(SlopeSyntax, MalformedOrUnsupportedParametersAreSyntaxErrors) {
  for (const char* text : {"#SLOPE\n", "#SLOPE [TYPE TRAPEZ]\n", "#SLOPE [TYPE=TRAPEZ\n", "#SLOPE []\n",
                           "#SLOPE [TYPE=TRAPEZ, WEIGHT=50]\n"}) {
    const auto d = decode(text);
    EXPECT_TRUE(d.has(ErrorId::NcSlopeSyntax)) << text << dump(d);
    EXPECT_FALSE(d.has(ErrorId::NcUnsupported)) << text;
  }
}

}  // namespace
}  // namespace nck::nc::test
