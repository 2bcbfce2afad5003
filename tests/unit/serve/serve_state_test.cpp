// The API's state and MDI answers (issue 47 item 5): the state lists the
// run's channels from the start, with last_error; MDI text that does not
// decode answers 422 with its diagnostic, text whose error depends on the
// channel's state is left to the run.
#include <filesystem>
#include <memory>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "nck/config/load.hpp"
#include "nck/serve/mdi_check.hpp"
#include "nck/serve/serve_api.hpp"

namespace nck::app::serve {
namespace {

const std::string kMill = std::string(NCK_SOURCE_DIR) + "/examples/mill";

// The milling example's API over a kernel that has not started (no cycle, no snapshot yet).
struct IdleMill {
  config::LoadResult loaded = config::load_machine(kMill);
  ProgramFolders folders{{kMill}, std::filesystem::temp_directory_path(), 1 << 20};
  std::unique_ptr<LiveKernel> kernel;
  std::unique_ptr<ServeApi> api;

  IdleMill() {
    auto run = sim::DryRun::create(*loaded.machine, {}, served_run_options(folders));
    kernel = std::make_unique<LiveKernel>(std::make_unique<sim::DryRun>(std::move(*run)), 1.0);
    api = std::make_unique<ServeApi>(*loaded.machine, *kernel, folders);
  }
  HttpReply get(std::string_view path) { return api->handle(HttpRequest{"GET", path, {}}); }
  HttpReply post(const nlohmann::json& command) {
    const std::string body = command.dump();
    return api->handle(HttpRequest{"POST", "/api/v1/command", body});
  }
};

TEST(ServeState, ListsTheChannelsBeforeTheFirstSnapshot) {
  IdleMill mill;
  const nlohmann::json st = nlohmann::json::parse(mill.get("/api/v1/state").body);
  ASSERT_EQ(st.at("channels").size(), 1u) << st;  // was []: nothing taken from the kernel yet
  const nlohmann::json& ch = st["channels"][0];
  EXPECT_EQ(ch.at("state"), "idle");
  EXPECT_EQ(ch.at("program_state"), "idle");
  EXPECT_TRUE(ch.at("axes").contains("X"));
  EXPECT_TRUE(ch.at("last_error").is_null());
  EXPECT_TRUE(st.at("last_error").is_null());
}

TEST(ServeState, MdiTextThatDoesNotDecodeIs422WithItsDiagnostic) {
  IdleMill mill;
  const HttpReply r = mill.post({{"command", "mdi"}, {"text", "G0 X1 ?"}});
  EXPECT_EQ(r.status, 422u) << r.body;
  const nlohmann::json e = nlohmann::json::parse(r.body).at("error");
  EXPECT_EQ(e.at("id"), 920003);
  EXPECT_EQ(e.at("name"), "NcUnexpectedCharacter");
  EXPECT_EQ(e.at("file"), "MDI");
  EXPECT_EQ(e.at("line"), 1);
  EXPECT_EQ(e.at("column"), 7);
  EXPECT_EQ(e.at("channel"), 1);
  EXPECT_FALSE(e.at("remedy").get<std::string>().empty());
}

TEST(ServeState, OnlyTheTextsOwnErrorsAreDecidedBeforeTheRun) {
  const config::LoadResult loaded = config::load_machine(kMill);
  const std::vector<std::filesystem::path> roots{kMill};
  EXPECT_FALSE(mdi_text_error(*loaded.machine, 0, "G90 G0 X10 Y5", roots));
  EXPECT_EQ(mdi_text_error(*loaded.machine, 0, "G77 X1", roots)->id, ErrorId::NcUnknownGCode);
  EXPECT_EQ(mdi_text_error(*loaded.machine, 0, "G0 Q5", roots)->id, ErrorId::NcUnknownWord);
  // a P parameter the program may have set, a position beyond the limits: the run decides
  EXPECT_FALSE(mdi_text_error(*loaded.machine, 0, "X=P7", roots));
  EXPECT_FALSE(mdi_text_error(*loaded.machine, 0, "G0 X9999", roots));
  // a loop is read a few blocks far, not to its end
  EXPECT_FALSE(mdi_text_error(*loaded.machine, 0, "$WHILE 1\nG91 G0 X0\n$ENDWHILE", roots));
}

}  // namespace
}  // namespace nck::app::serve
