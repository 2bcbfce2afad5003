#pragma once
// One run of the kernel in progress — the machine, its --plc scenario, the
// dry run and where its results go — cycle by cycle. `nck run` drives it to
// the end and writes files; the Python module's Machine.run does the same
// into memory, and its Session steps it and operates it in between: one run
// loop for all three.
#include <atomic>
#include <expected>
#include <memory>
#include <optional>
#include <string>

#include "nck/config/machine.hpp"
#include "nck/core/diagnostic.hpp"
#include "nck/run/progress.hpp"
#include "nck/run/run_options.hpp"
#include "nck/run/run_outputs.hpp"
#include "nck/run/stop_at.hpp"
#include "nck/sim/dry_run.hpp"
#include "nck/sim/scenario.hpp"

namespace nck::app {

class Simulation {
 public:
  // Who runs it: `nck run` (stderr printed, the process's stop flag, which
  // signals raise) or a library user in a longer-lived process (the Python
  // module: stderr's lines kept, a stop flag of the run's own; it keeps the
  // events by starting outputs().event_memory).
  enum class Host : std::uint8_t { cli, embedded };
  // setup: the run `opt` asks for on machine `m` (opt.machine and its files
  // are not read again). The error: why it cannot run (exit 2); print
  // each with cli_text.
  static std::expected<std::unique_ptr<Simulation>, Diagnostics> create(config::Machine m, const RunOptions& opt,
                                                                        Host host = Host::cli);
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;
  ~Simulation();

  // One cycle: preparation, the kernel, and every output of the cycle.
  void cycle();
  // Cycles until every channel ended (nullopt) or something stops the run:
  // opt's limits, --stop-at, a hold nothing releases, the stop flag.
  std::optional<kernel::EndReason> run_to_end();
  // After the last cycle: ends preparation and every channel still running
  // (`stopped`), sums the time by cause. Then exit_code(), end_reason() and
  // final_json() may be read.
  void finish(std::optional<kernel::EndReason> stopped);
  // As README lists them: 0 program end, 1 NC error or a limit, 130/143 SIGINT/SIGTERM.
  int exit_code() const;
  // The final state's "end": why the run ended.
  std::string end_reason() const;
  nlohmann::json final_json() const;

  // The stop flag the run obeys (Host::embedded: the run's own, which a
  // WallClockLimit of the caller may raise; else nullptr: the process's).
  std::atomic<bool>* own_stop_flag() { return stop_ == &own_stop_ ? &own_stop_ : nullptr; }

  sim::DryRun& run() { return *run_; }
  const sim::DryRun& run() const { return *run_; }
  const config::Machine& machine() const { return *machine_; }
  RunOutputs& outputs() { return out_; }
  const RunNames& names() const { return names_; }
  const RunOptions& options() const { return opt_; }
  bool trace_full() const { return trace_full_; }
  // The last cycle's output (a session's path velocity, waits).
  const kernel::TickOutput& last_cycle() const { return *tick_; }

 private:
  Simulation(const RunOptions& opt, Host host);
  void record_events(const kernel::TickOutput& o);
  void report_dropped_events(const kernel::TickOutput& o);
  void report_refusals(const kernel::TickOutput& o);
  void report_events_dropped(const kernel::TickOutput& o);
  void end_unfinished_channels(kernel::EndReason reason);
  void report_memory_full(ErrorId id, const char* what, std::uint64_t max_bytes);

  RunOptions opt_;
  std::unique_ptr<config::Machine> machine_;
  std::unique_ptr<sim::Scenario> scenario_;  // the dry run points into it
  std::unique_ptr<sim::DryRun> run_;
  RunOutputs out_;
  RunNames names_;
  BlockEventText block_text_;  // block events written without a JSON object
  Progress progress_;
  std::optional<StopAtWatch> stop_at_;
  std::unique_ptr<kernel::TickOutput> tick_;
  std::atomic<bool> own_stop_{false};
  const std::atomic<bool>* stop_ = nullptr;
  bool stop_at_reached_ = false;
  bool trace_full_ = false;
  std::optional<kernel::EndReason> stopped_;
};

// A diagnostic as `nck run` prints it: bad usage as "nck: error ID: text",
// the rest as format(d).
std::string cli_text(const Diagnostic& d);

}  // namespace nck::app
