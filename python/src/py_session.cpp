// A live session (nck.Session wraps it): the machine runs cycle by cycle
// when asked, and the operator's actions reach it as one line of the --plc
// scenario grammar (sim::parse_operator_action, DryRun::operate): the same
// layer as a scenario file and nck serve, no second implementation.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include "nck/run/simulation.hpp"
#include "nck/sim/operator_action.hpp"
#include "py_common.hpp"
#include "py_interrupt.hpp"
#include "py_machine.hpp"

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
  std::optional<std::int64_t> n;     // a block numbered N<n> starts
  std::optional<std::uint32_t> line; // a block of this main-program line starts
  std::optional<std::string> event;  // the first event of this "ev" kind
  std::optional<double> time_s;      // simulated time reached
  bool matches(const nlohmann::ordered_json& e) const {
    const std::string& ev = e["ev"].get_ref<const std::string&>();
    if (event && ev == *event) return true;
    if (ev != "block") return false;
    if (n && e["n"].is_number_integer() && e["n"].get<std::int64_t>() == *n) return true;
    return line && e["line"].get<std::uint32_t>() == *line;
  }
};

class Session {
 public:
  Session(const Machine& m, std::vector<std::string> programs, std::string plc) : machine_(&m) {
    RunArgs args;
    args.programs = std::move(programs);
    args.plc = std::move(plc);
    app::RunOptions opt = m.options(args);
    opt.operator_present = true;
    auto created = app::Simulation::create(m.data, opt, app::Simulation::Host::embedded);
    if (!created) {
      NckError e{"ProgramError", {}};
      for (const Diagnostic& d : created.error().items())
        if (d.severity == Severity::error) e.diagnostics.push_back(d);
      throw e;
    }
    sim_ = std::move(*created);
    // The operator presses cycle start: a hold (M0, single step, stop) waits for it.
    for (std::size_t ch = 1; ch <= m.data.channels.size(); ++ch) action(fmt::format("ch={} auto_cycle_start off", ch));
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
    auto& events = sim_->outputs().event_list;
    for (std::int64_t i = 0; i < max_cycles && !pressed.load(std::memory_order_relaxed); ++i) {
      const std::size_t seen = events.size();
      sim_->cycle();
      for (std::size_t k = seen; k < events.size(); ++k)
        if (u.matches(events[k])) return true;
      if (u.time_s && sim_->run().time_s() >= *u.time_s) return true;
      if (waits_for_operator()) return false;
    }
    return false;
  }

  // One operator line ("feed_override 80", "ch=2 feedhold on", "mdi G0 X10").
  void action(const std::string& line) {
    Diagnostics ds;
    const std::optional<sim::OperatorAction> op = sim::parse_operator_action(line, sim_->machine(), ds, "python");
    if (!op) throw NckError{"ActionError", ds.items()};
    if (std::optional<Diagnostic> refused = sim_->run().operate(*op)) throw NckError{"ActionError", {*refused}};
  }

  // MDI text runs at once: one cycle decodes it, and an error in it raises
  // ProgramError (the session stays usable).
  void mdi(const std::string& text, int channel) {
    auto& events = sim_->outputs().event_list;
    action(fmt::format("ch={} mdi {}", channel, text));
    const std::size_t seen = events.size();
    step(1);
    for (std::size_t k = seen; k < events.size(); ++k) {
      const nlohmann::ordered_json& e = events[k];
      if (e["ev"] != "error" || e.value("ch", 0) != channel) continue;
      throw NckError{"ProgramError",
                     {make_diagnostic(static_cast<ErrorId>(e["id"].get<std::uint32_t>()),
                                      SourceLoc{"mdi", 1, 0}, e["msg"].get<std::string>())}};
    }
  }

  pyb::list take_events() {
    auto& events = sim_->outputs().event_list;
    pyb::list out(events.size());
    for (std::size_t i = 0; i < events.size(); ++i) out[i] = to_python(events[i]);
    events.clear();
    return out;
  }

  pyb::object state() const;

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
    for (const app::FinalError& e : sim_->outputs().errors) out.append(error_dict(e));
    return out;
  }
  std::vector<std::string> messages() { return sim_->outputs().console.take(); }

 private:
  const Machine* machine_;  // kept alive by the Python Session (keep_alive)
  std::unique_ptr<app::Simulation> sim_;
};

// The --final document's positions, spindles and HLI, with each channel's
// program state, block, path velocity and wait of the last cycle.
pyb::object Session::state() const {
  const sim::DryRun& run = sim_->run();
  nlohmann::json doc = app::final_json(sim_->machine(), run, run.time_s(), "running", {}, nlohmann::ordered_json::object());
  doc.erase("end");
  doc.erase("errors");
  doc.erase("time_by_cause");
  doc.erase("format");
  doc["t"] = run.time_s();
  doc["cycle"] = run.kernel().cycles();
  const kernel::TickOutput& o = sim_->last_cycle();
  for (std::size_t c = 0; c < run.kernel().channel_count() && c < doc["channels"].size(); ++c) {
    const kernel::ChannelState st = run.kernel().channel_state(c);
    nlohmann::json& ch = doc["channels"][c];
    ch["ch"] = c + 1;
    ch["program_state"] = kernel::state_name(st.program_state);
    ch["status"] = status_name(st.status);
    ch["line"] = st.at.line;
    ch["n"] = st.at.n ? nlohmann::json(*st.at.n) : nlohmann::json(nullptr);
    ch["file"] = sim_->names().file(c, st.at.file_id);
    ch["path_velocity_mm_s"] = o.channels[c].path_velocity_mm_s;
    ch["wait"] = o.channels[c].cause == kernel::CycleCause::wait
                     ? nlohmann::json(kernel::wait_reason_name(o.channels[c].wait_reason))
                     : nlohmann::json(nullptr);
  }
  return to_python(doc);
}

}  // namespace

void bind_session(pyb::module_& m) {
  pyb::class_<Until>(m, "_Until")
      .def(pyb::init([](std::optional<std::int64_t> n, std::optional<std::uint32_t> line,
                        std::optional<std::string> event, std::optional<double> time_s) {
             if (event && !app::event_kind_from(*event))
               raise("ArgumentError", ErrorId::AppBadArgument,
                     fmt::format("'{}' is no event kind (docs/outputs.md: block, wait, error, end, state ...)", *event));
             return Until{n, line, event, time_s};
           }),
           pyb::arg("n"), pyb::arg("line"), pyb::arg("event"), pyb::arg("time_s"));
  pyb::class_<Session>(m, "_Session")
      .def(pyb::init<const Machine&, std::vector<std::string>, std::string>(), pyb::arg("machine"),
           pyb::arg("programs"), pyb::arg("plc"), pyb::keep_alive<1, 2>())
      .def("step", &Session::step, pyb::arg("cycles"))
      .def("run_until", &Session::run_until, pyb::arg("until"), pyb::arg("max_cycles"))
      .def("action", &Session::action, pyb::arg("line"))
      .def("mdi", &Session::mdi, pyb::arg("text"), pyb::arg("channel"))
      .def("events", &Session::take_events)
      .def("state", &Session::state)
      .def("errors", &Session::errors)
      .def("messages", &Session::messages)
      .def_property_readonly("time_s", &Session::time_s)
      .def_property_readonly("cycles", &Session::cycles);
}

}  // namespace nck::py
