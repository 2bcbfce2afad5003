#include "hal/hal_api.hpp"

#include <cstdlib>

#include <fmt/format.h>

#include "nck/output/output_writers.hpp"
#include "nck/serve/access.hpp"
#include "nck/serve/api_message.hpp"
#include "nck/serve/api_pages.hpp"
#include "nck/serve/preview_page.hpp"
#include "nck/serve/program_page.hpp"
#include "nck/sim/operator_action.hpp"

namespace nck::hal {

using app::serve::channel_of;
using app::serve::error_reply;
using app::serve::HttpReply;
using app::serve::ok_json;
using json = nlohmann::ordered_json;

namespace {

// The generation every state and event carries: one run, the one the HAL
// session was started with.
constexpr std::uint64_t kRun = 1;

HttpReply not_offered(std::string_view what, std::string_view instead) {
  return error_reply(409, ErrorId::HalApiNotOffered, fmt::format("nck-hal does not offer {}: {}", what, instead));
}

// The actions nck.cycle merges with the channel's pins (api_controls.hpp).
bool passed_on(sim::ActionKind k) {
  using K = sim::ActionKind;
  return k == K::cycle_start || k == K::reset || k == K::stop || k == K::feedhold || k == K::single_step ||
         k == K::optional_stop || k == K::feed_override || k == K::rapid_override || k == K::skip_mask ||
         k == K::spindle_override || k == K::spindle_feedhold;
}

}  // namespace

HalApi::HalApi(const config::Machine& m, Link& link, const prep::RunRecords& records, std::filesystem::path program)
    : machine_(m), link_(link), records_(records), program_(std::move(program)),
      preview_(app::serve::preview_page(m, 1, program_)) {
  last_.generation = kRun;
  last_.channel_count = m.channels.size();
}

void HalApi::take_event(const kernel::Event& e) {
  const app::RunNames names{&records_};
  std::string line = app::EventWriter::line(e, names);
  std::lock_guard lock(mutex_);
  last_errors_.take(e, names);
  app::note_event(frames_, e, records_);
  events_ += events_.empty() ? "[" : ",";
  events_ += line;
}

void HalApi::take_state() {
  // At the stream's pace: the path gets a point per state taken, as nck serve's does.
  const auto now = std::chrono::steady_clock::now();
  if (now - last_taken_ < app::serve::HttpLimits{}.stream_period || !link_.state.take()) return;
  last_taken_ = now;
  std::lock_guard lock(mutex_);
  const std::uint64_t run = last_.generation;
  last_ = link_.state.front();
  last_.generation = run;
  path_.take(last_, machine_, app::channel_places(last_, machine_, frames_));
  fresh_ = true;
}

std::string HalApi::state_document() {
  json j = app::snapshot_json(last_, machine_, records_, frames_, &last_errors_);
  j["programs"] = json::array({program_.filename().string()});
  j["staged"] = false;
  j["hal"] = true;  // the kernel runs in a HAL thread: the page hides what nck-hal does not offer
  return app::dump_json(j);
}

HttpReply HalApi::handle(const app::serve::HttpRequest& r) {
  const std::string_view path = r.target.substr(0, r.target.find('?'));
  if (r.method == "GET") {
    if (auto page = app::serve::page_file(path)) return *page;
    if (auto fixed = app::serve::fixed_answer(path)) return *fixed;
    if (path == "/api/v1/state") {
      std::lock_guard lock(mutex_);
      return HttpReply{200, "application/json", state_document(), {}};
    }
    if (path == "/api/v1/machine") return ok_json(app::serve::machine_json(machine_));
    if (path == "/api/v1/programs") return ok_json(json{{"programs", json::array({program_.filename().string()})}});
    if (path == "/api/v1/program") return program_text(r.target);
    if (path == "/api/v1/preview") return by_channel(r.target, preview_);
    if (path == "/api/v1/path") {
      std::lock_guard lock(mutex_);
      return by_channel(r.target, path_.json(1, kRun));
    }
    if (path == "/api/v1/offsets") return not_offered("offsets", "the real-time kernel was built with the lists as they were");
  }
  if (r.method == "POST") {
    if (path == "/api/v1/command") return command(r.body);
    if (path == "/api/v1/estop" || path == "/api/v1/machine_on")
      return not_offered(path.substr(8), "the E-stop chain drives nck.estop and nck.machine-on");
    if (path == "/api/v1/upload") return not_offered("uploads", "the program is the one nck-hal was started with");
    if (path == "/api/v1/home") return not_offered("homing here", "G74 in the program homes the axes");
    if (path.starts_with("/api/v1/offsets") || path.starts_with("/api/v1/tools"))
      return not_offered("offset edits", "the real-time kernel was built with the lists as they were");
  }
  return error_reply(404, ErrorId::ApiNotFound, fmt::format("no {} {} (docs/api.md)", r.method, path.substr(0, 80)));
}

HttpReply HalApi::by_channel(std::string_view target, const std::string& answer) const {
  if (channel_of(target) != 1) return error_reply(400, ErrorId::ApiBadValue, "nck-hal runs channel 1 only");
  return HttpReply{200, "application/json", answer, {}};
}

HttpReply HalApi::program_text(std::string_view target) const {
  if (channel_of(target) != 1) return error_reply(400, ErrorId::ApiBadValue, "nck-hal runs channel 1 only");
  const std::string_view from_text = app::serve::query_value(target, "from");
  const long long from = from_text.empty() ? 1 : std::atoll(std::string(from_text).c_str());
  if (from < 1) return error_reply(400, ErrorId::ApiBadValue, "'from' is a line number from 1 on");
  return HttpReply{200, "application/json", app::serve::program_page(1, program_, static_cast<std::size_t>(from)), {}};
}

HttpReply HalApi::command(std::string_view body) {
  Diagnostics diags;
  const auto c = app::serve::parse_api_command(body, machine_.channels.size(), diags);
  if (!c) return error_reply(diags.items().front().id == ErrorId::ApiTooLarge ? 413 : 400, diags.items().front());
  using K = app::serve::ApiCommand::Kind;
  switch (c->kind) {
    case K::pause:
    case K::step_cycle:
    case K::speed: return not_offered("pause, step or speed", "the HAL thread runs the kernel at its period");
    case K::load: return not_offered("loading", "the program is the one nck-hal was started with");
    case K::mdi: return not_offered("MDI", "the program is the one nck-hal was started with");
    case K::action:
    case K::action_line: break;
  }
  const auto op = c->kind == K::action ? sim::check_operator_action(sim::OperatorAction{c->action, {}}, machine_, diags, "api")
                                       : sim::parse_operator_action(c->line, machine_, diags, "api");
  if (!op) return error_reply(400, diags.items().front());
  if (op->action.channel != 1) return error_reply(400, ErrorId::ApiBadValue, "nck-hal runs channel 1 only");
  if (!passed_on(op->action.kind()))
    return not_offered(fmt::format("'{}'", sim::action_name(op->action.kind())),
                       "the HAL file wires the machine's inputs (docs/hal.md, \"The HMI\")");
  return pass_on(op->action);
}

// One producer: this thread (the server's).
HttpReply HalApi::pass_on(const sim::ScenarioAction& a) {
  if (!link_.api_actions.push(a))
    return error_reply(429, ErrorId::PlcOperatorActionsFull, "nck.cycle has 64 actions waiting");
  if (a.kind() == sim::ActionKind::reset) {
    std::lock_guard lock(mutex_);
    last_errors_.clear(a.channel);
  }
  return ok_json(json{{"ok", true}});
}

void HalApi::collect(std::vector<std::string>& frames) {
  std::lock_guard lock(mutex_);
  if (!events_.empty())
    frames.push_back(replay_.number(fmt::format("event: events\ndata: {}]\n\n", events_), true));
  events_.clear();
  if (!fresh_) return;
  fresh_ = false;
  frames.push_back(replay_.number(fmt::format("event: state\ndata: {}\n\n", state_document()), false));
}

std::string HalApi::stream_start(std::optional<std::uint64_t> last_event_id) {
  std::lock_guard lock(mutex_);
  return fmt::format("retry: 1000\n\nevent: machine\ndata: {}\n\n{}event: state\ndata: {}\n\n",
                     app::dump_json(app::serve::machine_json(machine_)),
                     last_event_id ? replay_.since(*last_event_id) : "", state_document());
}

}  // namespace nck::hal
