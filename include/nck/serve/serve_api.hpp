#pragma once
// nck serve's API (docs/api.md): the page and its files, the state, the
// machine, the programs one may load, the commands, the stream. Runs in the
// server thread; reaches the kernel only through LiveKernel.
#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "nck/config/machine.hpp"
#include "nck/serve/http_server.hpp"
#include "nck/serve/live_kernel.hpp"
#include "nck/serve/live_path.hpp"
#include "nck/serve/offset_book.hpp"
#include "nck/serve/program_folders.hpp"
#include "nck/serve/snapshot_json.hpp"
#include "nck/serve/stream_replay.hpp"
#include "nck/sim/operator_action.hpp"

namespace nck::app::serve {

struct ApiCommand;

// The options every served run is made with — the first one, made before
// the API, too: preparation in its thread, block maps and modal states for
// the state, and the folders every file a program or MDI opens must lie in
// (an empty list would let the first run's MDI open any file).
sim::DryRunOptions served_run_options(const ProgramFolders& folders);

class ServeApi : public ApiHandler {
 public:
  ServeApi(const config::Machine& m, LiveKernel& kernel, ProgramFolders folders);

  HttpReply handle(const HttpRequest& r) override;
  void collect(std::vector<std::string>& frames) override;
  std::string stream_start(std::optional<std::uint64_t> last_event_id) override;

  // A fresh run of the loaded programs (setup side), ready to hand over;
  // the reason when a program cannot be opened.
  // with_programs false: a run without programs (the idle machine).
  std::expected<std::unique_ptr<sim::DryRun>, Diagnostic> make_run(const std::optional<prep::SearchMark>& search,
                                                                   std::size_t search_channel,
                                                                   bool with_programs = true) const;
  // Loads `program` into channel ch (0-based) and stages the run.
  std::optional<Diagnostic> load(std::size_t ch, const std::string& program);

 private:
  HttpReply command(std::string_view body);
  HttpReply act(const ApiCommand& c);
  HttpReply mdi(std::size_t ch, const std::string& text, bool queue);
  HttpReply operate(const std::optional<sim::OperatorAction>& op, const Diagnostics& diags);
  HttpReply pass_on(const sim::ScenarioAction& a);
  HttpReply start_or_release(std::size_t ch, const sim::ScenarioAction& cycle_start);
  // E-stop and machine on (machine_input.cpp).
  HttpReply machine_input(std::string_view path, std::string_view body);
  std::optional<HttpReply> refused_by_machine(sim::ActionKind kind, std::size_t ch) const;
  // POST /api/v1/home: G74 for the named axes through MDI (home_api.cpp).
  HttpReply home(std::string_view body);
  void note_machine_input(const sim::ScenarioAction& a);
  HttpReply program_text(std::string_view target) const;
  HttpReply preview(std::string_view target);
  HttpReply path_so_far(std::string_view target) const;
  HttpReply upload(std::string_view target, std::string_view body);
  // Offsets and tools (offsets_api.cpp, issue 48 item 8).
  std::optional<HttpReply> offsets_route(const HttpRequest& r);
  HttpReply offsets_page() const;
  HttpReply edit_offset(std::string_view path, std::string_view body);
  HttpReply touch_off(std::size_t ch, const std::string& offset, const std::string& axis, double reads_mm);
  HttpReply edited(std::optional<Diagnostic> refusal);
  HttpReply reload_lists();
  // A channel that runs a program (not idle, ended or failed), if any.
  std::optional<std::size_t> busy_channel() const;
  std::string state_frame();
  void drain_events(std::vector<std::string>& frames);
  void advance(std::vector<std::string>& frames);
  void seed_state();

  config::Machine machine_;  // the server's copy: offset and tool edits change it, the next run takes it
  LiveKernel& kernel_;
  ProgramFolders folders_;
  std::vector<std::filesystem::path> programs_;  // per channel: the loaded program (empty: none)
  std::vector<std::string> previews_;            // per channel: its preview's answer, once asked (empty: not yet)
  std::unique_ptr<sim::DryRun> staged_;          // loaded, waits for cycle start
  std::optional<prep::SearchMark> staged_search_;  // its block search (an edit makes it again)
  std::size_t staged_search_channel_ = 0;
  sim::DryRun* serving_ = nullptr;  // the run of generation_ (the kernel's, or the one it just gave back)
  std::uint64_t generation_ = 1;
  ChannelFrames frames_{};
  LiveSnapshot last_{};  // the newest state taken
  LastErrors last_errors_;  // of the run of generation_, from its events (the state's last_error)
  LivePath path_;        // the run's path so far, for a page loaded during it
  bool estop_ = false, machine_on_ = true;  // as the last POST /api/v1/estop, /machine_on set them
  // per channel: an E-stop came, no reset of that channel after its release yet (the kernel's latch)
  std::array<bool, config::kMaxChannels> reset_pending_{};
  StreamReplay replay_;  // the frames' ids, the events a reconnecting client missed
  OffsetBook offsets_;   // the edits of the lists not saved yet
};

}  // namespace nck::app::serve
