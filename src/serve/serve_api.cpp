#include "nck/serve/serve_api.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "nck/config/parameter_registry.hpp"
#include "nck/core/utf8.hpp"
#include "nck/core/version.hpp"
#include "nck/output/diagnostic_json.hpp"
#include "nck/output/output_writers.hpp"
#include "nck/report/embedded_files.hpp"
#include "nck/run/start_at.hpp"
#include "nck/serve/access.hpp"
#include "nck/serve/api_pages.hpp"
#include "nck/serve/api_message.hpp"
#include "nck/serve/live_path.hpp"
#include "nck/serve/mdi_check.hpp"
#include "nck/serve/preview_page.hpp"
#include "nck/serve/program_page.hpp"
#include "nck/sim/operator_action.hpp"

namespace nck::app::serve {
namespace {

using json = nlohmann::ordered_json;

}  // namespace

sim::DryRunOptions served_run_options(const ProgramFolders& folders) {
  sim::DryRunOptions o;
  o.record_frames = true;  // positions in program coordinates
  o.record_modal = true;
  o.prep_thread = true;
  o.allowed_roots = folders.roots();
  o.homed_axes.fill(0u);  // a live machine starts unhomed; the server carries what G74 homed (LiveKernel)
  return o;
}

ServeApi::ServeApi(const config::Machine& m, LiveKernel& kernel, ProgramFolders folders)
    : machine_(m), kernel_(kernel), folders_(std::move(folders)), programs_(m.channels.size()), previews_(m.channels.size()),
      serving_(kernel.current()), offsets_(m) {
  seed_state();
}

// The state before the kernel's first snapshot is taken: the run's channels
// as they start (the kernel thread does not run yet), so that no state
// lists no channel (a GET in the first 25 ms answered "channels": []).
void ServeApi::seed_state() {
  const kernel::Kernel& k = serving_->kernel();
  last_.channel_count = std::min(k.channel_count(), last_.channels.size());
  last_.spindle_count = std::min(k.spindle_count(), last_.spindles.size());
  for (std::size_t ch = 0; ch < last_.channel_count; ++ch) {
    const kernel::ChannelState st = k.channel_state(ch);
    last_.channels[ch].axis_mcs = st.axis_mcs;
    last_.channels[ch].program_state = st.program_state;
    last_.channels[ch].at = st.at;
    last_.channels[ch].homed_axes = st.homed_axes;
    last_.channels[ch].homing_required = st.homing_required;
    last_.channels[ch].hli = serving_->machine().hli().channel[ch];
  }
  for (std::size_t i = 0; i < last_.spindle_count; ++i)
    last_.spindle_override_pct[i] = serving_->machine().hli().spindle_control[i].effective_override_percent();
}

HttpReply ServeApi::handle(const HttpRequest& r) {
  const std::string_view path = r.target.substr(0, r.target.find('?'));
  if (auto reply = offsets_route(r)) return *reply;
  if (r.method == "GET") {
    if (auto page = page_file(path)) return *page;
    if (path == "/api/v1/state") return HttpReply{200, "application/json", state_frame(), {}};
    if (path == "/api/v1/machine") return ok_json(machine_json(machine_));
    if (auto fixed = fixed_answer(path)) return *fixed;
    if (path == "/api/v1/programs") return ok_json(json{{"programs", folders_.list()}});
    if (path == "/api/v1/program") return program_text(r.target);
    if (path == "/api/v1/preview") return preview(r.target);
    if (path == "/api/v1/path") return path_so_far(r.target);
  }
  if (r.method == "POST") {
    if (path == "/api/v1/command") return command(r.body);
    if (path == "/api/v1/upload") return upload(r.target, r.body);
    if (path == "/api/v1/estop" || path == "/api/v1/machine_on") return machine_input(path, r.body);
    if (path == "/api/v1/home") return home(r.body);
  }
  // An old or newer client: say which version this server speaks.
  if (path.starts_with("/api/") && !path.starts_with("/api/v1/"))
    return error_reply(404, ErrorId::ApiNotFound,
                       fmt::format("no {} {}: this server speaks API v1 only (/api/v1/..., GET /api/v1/version)",
                                   r.method, path.substr(0, 80)));
  return error_reply(404, ErrorId::ApiNotFound, fmt::format("no {} {} (docs/api.md)", r.method, path.substr(0, 80)));
}

HttpReply ServeApi::command(std::string_view body) {
  Diagnostics diags;
  const auto c = parse_api_command(body, machine_.channels.size(), diags);
  if (!c) return error_reply(diags.items().front().id == ErrorId::ApiTooLarge ? 413 : 400, diags.items().front());
  return act(*c);
}

HttpReply ServeApi::act(const ApiCommand& c) {
  using K = ApiCommand::Kind;
  Diagnostics diags;
  const std::size_t ch = c.channel - 1u;
  switch (c.kind) {
    case K::pause: kernel_.set_paused(c.on); break;
    case K::step_cycle: kernel_.step_one_cycle(); break;
    case K::speed: kernel_.set_speed(c.speed); break;
    case K::load: {
      if (auto d = load(ch, c.program)) return error_reply(d->id == ErrorId::ApiChannelBusy ? 409 : 400, *d);
      if (c.start_at.empty()) break;
      const auto mark = parse_start_at(c.start_at);
      if (!mark) return error_reply(400, ErrorId::ApiBadValue, "'start_at' is no block-search mark: N<n>[:<pass>][@<program>]");
      auto run = make_run(*mark, ch);
      if (!run) return error_reply(400, run.error());
      staged_ = std::move(*run);
      staged_search_ = *mark;
      staged_search_channel_ = ch;
      break;
    }
    case K::mdi:
      if (auto no = refused_by_machine(sim::ActionKind::mdi, ch)) return *no;
      return mdi(ch, c.text, c.queue);
    case K::action:
      return operate(sim::check_operator_action(sim::OperatorAction{c.action, {}}, machine_, diags, "api"), diags);
    case K::action_line: return operate(sim::parse_operator_action(c.line, machine_, diags, "api"), diags);
  }
  return ok_json(json{{"ok", true}});
}

HttpReply ServeApi::mdi(std::size_t ch, const std::string& text, bool queue) {
  // Text that does not decode is answered with its diagnostic, not queued.
  if (auto d = mdi_text_error(machine_, ch, text, folders_.roots())) return error_reply(422, *d, ch + 1);
  if (auto d = serving_->mdi(ch, text, last_.channels[ch].program_state, SourceLoc{}, queue))
    return error_reply(409, *d);
  return ok_json(json{{"ok", true}});
}

// An operator action checked and resolved against the machine (or the reason in diags).
HttpReply ServeApi::operate(const std::optional<sim::OperatorAction>& op, const Diagnostics& diags) {
  if (!op) return error_reply(400, diags.items().front());
  const std::size_t ch = op->action.channel - 1u;
  if (auto no = refused_by_machine(op->action.kind(), ch)) return *no;
  if (op->action.kind() == sim::ActionKind::mdi) return mdi(ch, op->mdi_text, false);
  if (op->action.kind() == sim::ActionKind::cycle_start) return start_or_release(ch, op->action);
  return pass_on(op->action);
}

HttpReply ServeApi::pass_on(const sim::ScenarioAction& a) {
  if (!kernel_.operate(a)) return error_reply(429, ErrorId::PlcOperatorActionsFull, "the kernel has 64 actions waiting");
  if (a.kind() == sim::ActionKind::reset) last_errors_.clear(a.channel);  // also of an idle channel
  note_machine_input(a);
  return ok_json(json{{"ok", true}});
}

// Cycle start: a loaded (or ended) program starts; otherwise the channel's
// hold is released as the PLC's cycle start does.
HttpReply ServeApi::start_or_release(std::size_t ch, const sim::ScenarioAction& cycle_start) {
  const bool free = channel_free(last_.channels[ch].program_state);
  if (free && !staged_ && !programs_[ch].empty()) {
    auto run = make_run(std::nullopt, 0);
    if (!run) return error_reply(400, run.error());
    staged_ = std::move(*run);
  }
  if (free && staged_) {
    if (!kernel_.load(std::move(staged_))) return error_reply(409, ErrorId::ApiBusy, "the run loaded before is not taken yet");
    return ok_json(json{{"ok", true}, {"started", true}});
  }
  return pass_on(cycle_start);
}

std::optional<std::size_t> ServeApi::busy_channel() const {
  for (std::size_t i = 0; i < last_.channel_count; ++i)
    if (!channel_free(last_.channels[i].program_state)) return i;
  return std::nullopt;
}

std::optional<Diagnostic> ServeApi::load(std::size_t ch, const std::string& program) {
  if (const auto busy = busy_channel())
    return make_diagnostic(ErrorId::ApiChannelBusy, SourceLoc{},
                           fmt::format("channel {} is {}: reset it or wait for its end", *busy + 1,
                                       kernel::state_name(last_.channels[*busy].program_state)));
  const auto path = folders_.resolve(program);
  if (!path) return path.error();
  const std::filesystem::path before = programs_[ch];
  programs_[ch] = *path;
  previews_[ch].clear();
  auto run = make_run(std::nullopt, 0);
  if (!run) {
    programs_[ch] = before;
    return run.error();
  }
  staged_ = std::move(*run);
  staged_search_.reset();
  return std::nullopt;
}

std::expected<std::unique_ptr<sim::DryRun>, Diagnostic> ServeApi::make_run(
    const std::optional<prep::SearchMark>& search, std::size_t search_channel, bool with_programs) const {
  sim::DryRunOptions o = served_run_options(folders_);
  o.search = search;
  o.search_channel = search_channel;
  for (std::size_t ch = 0; ch < o.skip_masks.size(); ++ch) o.skip_masks[ch] = last_.channels[ch].hli.skip_mask;
  // The new run starts where the axes stand (issue 48 item 10): the DRO
  // does not jump, and a block search returns to the contour from there.
  for (std::size_t ch = 0; ch < last_.channel_count && ch < o.start_mcs.size(); ++ch)
    o.start_mcs[ch] = last_.channels[ch].axis_mcs;
  for (std::size_t ch = 0; ch < last_.channel_count && ch < o.homed_axes.size(); ++ch)
    o.homed_axes[ch] = last_.channels[ch].homed_axes;  // LiveKernel hands on the newest at the swap
  auto run = sim::DryRun::create(machine_, with_programs ? programs_ : std::vector<std::filesystem::path>(programs_.size()), o);
  if (!run) return std::unexpected(run.error());
  auto live = std::make_unique<sim::DryRun>(std::move(*run));
  // The operator presses cycle start for every hold (M0, single step,
  // search); the switches and the override stay as the operator left them
  // (the skip levels already rule the decoding: DryRunOptions::skip_masks).
  for (std::size_t ch = 0; ch < machine_.channels.size() && ch < config::kMaxChannels; ++ch) {
    const plc::ChannelControl& c = last_.channels[ch].hli;
    const auto n = static_cast<std::uint8_t>(ch + 1);
    for (const sim::ScenarioAction& a :
         {sim::make_action(n, sim::act::AutoCycleStart{false}),
          sim::make_action(n, sim::act::FeedOverride{c.feed_override_percent}),
          sim::make_action(n, sim::act::RapidOverride{c.rapid_override_percent}),
          sim::make_action(n, sim::act::SingleStep{c.single_step}),
          sim::make_action(n, sim::act::OptionalStop{c.optional_stop}), sim::make_action(n, sim::act::Mode{c.manual_mode})})
      (void)live->machine().operate(a);
  }
  live->start_preparation_thread();
  return live;
}

HttpReply ServeApi::program_text(std::string_view target) const {
  const std::size_t ch = channel_of(target);
  if (ch < 1 || ch > programs_.size()) return error_reply(400, ErrorId::ApiBadValue, "'channel' is no channel of the machine");
  const std::string_view from_text = query_value(target, "from");
  const long long from = from_text.empty() ? 1 : std::atoll(std::string(from_text).c_str());
  if (from < 1) return error_reply(400, ErrorId::ApiBadValue, "'from' is a line number from 1 on");
  const std::filesystem::path& loaded = programs_[ch - 1];
  if (loaded.empty()) return HttpReply{200, "application/json", program_page(ch, loaded, static_cast<std::size_t>(from)), {}};
  // Resolved again: since the load the file may have become a link out of
  // the folders (its text was served), a FIFO or a larger file.
  const auto now = folders_.resolve(loaded.string());
  if (!now) return error_reply(400, now.error());
  return HttpReply{200, "application/json",
                   program_page(ch, loaded, static_cast<std::size_t>(from), kMaxProgramPageBytes, *now), {}};
}

// The check plans the whole program once per load (a 100,000-point
// preview in well under a second); later asks get the same answer.
HttpReply ServeApi::preview(std::string_view target) {
  const std::size_t ch = channel_of(target);
  if (ch < 1 || ch > programs_.size()) return error_reply(400, ErrorId::ApiBadValue, "'channel' is no channel of the machine");
  std::string& page = previews_[ch - 1];
  if (page.empty()) page = preview_page(machine_, ch, programs_[ch - 1]);
  return HttpReply{200, "application/json", page, {}};
}

HttpReply ServeApi::path_so_far(std::string_view target) const {
  const std::size_t ch = channel_of(target);
  if (ch < 1 || ch > programs_.size()) return error_reply(400, ErrorId::ApiBadValue, "'channel' is no channel of the machine");
  return HttpReply{200, "application/json", path_.json(ch, generation_), {}};
}

HttpReply ServeApi::upload(std::string_view target, std::string_view body) {
  const std::string_view wanted = query_value(target, "name");
  // A running program opens its subroutines when it calls them, and a
  // restart reads the program again: while one runs, nothing it may read is
  // replaced (new names are stored).
  if (const auto busy = busy_channel(); busy && folders_.upload_exists(wanted))
    return error_reply(409, ErrorId::ApiUploadReplacesRunning,
                       fmt::format("channel {} runs a program: '{}' is not replaced meanwhile", *busy + 1, wanted));
  const auto name = folders_.save_upload(wanted, body);
  if (!name) return error_reply(name.error().id == ErrorId::ApiTooLarge ? 413 : 400, name.error());
  for (std::string& p : previews_) p.clear();  // a loaded program (or one it calls) may be the file replaced
  return ok_json(json{{"ok", true}, {"program", *name}});
}

// The kernel runs a newer run than the one the server names events with:
// the old one goes (its preparation thread ends here, never in the kernel).
// The kernel took the next run: the server serves it from now on, and the
// stream says so before any of its events (`event: run`), so a page knows
// which run an event belongs to without guessing from the states.
void ServeApi::advance(std::vector<std::string>& frames) {
  std::unique_ptr<sim::DryRun> old = kernel_.take_retired();
  old.reset();
  serving_ = kernel_.current();
  ++generation_;
  frames_ = ChannelFrames{};
  last_errors_ = LastErrors{};  // a new run starts without an error
  path_.clear();
  frames.push_back(replay_.number(fmt::format("event: run\ndata: {{\"run\":{}}}\n\n", generation_), true));
}

void ServeApi::drain_events(std::vector<std::string>& frames) {
  std::string batch;
  const auto flush = [&] {
    if (!batch.empty()) frames.push_back(replay_.number(fmt::format("event: events\ndata: {}]\n\n", batch), true));
    batch.clear();
  };
  auto& q = kernel_.events();
  for (; !q.empty(); q.pop()) {
    const LiveEvent& le = q.front();
    if (le.generation > generation_) {  // every event of the old run came before
      flush();
      advance(frames);
    }
    const kernel::Event& e = le.event;
    last_errors_.take(e, RunNames{serving_});
    note_event(frames_, e, *serving_);
    batch += batch.empty() ? "[" : ",";
    batch += EventWriter::line(e, RunNames{serving_});
  }
  flush();
}

void ServeApi::collect(std::vector<std::string>& frames) {
  drain_events(frames);
  if (!kernel_.take_snapshot()) return;
  if (kernel_.snapshot().generation > generation_) {
    drain_events(frames);  // the old run's last events first
    if (kernel_.snapshot().generation > generation_) advance(frames);
  }
  last_ = kernel_.snapshot();
  path_.take(last_, machine_, channel_places(last_, machine_, frames_));
  frames.push_back(replay_.number(fmt::format("event: state\ndata: {}\n\n", state_frame()), false));
}

std::string ServeApi::state_frame() {
  json j = snapshot_json(last_, machine_, *serving_, frames_, &last_errors_);
  json programs = json::array();
  for (const auto& p : programs_) programs.push_back(p.empty() ? json() : json(p.filename().string()));
  j["programs"] = std::move(programs);
  j["staged"] = staged_ != nullptr;
  return dump_json(j);
}

// retry: a client that loses the stream reconnects after 1 s (and sends
// Last-Event-ID: the events it missed come before the state).
std::string ServeApi::stream_start(std::optional<std::uint64_t> last_event_id) {
  return fmt::format("retry: 1000\n\nevent: machine\ndata: {}\n\n{}event: state\ndata: {}\n\n",
                     dump_json(machine_json(machine_)), last_event_id ? replay_.since(*last_event_id) : "",
                     state_frame());
}

}  // namespace nck::app::serve
