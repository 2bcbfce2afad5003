#pragma once
// nck-hal --serve: nck serve's API and HMI (docs/api.md) for the kernel in
// the HAL thread. nck.cycle publishes its state into the shared Link after
// every cycle and takes the operator's actions from it; this handler turns
// them into the same state document, stream and commands as nck serve.
// What the HAL file owns is refused with 940407 (docs/hal.md, "The HMI"):
// another program, MDI, the pace, E-stop, machine on, homing, offsets.
//
// Two threads use it: nck-hal's main loop (take_event, take_state: it
// prepares the program and reads the Link) and the server thread (the
// ApiHandler side). They meet under one mutex, never in the HAL thread.
#include <chrono>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include "hal/link.hpp"
#include "nck/output/last_errors.hpp"
#include "nck/prep/run_records.hpp"
#include "nck/run/state_document.hpp"
#include "nck/serve/http_server.hpp"
#include "nck/serve/live_path.hpp"
#include "nck/serve/stream_replay.hpp"

namespace nck::hal {

class HalApi final : public app::serve::ApiHandler {
 public:
  HalApi(const config::Machine& m, Link& link, const prep::RunRecords& records, std::filesystem::path program);

  // main loop ------------------------------------------------------------
  // An event nck.cycle sent (after nck-hal printed it).
  void take_event(const kernel::Event& e);
  // The newest state nck.cycle published, if it published one since.
  void take_state();

  // server thread ---------------------------------------------------------
  app::serve::HttpReply handle(const app::serve::HttpRequest& r) override;
  void collect(std::vector<std::string>& frames) override;
  std::string stream_start(std::optional<std::uint64_t> last_event_id) override;

 private:
  app::serve::HttpReply command(std::string_view body);
  app::serve::HttpReply pass_on(const sim::ScenarioAction& a);
  app::serve::HttpReply program_text(std::string_view target) const;
  app::serve::HttpReply by_channel(std::string_view target, const std::string& answer) const;
  std::string state_document();  // under mutex_

  const config::Machine& machine_;
  Link& link_;
  const prep::RunRecords& records_;
  const std::filesystem::path program_;
  std::string preview_;  // the program's path as nck check plans it (once, at the start)

  std::mutex mutex_;  // the main loop's side and the server thread's
  app::LiveSnapshot last_{};
  app::ChannelFrames frames_{};
  app::LastErrors last_errors_;
  app::serve::LivePath path_;
  std::string events_;   // the events frame's JSON array so far ("[..." or empty)
  bool fresh_ = false;   // a state came since the last collect
  std::chrono::steady_clock::time_point last_taken_{};  // main loop only

  app::serve::StreamReplay replay_;  // server thread only
};

}  // namespace nck::hal
