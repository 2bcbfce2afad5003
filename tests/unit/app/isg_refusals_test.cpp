// Clear refusals through the nck binary (issue 44, item 12): ISG functions
// nck does not have are named as such (920052), never "unknown"; a
// #CONTOUR MODE parameter is called a parameter; ISO/Fanuc words that mean
// something else in ISG, or nothing, get a remedy that says what to write.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "cli_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;

CliResult parse_second_line(const std::string& name, const std::string& line) {
  const auto p = write(temp_dir("refuse-" + name) / "main.nc", fmt::format("G0 X0\n{}\nM30\n", line));
  return run_nck("parse " + p.string());
}

TEST(IsgRefusals, HashFunctionsNckDoesNotHaveAreNamed) {
  for (auto [text, name] : {std::pair{"#TURN [THREAD_CHAIN=1]", "#TURN"},
                            {"#TOOL ORI CS [0,0,1]", "#TOOL ORI"},
                            {"#FILE NAME [MSG=\"log.txt\"]", "#FILE NAME"},
                            {"#TRAFO ON", "#TRAFO"}}) {
    const CliResult r = parse_second_line("hash", text);
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find(fmt::format("main.nc:2:1: error 920052: {} is an ISG function nck does not support", name)),
              std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("920080"), std::string::npos) << r.output;  // never "unknown # command"
  }
}

TEST(IsgRefusals, ContourModeParameterIsCalledAParameter) {
  const CliResult r = parse_second_line("contour", "#CONTOUR MODE [RELEVANT_TRACK=0.5]");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("parameter RELEVANT_TRACK"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("contouring type RELEVANT_TRACK"), std::string::npos) << r.output;
  const CliResult t = parse_second_line("contour-type", "#CONTOUR MODE [DIST PRE_DIST=1]");
  EXPECT_NE(t.output.find("contouring type DIST"), std::string::npos) << t.output;
}

TEST(IsgRefusals, IsoWordsGetAnIsgRemedy) {
  for (auto [text, id, remedy] : {std::tuple{"G20", "920052", "G70"}, {"G21", "920052", "G71"},
                                  {"O1234", "920004", "%"}, {"G28 X0 Y0", "920005", "G74"},
                                  {"G43 H1", "920005", "D"}}) {
    const CliResult r = parse_second_line("iso", text);
    EXPECT_EQ(r.exit_code, 1) << text << "\n" << r.output;
    const auto at = r.output.find(fmt::format("main.nc:2:1: error {}: ", id));
    ASSERT_NE(at, std::string::npos) << text << "\n" << r.output;
    const std::string message = r.output.substr(at, r.output.find('\n', at) - at);
    EXPECT_NE(message.find("ISO"), std::string::npos) << message;
    EXPECT_NE(message.find(remedy), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace nck::app
