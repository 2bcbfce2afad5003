// The diagnostic's one shape (issue 47 item 5): one writer for every
// surface, absent fields left out; the events and --final keep their first
// fields and gain the rest; the catalogue has a shape of its own; the last
// error of a channel lasts until its reset.
#include <gtest/gtest.h>

#include "nck/output/diagnostic_json.hpp"
#include "nck/output/last_errors.hpp"
#include "nck/output/output_writers.hpp"

namespace nck::app {
namespace {

std::vector<std::string> keys(const nlohmann::ordered_json& j) {
  std::vector<std::string> out;
  for (auto it = j.begin(); it != j.end(); ++it) out.push_back(it.key());
  return out;
}

TEST(DiagnosticJson, EveryFieldInItsOrderWhereItApplies) {
  const Diagnostic d = make_diagnostic(ErrorId::NcUnexpectedCharacter, SourceLoc{"p.nc", 3, 7}, "'$' is no word");
  const nlohmann::ordered_json j = diagnostic_json(d, 2);
  EXPECT_EQ(keys(j), (std::vector<std::string>{"id", "severity", "name", "message", "remedy", "file", "line", "column",
                                               "channel"}));
  EXPECT_EQ(j["id"], 920003);
  EXPECT_EQ(j["severity"], "error");
  EXPECT_EQ(j["name"], "NcUnexpectedCharacter");
  EXPECT_EQ(j["message"], "'$' is no word");
  EXPECT_EQ(j["remedy"], std::string(find_error(ErrorId::NcUnexpectedCharacter)->remedy));
  EXPECT_EQ(j["file"], "p.nc");
  EXPECT_EQ(j["line"], 3);
  EXPECT_EQ(j["column"], 7);
  EXPECT_EQ(j["channel"], 2);
}

TEST(DiagnosticJson, NoPlaceholderForWhatDoesNotApply) {
  const nlohmann::ordered_json j = diagnostic_json(make_diagnostic(ErrorId::PlcScenarioBadNumber, {}, "201 %"));
  EXPECT_EQ(keys(j), (std::vector<std::string>{"id", "severity", "name", "message", "remedy"}));
  // a line without a column, and a severity the occurrence gives
  const nlohmann::ordered_json w =
      diagnostic_json(ErrorId::KernelSoftwareLimit, "x", SourceLoc{"p.nc", 4, 0}, 0, Severity::warning);
  EXPECT_EQ(keys(w), (std::vector<std::string>{"id", "severity", "name", "message", "remedy", "file", "line"}));
  EXPECT_EQ(w["severity"], "warning");
}

TEST(DiagnosticJson, EarlierFieldsStayFirstAndKeepTheirValues) {
  const FinalError e{930003, 1, 11, "p.nc", "X 650 is outside"};
  const nlohmann::ordered_json j = final_error_json(e);
  EXPECT_EQ(keys(j), (std::vector<std::string>{"id", "ch", "line", "file", "msg", "severity", "name", "message", "remedy",
                                               "channel"}));
  EXPECT_EQ(j["message"], j["msg"]);
  EXPECT_EQ(j["channel"], 1);
  // the machine's: ch 0 and "" stay as they were, the shape's fields leave them out
  const nlohmann::ordered_json m = final_error_json(FinalError{940200, 0, 0, "", "full"});
  EXPECT_EQ(m["ch"], 0);
  EXPECT_EQ(m["file"], "");
  EXPECT_FALSE(m.contains("channel"));
}

TEST(DiagnosticJson, ErrorEventsAreTheShapeToo) {
  kernel::Event e{{0.5, 1, {}}, kernel::ev::Error{{ErrorId::KernelSoftwareLimit, {}, {}}}};
  e.at.line = 4;
  const nlohmann::ordered_json j = EventWriter::object(e, RunNames{});
  EXPECT_EQ(keys(j), (std::vector<std::string>{"t", "ch", "ev", "id", "line", "file", "msg", "severity", "name", "message",
                                               "remedy", "channel"}));
  EXPECT_EQ(j["severity"], "error");
  EXPECT_EQ(j["message"], j["msg"]);
  const kernel::Event w{{0.5, 0, {}}, kernel::ev::Warning{{ErrorId::KernelEventsDropped, {}, {}}}};
  const nlohmann::ordered_json jw = EventWriter::object(w, RunNames{});
  EXPECT_EQ(jw["severity"], "warning");
  EXPECT_FALSE(jw.contains("channel"));
  EXPECT_FALSE(EventWriter::object(kernel::Event{{0.5, 1, {}}, kernel::ev::Stop{}}, RunNames{}).contains("severity"));
}

TEST(CatalogueJson, OneShapeForEveryEntry) {
  const nlohmann::ordered_json all = catalogue_json();
  ASSERT_EQ(all.size(), all_errors().size());
  for (const auto& e : all)
    EXPECT_EQ(keys(e), (std::vector<std::string>{"id", "severity", "name", "cause", "remedy"})) << e;
}

TEST(LastErrors, AnErrorLastsUntilItsChannelsReset) {
  LastErrors last;
  const RunNames names;
  EXPECT_TRUE(last.latest().is_null());
  last.take(kernel::Event{{1.0, 1, {}}, kernel::ev::Error{{ErrorId::KernelSoftwareLimit, {}, {}}}}, names);
  last.take(kernel::Event{{1.0, 2, {}}, kernel::ev::Warning{{ErrorId::KernelJogRefused, {}, {}}}}, names);
  EXPECT_EQ(last.channel(1)["id"], 930003);
  EXPECT_EQ(last.latest(), last.channel(1));
  EXPECT_TRUE(last.channel(2).is_null());  // a warning is no error
  last.take(kernel::Event{{2.0, 2, {}}, kernel::ev::Error{{ErrorId::KernelSoftwareLimit, {}, {}}}}, names);
  EXPECT_EQ(last.latest()["channel"], 2);
  using kernel::ProgramState;
  last.take(kernel::Event{{3.0, 2, {}}, kernel::ev::State{ProgramState::error, ProgramState::idle, kernel::StateReason::reset}},
            names);
  EXPECT_TRUE(last.channel(2).is_null());
  EXPECT_EQ(last.latest()["channel"], 1);
  // an MDI error's own error -> idle is no reset: the error stays
  last.take(kernel::Event{{3.0, 1, {}}, kernel::ev::State{ProgramState::error, ProgramState::idle, kernel::StateReason::error}},
            names);
  EXPECT_EQ(last.channel(1)["id"], 930003);
  // ... the operator's reset of that idle channel clears it
  last.clear(1);
  EXPECT_TRUE(last.channel(1).is_null());
  EXPECT_TRUE(last.latest().is_null());
}

}  // namespace
}  // namespace nck::app
