// A live session (nck.Session wraps it): the machine runs cycle by cycle
// when asked, and each operator call builds the typed action a --plc
// scenario line builds, checked and resolved by the same code as nck
// serve's (sim::check_operator_action, DryRun::operate). Only action(line),
// a line the user typed, goes through the scenario parser.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "nck/run/simulation.hpp"
#include "nck/run/state_document.hpp"
#include "nck/sim/action_words.hpp"
#include "nck/sim/operator_action.hpp"
#include "py_common.hpp"
#include "py_interrupt.hpp"
#include "py_machine.hpp"
#include "py_run.hpp"
#include "py_turns.hpp"

namespace nck::py {
namespace {

const char* status_name(kernel::ChannelStatus s) {
  using S = kernel::ChannelStatus;
  switch (s) {
    case S::idle: return "idle";
    case S::running: return "running";
    case S::waiting: return "waiting";
    case S::ended: return "ended";
    case S::aborted: return "aborted";
  }
  return "idle";
}

// What run_until waits for; unset fields match nothing.
struct Until {
  std::optional<std::int64_t> n;            // a block numbered N<n> starts
  std::optional<std::uint32_t> line;        // a block of this main-program line starts
  std::optional<kernel::EventKind> event;   // the first event of this kind
  std::optional<double> time_s;             // simulated time reached
  bool matches(const app::EventRecord& e) const {
    const auto kind = static_cast<kernel::EventKind>(e.kind);
    if (event && kind == *event) return true;
    if (kind != kernel::EventKind::block) return false;
    if (n && e.n == *n) return true;
    return line && e.line == *line;
  }
};

class Session {
 public:
  Session(const Machine& m, std::vector<std::string> programs, std::string plc, double max_events_mb)
      : machine_(&m) {
    check_positive(max_events_mb, "max_events_mb");
    RunArgs args;
    args.programs = std::move(programs);
    args.plc = std::move(plc);
    opt_ = m.options(args);
    opt_.operator_present = true;
    sim_ = simulation();
    // Events wait for events(); past the bound the oldest go (a ring), not the session.
    sim_->outputs().event_memory.start(mb_bytes(max_events_mb), app::EventMemory::Full::drop_oldest);
    // The operator presses cycle start: a hold (M0, single step, stop) waits for it.
    for (std::size_t ch = 1; ch <= m.data.channels.size(); ++ch)
      operate(static_cast<std::int64_t>(ch), sim::act::AutoCycleStart{false}, {}, false);
  }

  // Cycle start. On a channel that runs no program (idle, after its end, a
  // reset or an error) while the session has one for it, and no other
  // channel runs one: the programs start again, as nck serve's cycle start
  // starts them. Otherwise the hold (M0/M1, single step, stop) is released.
  void cycle_start(std::int64_t ch) {
    if (restarts(ch)) restart(ch);
    else operate(ch, sim::act::CycleStart{});
  }

  void step(std::int64_t cycles) {
    if (cycles < 0)
      raise("ArgumentError", ErrorId::AppBadArgument, fmt::format("step({}): a cycle count is 0 or more", cycles));
    // Ctrl-C stops between two cycles: the session stays whole (not the
    // simulation's stop flag, which would also stop decoding for good).
    std::atomic<bool> pressed{false};
    const CtrlC ctrl_c(pressed);
    {
      pyb::gil_scoped_release no_gil;
      for (std::int64_t i = 0; i < cycles && !pressed.load(std::memory_order_relaxed); ++i) sim_->cycle();
    }
    ctrl_c.raise_if_pressed();
  }

  // true once the condition came; false when nothing changes any more
  // without the operator (waits_for_operator) or max_cycles passed first.
  bool run_until(const Until& u, std::int64_t max_cycles) {
    if (max_cycles < 0)
      raise("ArgumentError", ErrorId::AppBadArgument, fmt::format("max_cycles {} is negative", max_cycles));
    std::atomic<bool> pressed{false};
    const CtrlC ctrl_c(pressed);
    bool reached = false;
    {
      pyb::gil_scoped_release no_gil;
      reached = cycles_until(u, max_cycles, pressed);
    }
    ctrl_c.raise_if_pressed();
    return reached;
  }

  bool cycles_until(const Until& u, std::int64_t max_cycles, const std::atomic<bool>& pressed) {
    const app::EventMemory& events = sim_->outputs().event_memory;
    for (std::int64_t i = 0; i < max_cycles && !pressed.load(std::memory_order_relaxed); ++i) {
      const std::uint64_t seen = events.total();
      sim_->cycle();
      // counted from the run's first event: a full memory drops its oldest within the cycle
      for (std::uint64_t k = std::max(seen, events.first()); k < events.total(); ++k)
        if (u.matches(events.records[k - events.first()])) return true;
      if (u.time_s && sim_->run().time_s() >= *u.time_s) return true;
      if (waits_for_operator()) return false;
    }
    return false;
  }

  // One operator line the user typed ("feed_override 80", "ch=2 feedhold on", "mdi G0 X10").
  void action(const std::string& line) {
    Diagnostics ds;
    const std::optional<sim::OperatorAction> op = sim::parse_operator_action(line, sim_->machine(), ds, "python");
    if (op && op->action.kind() == sim::ActionKind::cycle_start && restarts(op->action.channel))
      return restart(op->action.channel);  // as cycle_start(): a typed line means the same
    run(op, ds);
  }

  // A typed operator action for channel ch (1-based), checked as a scenario
  // line; `record`: an "operator" event says so (not the session's own setup).
  void operate(std::int64_t ch, const sim::ActionPayload& payload, std::string mdi_text = {}, bool record = true) {
    // Beyond 255 the channel is as wrong as at 255 (kMaxChannels is far below).
    sim::OperatorAction op{sim::ScenarioAction{}, std::move(mdi_text)};
    op.action.channel = static_cast<std::uint8_t>(std::clamp<std::int64_t>(ch, 0, 255));
    op.action.payload = payload;
    Diagnostics ds;
    run(sim::check_operator_action(std::move(op), sim_->machine(), ds, "python", sim::Quoting::python), ds, record);
  }

  void skip_mask(std::int64_t ch, std::int64_t mask) {
    if (mask > static_cast<std::int64_t>(sim::words::kAllSkipLevels))
      refuse(fmt::format("ch={} skip_mask {:#x}", ch, mask), ErrorId::PlcScenarioBadNumber,
             sim::words::not_a_skip_mask(fmt::format("{:#x}", mask)));
    operate(ch, sim::act::SkipMask{static_cast<std::uint32_t>(mask)});
  }

  // The spindle override of channel ch's spindle `name` (the refusal quotes
  // the line without the channel, as it always has).
  void spindle_override(std::int64_t ch, const std::string& name, double percent) {
    sim::act::SpindleOverride o;
    if (!fits(name, o.spindle.name))
      refuse(fmt::format("override {} {:g}", name, percent), ErrorId::PlcScenarioBadSpindleName,
             sim::words::not_a_spindle(shown(name)));
    o.percent = percent;
    operate(ch, o);
  }

  void jog(std::int64_t ch, const std::string& axis, const std::string& direction, std::optional<double> speed_mm_min) {
    const std::string speed = speed_mm_min ? fmt::format(" {:g}", *speed_mm_min) : "";
    const std::string line = fmt::format("ch={} jog {} {}{}", ch, axis, direction, speed);
    sim::act::Jog j;
    if (!fits(axis, j.axis.name)) refuse(line, ErrorId::PlcScenarioBadNumber, sim::words::not_an_axis(shown(axis)));
    const std::optional<std::int8_t> d = sim::jog_direction_word(direction, true);
    if (!d) refuse(line, ErrorId::PlcScenarioBadJog, sim::words::not_a_jog_direction(shown(direction), true));
    j.direction = *d;
    if (speed_mm_min && j.direction == 0)  // a released key has no speed
      refuse(line, ErrorId::PlcScenarioExtraArgument,
             fmt::format("'{:g}' is one word too many for 'jog'; remove it or start a comment with #", *speed_mm_min));
    if (speed_mm_min && !(*speed_mm_min > 0))
      refuse(line, ErrorId::PlcScenarioBadJog, sim::words::not_a_jog_speed(fmt::format("{:g}", *speed_mm_min)));
    j.speed_mm_min = speed_mm_min.value_or(0);
    operate(ch, j);
  }

  // A signed step: its sign is the direction.
  void jog_increment(std::int64_t ch, const std::string& axis, double step_mm) {
    sim::act::JogIncrement j;
    j.direction = step_mm < 0 ? -1 : 1;
    j.step_mm = std::abs(step_mm);
    if (!fits(axis, j.axis.name))
      refuse(fmt::format("ch={} jog_increment {} {} {:g}", ch, axis, j.direction < 0 ? "-" : "+", j.step_mm),
             ErrorId::PlcScenarioBadNumber, sim::words::not_an_axis(shown(axis)));
    operate(ch, j);
  }

  void mode(std::int64_t ch, const std::string& name) {
    const std::optional<bool> manual = sim::manual_mode_word(name);
    if (!manual)
      refuse(fmt::format("ch={} mode {}", ch, name), ErrorId::PlcScenarioBadMode, sim::words::not_a_mode(shown(name)));
    operate(ch, sim::act::Mode{*manual});
  }

  // MDI text runs at once: one cycle decodes it, and an error in it raises
  // ProgramError (the session stays usable). The run's error list has each
  // NC error with its text, kept or not as an event.
  void mdi(const std::string& text, std::int64_t channel) {
    const std::vector<app::FinalError>& errors = sim_->outputs().errors;
    submit_mdi(channel, text);
    const std::size_t seen = errors.size();
    step(1);
    for (std::size_t k = seen; k < errors.size(); ++k) {
      const app::FinalError& e = errors[k];
      if (static_cast<std::int64_t>(e.channel) != channel || e.id == number(ErrorId::AppChannelReset)) continue;  // a scenario's reset is none
      throw NckError{"ProgramError", {make_diagnostic(static_cast<ErrorId>(e.id), SourceLoc{e.file, e.line, 0}, e.msg)}};
    }
  }

  pyb::list take_events() {
    app::EventMemory& events = sim_->outputs().event_memory;
    pyb::list out = event_dicts(events);
    events.clear();
    return out;
  }

  pyb::object state() const;
  nlohmann::json session_fields() const;

  // Nothing changes any more without the operator: no channel runs a
  // program or MDI block (a hold waits for cycle start), none jogs, and the
  // --plc scenario has no line left.
  bool waits_for_operator() const {
    const kernel::Kernel& k = sim_->run().kernel();
    for (std::size_t ch = 0; ch < k.channel_count(); ++ch) {
      const kernel::ProgramState st = k.program_state(ch);
      const bool still = st == kernel::ProgramState::idle || st == kernel::ProgramState::hold ||
                         st == kernel::ProgramState::ended || st == kernel::ProgramState::error;
      if (!still || k.channel_jogging(ch)) return false;
    }
    return !sim_->run().machine().scenario_pending();
  }

  double time_s() const { return sim_->run().time_s(); }
  std::uint64_t cycles() const { return sim_->run().kernel().cycles(); }
  pyb::list errors() const {
    pyb::list out;
    for (const app::FinalError& e : past_errors_) out.append(error_dict(e));
    for (const app::FinalError& e : sim_->outputs().errors) out.append(error_dict(e));
    return out;
  }
  std::vector<std::string> messages() { return sim_->outputs().console.take(); }

 private:
  void run(const std::optional<sim::OperatorAction>& op, const Diagnostics& ds, bool record = true) {
    if (!op) throw NckError{"ActionError", ds.items()};
    if (std::optional<Diagnostic> refused = sim_->run().operate(*op)) throw NckError{"ActionError", {*refused}};
    // the state's last_error goes with the reset, also of an idle channel (as nck serve's)
    if (op->action.kind() == sim::ActionKind::reset) sim_->outputs().last_errors.clear(op->action.channel);
    if (record) record_action(*op);
  }
  std::unique_ptr<app::Simulation> simulation() const;
  bool restarts(std::int64_t ch) const;
  void restart(std::int64_t ch);
  void record_action(const sim::OperatorAction& op);
  [[noreturn]] static void refuse(std::string_view line, ErrorId id, std::string_view message) {
    throw NckError{"ActionError", {sim::operator_action_refused(line, id, message, "python")}};
  }
  static std::string shown(std::string_view word) { return sim::operator_action_shown(word); }
  // A name the action can hold (at most 15 characters), copied into it.
  template <std::size_t N>
  static bool fits(const std::string& name, std::array<char, N>& to) {
    if (name.size() >= N) return false;
    std::copy(name.begin(), name.end(), to.begin());
    return true;
  }
  void submit_mdi(std::int64_t channel, const std::string& text);

 public:
  // The session for one Python caller (locked(), py_turns.hpp).
  Turns::Turn hold() { return turns_.take(); }

 private:
  const Machine* machine_;  // kept alive by the Python Session (keep_alive)
  app::RunOptions opt_;     // the session's programs and scenario, for a restart
  std::unique_ptr<app::Simulation> sim_;
  std::vector<app::FinalError> past_errors_;  // of the runs before a restart
  std::uint64_t runs_ = 1;                    // the session's runs (the state's "run")
  Turns turns_;
};

// One Python caller in a session at a time: step and run_until release the
// GIL, so a second thread could enter the same session mid-cycle (two
// threads stepping one session corrupted memory). Every bound call takes
// the session first; calls within the session (mdi's step) do not.
template <class R, class... A>
auto locked(R (Session::*method)(A...)) {
  return [method](Session& s, A... args) -> R {
    const auto session = s.hold();
    return (s.*method)(std::forward<A>(args)...);
  };
}
template <class R, class... A>
auto locked(R (Session::*method)(A...) const) {
  return [method](Session& s, A... args) -> R {
    const auto session = s.hold();
    return (s.*method)(std::forward<A>(args)...);
  };
}
template <class R, class... A>
auto locked(R (*call)(Session&, A...)) {
  return [call](Session& s, A... args) -> R {
    const auto session = s.hold();
    return call(s, std::forward<A>(args)...);
  };
}

// The session's MDI text as it has always been taken (a scenario line's
// rest): one line, a '#' ends it, the blanks around it dropped.
void Session::submit_mdi(std::int64_t channel, const std::string& text) {
  if (text.find_first_of("\r\n") != std::string::npos)
    throw NckError{"ActionError", {make_diagnostic(ErrorId::PlcOperatorActionBad, SourceLoc{},
                                                   "an operator action is one line")}};
  constexpr std::string_view kBlanks = " \t\v\f";
  std::string_view t = std::string_view(text).substr(0, text.find('#'));
  t.remove_prefix(std::min(t.size(), t.find_first_not_of(kBlanks)));
  t = t.substr(0, t.find_last_not_of(kBlanks) + 1);
  if (t.empty())
    refuse(fmt::format("ch={} mdi {}", channel, text), ErrorId::PlcScenarioMissingArgument,
           fmt::format("missing {}", sim::words::kMissingMdiText));
  operate(channel, sim::act::Mdi{}, std::string(t));
}

// A new run of the session's programs and scenario.
std::unique_ptr<app::Simulation> Session::simulation() const {
  auto created = app::Simulation::create(machine_->data, opt_, app::Simulation::Host::embedded);
  if (!created) {
    NckError e{"ProgramError", {}};
    for (const Diagnostic& d : created.error().items())
      if (d.severity == Severity::error) e.diagnostics.push_back(d);
    throw e;
  }
  return std::move(*created);
}

// Channel ch (1-based) has a program and no channel runs one (a restart
// would end another channel's program midway).
bool Session::restarts(std::int64_t ch) const {
  const kernel::Kernel& k = sim_->run().kernel();
  if (ch < 1 || static_cast<std::size_t>(ch) > opt_.programs.size()) return false;
  for (std::size_t c = 0; c < k.channel_count(); ++c) {
    const kernel::ProgramState st = k.program_state(c);
    if (st != kernel::ProgramState::idle && st != kernel::ProgramState::ended && st != kernel::ProgramState::error)
      return false;
  }
  return true;
}

// The programs again from their start, as nck serve's cycle start loads a
// new run: the operator's switches stay as they were (feed and rapid
// override, single step, optional stop, mode, skip levels), the events not
// yet taken and the errors so far are kept; time starts at 0 again.
void Session::restart(std::int64_t ch) {
  std::unique_ptr<app::Simulation> next = simulation();
  const plc::HliImage& hli = sim_->run().machine().hli();
  for (std::size_t c = 0; c < machine_->data.channels.size(); ++c) {
    const plc::ChannelControl& was = hli.channel[c];
    const auto n = static_cast<std::uint8_t>(c + 1);
    for (const sim::ScenarioAction& a :
         {sim::make_action(n, sim::act::AutoCycleStart{false}), sim::make_action(n, sim::act::FeedOverride{was.feed_override_percent}),
          sim::make_action(n, sim::act::RapidOverride{was.rapid_override_percent}),
          sim::make_action(n, sim::act::SingleStep{was.single_step}),
          sim::make_action(n, sim::act::OptionalStop{was.optional_stop}), sim::make_action(n, sim::act::Mode{was.manual_mode}),
          sim::make_action(n, sim::act::SkipMask{was.skip_mask})})
      (void)next->run().machine().operate(a);
  }
  next->outputs().event_memory = std::move(sim_->outputs().event_memory);
  past_errors_.insert(past_errors_.end(), sim_->outputs().errors.begin(), sim_->outputs().errors.end());
  sim_ = std::move(next);
  ++runs_;
  sim::OperatorAction op{sim::make_action(static_cast<std::uint8_t>(ch), sim::act::CycleStart{}), {}};
  record_action(op);
}

// An operator action the session took, as an "operator" event (docs/outputs.md):
// the scenario line it means, without the channel, which "ch" gives.
void Session::record_action(const sim::OperatorAction& op) {
  std::string line = sim::operator_line(op, sim::Quoting::api);
  if (line.starts_with("ch=")) line.erase(0, std::min(line.size(), line.find(' ') + 1));
  if (op.action.kind() == sim::ActionKind::mdi) line = "mdi " + op.mdi_text;
  nlohmann::ordered_json j;
  j["t"] = sim_->run().time_s();
  j["ch"] = op.action.channel;
  j["ev"] = app::kOperatorEventName;
  j["action"] = line;
  app::EventRecord head;
  head.t_s = sim_->run().time_s();
  head.channel = op.action.channel;
  head.kind = app::kOperatorEventKind;
  (void)sim_->outputs().event_memory.add(head, j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
}

// Adds what `into` lacks of `from`, object by object and array element by
// element: the session's fields from before the one writer stay beside it.
void add_missing(nlohmann::ordered_json& into, const nlohmann::ordered_json& from) {
  if (into.is_array() && from.is_array()) {
    for (std::size_t i = 0; i < into.size() && i < from.size(); ++i) add_missing(into[i], from[i]);
    return;
  }
  if (!into.is_object() || !from.is_object()) return;
  for (auto it = from.begin(); it != from.end(); ++it) {
    const auto found = into.find(it.key());
    if (found == into.end()) into[it.key()] = it.value();
    else add_missing(*found, it.value());
  }
}

// The state document of nck serve's GET /api/v1/state, by its one writer
// (app::state_json, issue 47 item 5), with the session's earlier fields
// beside it: the --final document's positions, offsets, tools, spindles
// and HLI, and per channel ch, status, line, n, file.
pyb::object Session::state() const {
  const sim::DryRun& run = sim_->run();
  auto snap = std::make_unique<app::LiveSnapshot>();
  app::fill_snapshot(run, sim_->last_cycle(), *snap);
  snap->generation = runs_;
  snap->speed = 0;  // the session's cycles run as fast as they are asked for ("max")
  std::array<app::ChannelPlace, config::kMaxChannels> places{};
  for (std::size_t c = 0; c < run.kernel().channel_count() && c < places.size(); ++c) {
    const sim::ChannelSnapshot cs = run.snapshot(c);
    places[c].pcs = cs.axis_pcs;
    // the modal state of the block in execution (as nck serve's), else the decoder's
    const std::optional<nc::ModalState>& running = sim_->outputs().blocks[c].modal;
    places[c].modal = running ? *running : cs.modal;
  }
  nlohmann::ordered_json doc = app::state_json(*snap, sim_->machine(), run, places, &sim_->outputs().last_errors);
  const nlohmann::ordered_json before = nlohmann::ordered_json::parse(
      session_fields().dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
  // Spindles: the session has always named them as keys (--final's layout);
  // each gains the one writer's fields of the same spindle.
  nlohmann::ordered_json spindles = before.at("spindles");
  for (const nlohmann::ordered_json& sp : doc["spindles"])
    if (spindles.contains(sp["name"].get<std::string>())) add_missing(spindles[sp["name"].get<std::string>()], sp);
  doc["spindles"] = std::move(spindles);
  add_missing(doc, before);
  return to_python(doc);
}

// The session's state before the one writer: the --final document's
// positions, spindles and HLI, with each channel's program state, block,
// path velocity and wait of the last cycle.
nlohmann::json Session::session_fields() const {
  const sim::DryRun& run = sim_->run();
  nlohmann::json doc = app::final_json(sim_->machine(), run, run.time_s(), "running", {}, nlohmann::ordered_json::object());
  doc.erase("end");
  doc.erase("errors");
  doc.erase("time_by_cause");
  doc.erase("format");
  doc["t"] = run.time_s();
  doc["cycle"] = run.kernel().cycles();
  for (std::size_t c = 0; c < run.kernel().channel_count() && c < doc["channels"].size(); ++c) {
    const kernel::ChannelState st = run.kernel().channel_state(c);
    nlohmann::json& ch = doc["channels"][c];
    ch["ch"] = c + 1;
    ch["status"] = status_name(st.status);
    ch["line"] = st.at.line;
    ch["n"] = st.at.n ? nlohmann::json(*st.at.n) : nlohmann::json(nullptr);
    ch["file"] = sim_->names().file(c, st.at.file_id);
  }
  return doc;
}

}  // namespace

void bind_session(pyb::module_& m) {
  pyb::class_<Until>(m, "_Until")
      .def(pyb::init([](std::optional<std::int64_t> n, std::optional<std::uint32_t> line,
                        std::optional<std::string> event, std::optional<double> time_s) {
             std::optional<kernel::EventKind> kind = event ? app::event_kind_from(*event) : std::nullopt;
             if (event && *event == app::kOperatorEventName) kind = static_cast<kernel::EventKind>(app::kOperatorEventKind);
             if (event && !kind)
               raise("ArgumentError", ErrorId::AppBadArgument,
                     fmt::format("'{}' is no event kind (docs/outputs.md: block, wait, error, end, state, operator ...)", *event));
             return Until{n, line, kind, time_s};
           }),
           pyb::arg("n"), pyb::arg("line"), pyb::arg("event"), pyb::arg("time_s"));
  pyb::class_<Session>(m, "_Session")
      .def(pyb::init<const Machine&, std::vector<std::string>, std::string, double>(), pyb::arg("machine"),
           pyb::arg("programs"), pyb::arg("plc"), pyb::arg("max_events_mb"), pyb::keep_alive<1, 2>())
      .def("step", locked(&Session::step), pyb::arg("cycles"))
      .def("run_until", locked(&Session::run_until), pyb::arg("until"), pyb::arg("max_cycles"))
      .def("action", locked(&Session::action), pyb::arg("line"))
      .def("cycle_start", locked(&Session::cycle_start), pyb::arg("ch"))
      .def("stop", locked(+[](Session& s, std::int64_t ch) { s.operate(ch, sim::act::Stop{}); }), pyb::arg("ch"))
      .def("reset", locked(+[](Session& s, std::int64_t ch) { s.operate(ch, sim::act::Reset{}); }),
           pyb::arg("ch"))
      .def("feedhold", locked(+[](Session& s, std::int64_t ch, bool on) { s.operate(ch, sim::act::Feedhold{on}); }),
           pyb::arg("ch"), pyb::arg("on"))
      .def("single_step",
           locked(+[](Session& s, std::int64_t ch, bool on) { s.operate(ch, sim::act::SingleStep{on}); }),
           pyb::arg("ch"), pyb::arg("on"))
      .def("optional_stop",
           locked(+[](Session& s, std::int64_t ch, bool on) { s.operate(ch, sim::act::OptionalStop{on}); }),
           pyb::arg("ch"), pyb::arg("on"))
      .def("feed_override",
           locked(+[](Session& s, std::int64_t ch, double pct) { s.operate(ch, sim::act::FeedOverride{pct}); }),
           pyb::arg("ch"), pyb::arg("percent"))
      .def("rapid_override",
           locked(+[](Session& s, std::int64_t ch, double pct) { s.operate(ch, sim::act::RapidOverride{pct}); }),
           pyb::arg("ch"), pyb::arg("percent"))
      .def("spindle_override", locked(&Session::spindle_override), pyb::arg("ch"), pyb::arg("spindle"),
           pyb::arg("percent"))
      .def("skip_mask", locked(&Session::skip_mask), pyb::arg("ch"), pyb::arg("mask"))
      .def("jog", locked(&Session::jog), pyb::arg("ch"), pyb::arg("axis"), pyb::arg("direction"),
           pyb::arg("speed_mm_min"))
      .def("jog_increment", locked(&Session::jog_increment), pyb::arg("ch"), pyb::arg("axis"), pyb::arg("step_mm"))
      .def("mode", locked(&Session::mode), pyb::arg("ch"), pyb::arg("name"))
      .def("mdi", locked(&Session::mdi), pyb::arg("text"), pyb::arg("channel"))
      .def("events", locked(&Session::take_events))
      .def("state", locked(&Session::state))
      .def("errors", locked(&Session::errors))
      .def("messages", locked(&Session::messages))
      .def_property_readonly("time_s", locked(&Session::time_s))
      .def_property_readonly("cycles", locked(&Session::cycles));
}

}  // namespace nck::py
