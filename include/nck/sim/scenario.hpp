#pragma once
// The --plc FILE scenario: timed HLI writes, one per line (grammar in
// docs/plc-scenario.md). Parsed at setup into a time-sorted list; replayed in
// the cyclic path by the simulated machine (nck/sim/scenario_player.hpp).
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "nck/config/machine.hpp"
#include "nck/kernel/program_state.hpp"
#include "nck/core/diagnostic.hpp"
#include "nck/plc/ext_command.hpp"
#include "nck/plc/hli.hpp"
#include "nck/prep/search_mark.hpp"

namespace nck::sim {

enum class ActionKind : std::uint8_t {
  spindle_override,     // override S1 50 / spindle_override S1 50
  override_valid,       // override_valid S1 on|off
  feed_override,        // feed_override 80
  rapid_override,       // rapid_override 50          (G0 blocks, as P-CHAN-00181 says)
  feedhold,             // feedhold on|off            (channel)
  spindle_feedhold,     // spindle_feedhold S1 on|off (one spindle)
  spindle_stop_at_end,  // spindle_stop_at_end on|off [S1]  (no spindle: all of the channel)
  reset,                // reset                      (channel reset request)
  spindle_reset,        // spindle_reset S1
  optional_stop,        // optional_stop on|off
  silent,               // silent on|off              (PLC stops acknowledging)
  spindle_cmd,          // spindle_cmd S2 M3 REV500   (external spindle command)
  handwheel,            // handwheel X 0.5            (mm moved by the handwheel in G201 manual mode)
  variable,             // variable V.E.GAP 1.5       (a channel variable the PLC writes, e.g. a distance sensor)
  cycle_start,          // cycle_start                (releases a program hold: M0 / M1)
  auto_cycle_start,     // auto_cycle_start on|off    (the simulated operator releases every hold at once)
  single_step,          // single_step on|off         (hold at block ends, P-CHAN-00015)
  skip_mask,            // skip_mask 0x5              (active block-skip levels /1 /3: program_block_ignore)
  block_search,         // block_search N100 pass 2 covered 400   (at time 0: the run starts with a block search)
  stop,                 // stop                       (NC stop: hold where the path is until cycle_start)
  mdi,                  // mdi G1 X10 F1000           (one block typed by the operator: Scenario::texts[value])
  jog,                  // jog X + [600] / jog X stop (continuous jog, speed mm/min)
  jog_increment,        // jog_increment X - 0.1      (one step in mm)
  mode,                 // mode manual|automatic      (the channel's mode selection)
};

// The action's name as written in the file (the primary spelling).
std::string_view action_name(ActionKind k) noexcept;

struct ScenarioAction {
  double t_s = 0;              // when; for a triggered line, the delay after its trigger
  // '@hold' (or '@hold+0.5'): the line acts when its channel first enters
  // this program state (in Scenario::triggered, not in actions).
  std::optional<kernel::ProgramState> trigger;
  std::uint32_t line = 0;      // 1-based line in the scenario file
  std::uint8_t channel = 1;    // 1-based
  ActionKind kind = ActionKind::reset;
  std::array<char, plc::kSpindleNameChars> spindle_name{};  // empty: none given
  std::int8_t spindle = plc::kNoSpindle;      // channel's spindle index (resolve_spindles)
  std::int8_t hli_spindle = plc::kNoSpindle;  // HLI object index (resolve_spindles)
  double value = 0;            // percent for the overrides
  bool on = false;             // switches
  plc::ExtSpindleCommand cmd;       // spindle_cmd only
  std::array<char, plc::kSpindleNameChars> axis_name{};  // handwheel, jog: the path axis
  std::int8_t axis = -1;       // handwheel, jog: channel axis index (resolve_spindles)
  std::int8_t direction = 0;   // jog: +1 / -1, 0 = stop; value = speed mm/s (0: the axis's), jog_increment: step mm
  std::array<char, 32> var_name{};  // variable: its name as the NC program writes it
  // block_search: the mark (value: N, block counter or byte offset); `on`: no hold at restart
  prep::SearchMark::Kind search_kind = prep::SearchMark::Kind::block_number;
  std::uint32_t search_pass = 1;
  double covered_permille = 0;
  std::array<char, 64> program{};  // the file the mark lies in (empty: see SearchMark::program)
  bool has_spindle() const noexcept { return spindle_name[0] != '\0'; }
  std::string_view spindle_view() const noexcept { return std::string_view(spindle_name.data()); }
};

struct Scenario {
  std::string file;
  std::vector<ScenarioAction> actions;  // sorted by time, file order within equal times
  std::vector<std::string> texts;       // MDI lines' text (ScenarioAction::value is the index)
  std::vector<ScenarioAction> triggered;  // lines that wait for a program state ('@hold'), in file order
};

inline constexpr std::size_t kMaxScenarioActions = 100000;
inline constexpr double kMaxOverridePercent = 200.0;

// setup: parses the text of a scenario file. Bad lines are skipped and
// reported in diags (ID, file, line, column); never throws on any input.
Scenario parse_scenario(std::string_view text, std::string file, Diagnostics& diags);

// The scenario's block_search line as a block search of its channel (0-based), if it has one.
struct ScenarioSearch {
  std::size_t channel = 0;
  prep::SearchMark mark;
};
std::optional<ScenarioSearch> block_search_of(const Scenario& sc);

// setup: checks channels and spindle names against the machine and fills
// spindle / hli_spindle (and cmd.spindle). "S" names the channel's main
// spindle as configured (main_spindle_ax_nr). Unresolvable actions are
// reported and removed.
void resolve_spindles(Scenario& sc, const config::Machine& m, const plc::SpindleMap& map,
                      Diagnostics& diags);

}  // namespace nck::sim
