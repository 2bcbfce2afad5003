#pragma once
// What one run is asked to do: `nck run`'s options, which the Python
// module and `nck diff --run` fill in as well.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "nck/prep/search_mark.hpp"
#include "nck/run/stop_at.hpp"

namespace nck::app {

class PathTrack;

struct RunOptions {
  std::string machine;
  std::vector<std::string> programs;  // program i runs in channel i+1
  std::string events, trace, final_state;
  std::string plc;     // --plc scenario file
  // Scenario lines an embedding gives as text (the Python module's
  // override=, feedhold= and a plc list), each with the name its
  // diagnostics give as file; merged with the --plc file's lines by time,
  // the earlier texts' first at equal times, then the file's.
  struct PlcText {
    std::string name, text;
  };
  std::vector<PlcText> plc_texts;
  std::string report;  // --report FILE.html
  std::uint64_t trace_every = 1;
  std::string trace_columns;  // --trace-columns path.a,path.j (trace_columns.hpp)
  double max_time_s = 86400;  // simulated seconds
  double max_wall_s = 0;      // wall-clock seconds (0 = no limit)
  std::uint32_t clamp_index = 0;  // clamp-offset group (pzv_grp) at program start
  bool realtime = false;
  bool prep_thread = false;  // preparation in a thread of its own
  bool unhomed = false;      // --unhomed: no axis homed at start (P-AXIS-00277)
  bool progress = true;       // on a terminal only
  std::vector<std::string> cycles;  // --cycles DIR: searched after startup.lis cycle_path[i]
  bool strict_keys = false;         // --strict: every unknown list key is an error (910032)
  // --start-mode: P-CHAN-00508 condition of this run; empty: ISG_STANDARD,
  // or SV with a block search
  std::string start_mode;
  std::optional<prep::SearchMark> start_at;  // --start-at / -block / -offset: block search in channel 1
  std::optional<double> covered_pct;         // --covered: of the restart block's path, 0..100 %
  std::optional<StopAt> stop_at;            // --stop-at: where the run ends
  // nck diff --run: records channel 1's path; and with report, the other
  // run shown as a ghost (diff_command.cpp's ghost_of). Not options of nck run.
  PathTrack* track = nullptr;
  const nlohmann::ordered_json* ghost = nullptr;
  // A channel may start without a program: an operator types MDI (the
  // Python session); `nck run` wants a program or scenario MDI lines.
  bool operator_present = false;
};

}  // namespace nck::app
