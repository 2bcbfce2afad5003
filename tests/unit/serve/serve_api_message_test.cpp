// nck serve's command messages, access checks and program folders: every
// malformed, unknown, mistyped or out-of-range message gets its ID; every
// good one becomes the typed action its scenario line builds.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "nck/serve/access.hpp"
#include "nck/serve/api_message.hpp"
#include "nck/serve/program_folders.hpp"
#include "nck/sim/operator_action.hpp"

namespace nck::app::serve {
namespace {

std::optional<ApiCommand> parse(std::string_view body, Diagnostics& d) { return parse_api_command(body, 2, d); }

std::optional<ApiCommand> good(std::string_view body) {
  Diagnostics d;
  auto c = parse(body, d);
  EXPECT_TRUE(c) << body << ": " << (d.items().empty() ? "" : d.items()[0].message);
  return c;
}

// The scenario line the command's typed action means (as refusals quote it).
std::string line_of(std::string_view body) {
  const auto c = good(body);
  if (!c) return {};
  if (c->kind == ApiCommand::Kind::action_line) return c->line;
  EXPECT_EQ(c->kind, ApiCommand::Kind::action) << body;
  return sim::operator_line(sim::OperatorAction{c->action, {}}, sim::Quoting::api);
}

ErrorId refused(std::string_view body) {
  Diagnostics d;
  EXPECT_FALSE(parse(body, d)) << body;
  EXPECT_EQ(d.items().size(), 1u) << body;
  return d.items().empty() ? ErrorId{} : d.items()[0].id;
}

TEST(ServeApiMessage, OperatorCommandsBecomeTypedActions) {
  auto c = good(R"({"command":"jog","axis":"X","direction":"+","speed_mm_min":600,"channel":2})");
  ASSERT_TRUE(c);
  ASSERT_EQ(c->action.kind(), sim::ActionKind::jog);
  EXPECT_EQ(c->action.channel, 2);
  EXPECT_EQ(c->action.get<sim::act::Jog>()->axis.view(), "X");
  EXPECT_EQ(c->action.get<sim::act::Jog>()->direction, 1);
  EXPECT_DOUBLE_EQ(c->action.get<sim::act::Jog>()->speed_mm_min, 600);
  c = good(R"({"command":"jog","axis":"X","direction":"stop","speed_mm_min":600})");
  ASSERT_TRUE(c);
  EXPECT_EQ(c->action.get<sim::act::Jog>()->speed_mm_min, 0);  // a released key has no speed
  c = good(R"({"command":"feed_override","percent":80})");
  ASSERT_TRUE(c);
  EXPECT_DOUBLE_EQ(c->action.get<sim::act::FeedOverride>()->percent, 80);
  c = good(R"({"command":"mode","mode":"manual"})");
  ASSERT_TRUE(c);
  EXPECT_TRUE(c->action.get<sim::act::Mode>()->manual);
}

TEST(ServeApiMessage, OperatorCommandsMeanTheirScenarioLines) {
  EXPECT_EQ(line_of(R"({"command":"cycle_start"})"), "ch=1 cycle_start");
  EXPECT_EQ(line_of(R"({"command":"feedhold","on":true,"channel":2})"), "ch=2 feedhold on");
  EXPECT_EQ(line_of(R"({"command":"feed_override","percent":80})"), "ch=1 feed_override 80");
  EXPECT_EQ(line_of(R"({"command":"rapid_override","percent":25})"), "ch=1 rapid_override 25");
  EXPECT_EQ(line_of(R"({"command":"spindle_override","spindle":"S1","percent":50.5})"), "ch=1 spindle_override S1 50.5");
  EXPECT_EQ(line_of(R"({"command":"skip_mask","mask":5})"), "ch=1 skip_mask 5");
  EXPECT_EQ(line_of(R"({"command":"jog","axis":"X","direction":"+","speed_mm_min":600})"), "ch=1 jog X + 600");
  EXPECT_EQ(line_of(R"({"command":"jog","axis":"X","direction":"stop"})"), "ch=1 jog X stop");
  EXPECT_EQ(line_of(R"({"command":"jog_increment","axis":"Z","direction":"-","step_mm":0.1})"), "ch=1 jog_increment Z - 0.1");
  EXPECT_EQ(line_of(R"({"command":"mode","mode":"manual"})"), "ch=1 mode manual");
  EXPECT_EQ(line_of(R"({"command":"single_step","on":false})"), "ch=1 single_step off");
  EXPECT_EQ(line_of(R"({"command":"action","line":"optional_stop on"})"), "ch=1 optional_stop on");
}

TEST(ServeApiMessage, OtherCommandsCarryTheirFields) {
  Diagnostics d;
  auto c = parse(R"({"command":"mdi","text":"G0 X10 #comment-free"})", d);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->kind, ApiCommand::Kind::mdi);
  EXPECT_EQ(c->text, "G0 X10 #comment-free");  // '#' stays: MDI text is not a scenario line
  EXPECT_FALSE(c->queue);  // refused while a text runs unless asked
  c = parse(R"({"command":"mdi","text":"G0 X1","queue":true})", d);
  ASSERT_TRUE(c);
  EXPECT_TRUE(c->queue);
  c = parse(R"({"command":"load","program":"contour.nc","start_at":"N100","channel":2})", d);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->kind, ApiCommand::Kind::load);
  EXPECT_EQ(c->program, "contour.nc");
  EXPECT_EQ(c->start_at, "N100");
  EXPECT_EQ(c->channel, 2);
  c = parse(R"({"command":"speed","speed":0})", d);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->speed, 0.0);
  EXPECT_TRUE(d.items().empty());
}

TEST(ServeApiMessage, EveryBadMessageHasItsId) {
  EXPECT_EQ(refused(""), ErrorId::ApiMalformedJson);
  EXPECT_EQ(refused("{"), ErrorId::ApiMalformedJson);
  EXPECT_EQ(refused("[1,2]"), ErrorId::ApiMalformedJson);
  EXPECT_EQ(refused(R"({"cmd":"reset"})"), ErrorId::ApiBadValue);
  EXPECT_EQ(refused(R"({"command":5})"), ErrorId::ApiBadValue);
  EXPECT_EQ(refused(R"({"command":"launch"})"), ErrorId::ApiUnknownCommand);
  EXPECT_EQ(refused(R"({"command":"action","line":""})"), ErrorId::ApiUnknownCommand);
  EXPECT_EQ(refused(R"({"command":"launch","channel":9})"), ErrorId::ApiBadValue);  // the first problem only
  EXPECT_EQ(refused(R"({"command":"reset","force":true})"), ErrorId::ApiUnknownField);
  EXPECT_EQ(refused(R"({"command":"feedhold"})"), ErrorId::ApiBadValue);              // missing
  EXPECT_EQ(refused(R"({"command":"feedhold","on":"yes"})"), ErrorId::ApiBadValue);   // wrong type
  EXPECT_EQ(refused(R"({"command":"feed_override","percent":250})"), ErrorId::ApiBadValue);  // range
  EXPECT_EQ(refused(R"({"command":"feed_override","percent":-1})"), ErrorId::ApiBadValue);
  EXPECT_EQ(refused(R"({"command":"rapid_override","percent":201})"), ErrorId::ApiBadValue);
  EXPECT_EQ(refused(R"({"command":"reset","channel":3})"), ErrorId::ApiBadValue);     // the machine has 2
  EXPECT_EQ(refused(R"({"command":"reset","channel":1.5})"), ErrorId::ApiBadValue);
  EXPECT_EQ(refused(R"({"command":"reset","channel":"1"})"), ErrorId::ApiBadValue);
  EXPECT_EQ(refused(R"({"command":"jog","axis":"X + 600 more","direction":"+"})"), ErrorId::ApiBadValue);
  EXPECT_EQ(refused(R"({"command":"jog","axis":"X","direction":"up"})"), ErrorId::ApiBadValue);
  EXPECT_EQ(refused(R"({"command":"mdi","text":"G0 X1\nM30"})"), ErrorId::ApiBadValue);
  EXPECT_EQ(refused(R"({"command":"mdi","text":"   "})"), ErrorId::ApiBadValue);
  EXPECT_EQ(refused(R"({"command":"mdi","text":")" + std::string(kMaxMdiChars + 1, 'X') + "\"}"), ErrorId::ApiBadValue);
  EXPECT_EQ(refused(std::string(kMaxCommandBytes + 1, ' ')), ErrorId::ApiTooLarge);
  EXPECT_EQ(refused(R"({"command":"speed","speed":1e9})"), ErrorId::ApiBadValue);
}

// issue 45, item 3: 1e-5 was accepted and froze the kernel (100 s per cycle).
TEST(ServeApiMessage, TheSpeedRange) {
  for (const char* body : {R"({"command":"speed","speed":1e-5})", R"({"command":"speed","speed":1e-300})",
                           R"({"command":"speed","speed":0.00099})", R"({"command":"speed","speed":10001})",
                           R"({"command":"speed","speed":-1})", R"({"command":"speed","speed":"fast"})"})
    EXPECT_EQ(refused(body), ErrorId::ApiBadValue) << body;
  EXPECT_EQ(good(R"({"command":"speed","speed":0.001})")->speed, 1e-3);
  EXPECT_EQ(good(R"({"command":"speed","speed":10000})")->speed, 1e4);
  EXPECT_EQ(good(R"({"command":"speed","speed":0})")->speed, 0.0);  // as fast as possible
  EXPECT_EQ(good(R"({"command":"speed","speed":"max"})")->speed, 0.0);
}

// issue 45: a fractional mask was cut to a whole one, and a key given twice
// was taken as the last one silently.
TEST(ServeApiMessage, WholeNumbersAndKeysOnce) {
  EXPECT_EQ(refused(R"({"command":"skip_mask","mask":1.5})"), ErrorId::ApiBadValue);
  EXPECT_EQ(line_of(R"({"command":"skip_mask","mask":3.0})"), "ch=1 skip_mask 3");
  EXPECT_EQ(refused(R"({"command":"skip_mask","mask":1,"mask":512})"), ErrorId::ApiMalformedJson);
  EXPECT_EQ(refused(R"({"command":"reset","command":"cycle_start"})"), ErrorId::ApiMalformedJson);
  EXPECT_EQ(refused(R"({"command":"reset","x":{"a":1,"a":2}})"), ErrorId::ApiMalformedJson);
  EXPECT_TRUE(good(R"({"command":"mdi","text":"G0 X1","channel":1})"));  // the same key in two objects is no duplicate
}

// The fastest of three parses of `body`, in seconds.
double parse_seconds(const std::string& body) {
  double best = 1e9;
  for (int i = 0; i < 3; ++i) {
    Diagnostics d;
    const auto t0 = std::chrono::steady_clock::now();
    (void)parse(body, d);
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

// An object of n distinct keys ("0":0,"1":0,...), the last one twice when `twice`.
std::string keys_object(int n, bool twice) {
  std::string body = "{";
  for (int i = 0; i < n; ++i) body += fmt::format("{}\"{}\":0", i ? "," : "", i);
  if (twice) body += fmt::format(",\"{}\":0", n - 1);
  return body + "}";
}

// Issue 45's attack campaign: the keys were searched in a list, so a 64 KiB
// command of 8,000 keys cost the server's thread 100 ms. Quadratic, 7,000
// keys take 49 times as long as 1,000; a set takes about 7 times.
TEST(ServeApiMessage, KeysAreCheckedInLinearTime) {
  EXPECT_EQ(refused(keys_object(7000, true)), ErrorId::ApiMalformedJson);
  ASSERT_LT(keys_object(7000, false).size(), kMaxCommandBytes);
  const double small = parse_seconds(keys_object(1000, false)), large = parse_seconds(keys_object(7000, false));
  EXPECT_LT(large, 20 * small) << small << " s for 1,000 keys, " << large << " s for 7,000";
}

TEST(ServeAccess, TokensCookiesAndNames) {
  const std::string t = make_token();
  EXPECT_EQ(t.size(), 32u);  // 128 bits
  EXPECT_NE(t, make_token());
  EXPECT_TRUE(same_token(t, t));
  EXPECT_FALSE(same_token(t.substr(0, 31), t));
  EXPECT_FALSE(same_token(t + "0", t));
  EXPECT_FALSE(same_token("", ""));  // no token is never a token
  EXPECT_EQ(cookie_value("a=1; nck_token=abc; b=2", "nck_token"), "abc");
  EXPECT_EQ(cookie_value("xnck_token=abc", "nck_token"), "");
  EXPECT_EQ(bearer_token("Bearer  abc "), "abc");
  EXPECT_EQ(bearer_token("Basic abc"), "");
  EXPECT_EQ(bearer_token("bearer abc"), "abc");  // the scheme is case-insensitive (RFC 9110)
  EXPECT_EQ(bearer_token("BEARER abc"), "abc");
  EXPECT_EQ(bearer_token("Bearerabc"), "");
  EXPECT_EQ(bearer_token("bearer"), "");
  EXPECT_EQ(query_value("/?token=abc&x=1", "token"), "abc");
  EXPECT_EQ(query_value("/?x=1", "token"), "");
  const ServerNames names("127.0.0.1", 8765);
  EXPECT_TRUE(names.host_ok("127.0.0.1:8765"));
  EXPECT_TRUE(names.host_ok("localhost:8765"));
  EXPECT_FALSE(names.host_ok("evil.example:8765"));  // DNS rebinding
  EXPECT_FALSE(names.host_ok("127.0.0.1:8766"));
  EXPECT_FALSE(names.host_ok(""));
}

TEST(ServeAccess, RequestBudgetRefillsAtItsRate) {
  RequestBudget b(50);
  const auto t0 = std::chrono::steady_clock::now();
  int taken = 0;
  for (int i = 0; i < 200; ++i) taken += b.take(t0);
  EXPECT_EQ(taken, 50);  // a burst of the rate, then nothing
  EXPECT_FALSE(b.take(t0 + std::chrono::milliseconds(10)));
  EXPECT_TRUE(b.take(t0 + std::chrono::milliseconds(30)));  // 1.5 tokens came back
}

TEST(ServeProgramFolders, NamesResolveInsideTheFoldersOnly) {
  namespace fs = std::filesystem;
  const fs::path base = fs::temp_directory_path() / "nck_serve_folders_test";
  fs::remove_all(base);
  fs::create_directories(base / "progs" / "sub");
  fs::create_directories(base / "outside");
  std::ofstream(base / "progs" / "a.nc") << "G0 X1\nM30\n";
  std::ofstream(base / "progs" / "sub" / "b.nc") << "M30\n";
  std::ofstream(base / "outside" / "secret.nc") << "M30\n";
  std::ofstream(base / "progs" / "big.nc") << std::string(2000, 'X');
  fs::create_symlink(base / "outside" / "secret.nc", base / "progs" / "link.nc");
  fs::create_directories(base / "uploads");
  const ProgramFolders f({base / "progs"}, base / "uploads", 1000);
  EXPECT_TRUE(f.resolve("a.nc"));
  EXPECT_TRUE(f.resolve("sub/b.nc"));
  EXPECT_TRUE(f.resolve((base / "progs" / "a.nc").string()));
  for (const char* bad : {"../outside/secret.nc", "sub/../../outside/secret.nc", "link.nc", "big.nc", "missing.nc", ""})
    EXPECT_EQ(f.resolve(bad).error().id, ErrorId::ApiProgramNotAllowed) << bad;
  EXPECT_FALSE(f.resolve((base / "outside" / "secret.nc").string()));
  const auto listed = f.list();
  EXPECT_NE(std::find(listed.begin(), listed.end(), "sub/b.nc"), listed.end());
  EXPECT_EQ(std::find(listed.begin(), listed.end(), "link.nc"), listed.end());
  EXPECT_TRUE(f.save_upload("up.nc", "M30\n"));
  EXPECT_TRUE(f.resolve("up.nc"));
  EXPECT_FALSE(f.save_upload("../up.nc", "M30\n"));
  EXPECT_FALSE(f.save_upload(".hidden", "M30\n"));
  EXPECT_EQ(f.save_upload("large.nc", std::string(1001, 'X')).error().id, ErrorId::ApiTooLarge);
  fs::remove_all(base);
}

}  // namespace
}  // namespace nck::app::serve
