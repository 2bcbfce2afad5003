#pragma once
// One operator or PLC action, typed: a head (when, which channel, which
// scenario line) and one payload per kind whose fields are named for what
// they mean, in the units their names give. A scenario file's line, a JSON
// command of nck serve and a Python session's call all build this; the
// simulated machine applies it in the cyclic path. Plain data, no strings
// (MDI text is an index), so it crosses the live kernel's queue as is.
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <type_traits>
#include <variant>

#include "nck/kernel/program_state.hpp"
#include "nck/plc/ext_command.hpp"
#include "nck/plc/hli.hpp"
#include "nck/prep/search_mark.hpp"

namespace nck::sim {

namespace act {

// A spindle as the operator names it and, once resolved, where it is.
struct SpindleRef {
  std::array<char, plc::kSpindleNameChars> name{};  // empty: none given
  std::int8_t index = plc::kNoSpindle;  // the channel's spindle (resolve_action)
  std::int8_t hli = plc::kNoSpindle;    // its HLI object (resolve_action)
  bool given() const noexcept { return name[0] != '\0'; }
  std::string_view view() const noexcept { return std::string_view(name.data()); }
};

// A path axis as the operator names it and, once resolved, its channel index.
struct AxisRef {
  std::array<char, plc::kSpindleNameChars> name{};
  std::int8_t index = -1;  // resolve_action
  // amp_fault naming a spindle (its drive): the spindle's machine axis list (resolve_action)
  std::int16_t spindle_axis_list = -1;
  std::string_view view() const noexcept { return std::string_view(name.data()); }
};

struct SpindleOverride { SpindleRef spindle; double percent = 0; };
struct OverrideValid { SpindleRef spindle; bool on = false; };
struct FeedOverride { double percent = 0; };
struct RapidOverride { double percent = 0; };  // G0 blocks, as P-CHAN-00181 says
struct Feedhold { bool on = false; };
struct SpindleFeedhold { SpindleRef spindle; bool on = false; };
struct SpindleStopAtEnd { SpindleRef spindle; bool on = false; };  // no spindle: all of the channel
struct Reset {};
struct SpindleReset { SpindleRef spindle; };
struct OptionalStop { bool on = false; };
struct Silent { bool on = false; };  // the PLC stops acknowledging
struct SpindleCmd { SpindleRef spindle; plc::ExtSpindleCommand cmd; };
struct Handwheel { AxisRef axis; double distance_mm = 0; };  // turned in G201 manual mode
struct Variable { std::array<char, 32> name{}; double value = 0; };  // upper case, as the NC program reads it
struct CycleStart {};
struct AutoCycleStart { bool on = false; };  // the simulated operator releases every hold at once
struct SingleStep { bool on = false; };
struct SkipMask { std::uint32_t mask = 0; };  // bit 0 = /1 ... bit 9 = /10
// The run starts with a block search to this mark (only at time 0).
struct BlockSearch {
  prep::SearchMark::Kind mark_kind = prep::SearchMark::Kind::block_number;
  std::int64_t mark_value = 0;  // N, block counter or byte offset
  std::uint32_t pass = 1;
  double covered_permille = 0;
  std::array<char, 64> program{};  // the file the mark lies in (empty: see SearchMark::program)
  bool no_hold_at_restart = false;
};
struct Stop {};
struct Mdi { std::uint32_t text = 0; };  // index of the NC block's text (Scenario::texts)
// A jog key pressed (direction +1 / -1) or released (0).
struct Jog { AxisRef axis; std::int8_t direction = 0; double speed_mm_min = 0; };  // 0: the axis's jog speed
struct JogIncrement { AxisRef axis; std::int8_t direction = 1; double step_mm = 0; };
struct Mode { bool manual = false; };
// The simulated CiA 402 drive of a path axis reports a fault while on
// (kenngr.antr_typ 8; a fault held from the start: the drive never enables).
struct DriveFault { AxisRef axis; bool on = false; };
// The machine's E-stop input and machine-on input (TickInput::machine; the
// line's channel does not matter: they act on the whole machine).
struct Estop { bool on = false; };
struct MachineOn { bool on = false; };
// The amplifier fault and the limit switches of a path axis's machine axis
// (TickInput::axes): any drive type, as a HAL machine's pins set them.
struct AmpFault { AxisRef axis; bool on = false; };
struct LimitSwitch { AxisRef axis; std::int8_t direction = 1; bool on = false; };  // +1 positive end, -1 negative

}  // namespace act

// The kinds in the order of ActionPayload's alternatives.
enum class ActionKind : std::uint8_t {
  spindle_override,     // override S1 50 / spindle_override S1 50
  override_valid,       // override_valid S1 on|off
  feed_override,        // feed_override 80
  rapid_override,       // rapid_override 50
  feedhold,             // feedhold on|off            (channel)
  spindle_feedhold,     // spindle_feedhold S1 on|off (one spindle)
  spindle_stop_at_end,  // spindle_stop_at_end on|off [S1]
  reset,                // reset                      (channel reset request)
  spindle_reset,        // spindle_reset S1
  optional_stop,        // optional_stop on|off
  silent,               // silent on|off
  spindle_cmd,          // spindle_cmd S2 M3 REV500   (external spindle command)
  handwheel,            // handwheel X 0.5
  variable,             // variable V.E.GAP 1.5       (a channel variable the PLC writes)
  cycle_start,          // cycle_start                (releases a program hold: M0 / M1)
  auto_cycle_start,     // auto_cycle_start on|off
  single_step,          // single_step on|off         (hold at block ends, P-CHAN-00015)
  skip_mask,            // skip_mask 0x5              (program_block_ignore)
  block_search,         // block_search N100 pass 2 covered 400
  stop,                 // stop                       (NC stop: hold until cycle_start)
  mdi,                  // mdi G1 X10 F1000           (one block typed by the operator)
  jog,                  // jog X + [600] / jog X stop (speed mm/min)
  jog_increment,        // jog_increment X - 0.1      (one step in mm)
  mode,                 // mode manual|automatic
  drive_fault,          // drive_fault X on|off       (the simulated CiA 402 drive faults)
  estop,                // estop on|off               (the machine's E-stop input)
  machine_on,           // machine_on on|off          (the machine-on input)
  amp_fault,            // amp_fault X on|off         (the axis's amplifier fault input)
  limit_switch,         // limit_switch X + on|off    (the axis's limit switch at its + or - end)
};

using ActionPayload =
    std::variant<act::SpindleOverride, act::OverrideValid, act::FeedOverride, act::RapidOverride, act::Feedhold,
                 act::SpindleFeedhold, act::SpindleStopAtEnd, act::Reset, act::SpindleReset, act::OptionalStop,
                 act::Silent, act::SpindleCmd, act::Handwheel, act::Variable, act::CycleStart, act::AutoCycleStart,
                 act::SingleStep, act::SkipMask, act::BlockSearch, act::Stop, act::Mdi, act::Jog,
                 act::JogIncrement, act::Mode, act::DriveFault, act::Estop, act::MachineOn,
                 act::AmpFault, act::LimitSwitch>;

// The action's name as a scenario file writes it (the primary spelling).
std::string_view action_name(ActionKind k) noexcept;

// The default payload of kind k (what a parser fills in).
ActionPayload payload_of(ActionKind k) noexcept;

struct ScenarioAction {
  double t_s = 0;  // when; for a triggered line, the delay after its trigger
  // '@hold' (or '@hold+0.5'): the line acts when its channel first enters
  // this program state (in Scenario::triggered, not in actions).
  std::optional<kernel::ProgramState> trigger;
  std::uint32_t line = 0;    // 1-based line in the scenario file (0: not from a file)
  std::uint8_t channel = 1;  // 1-based
  ActionPayload payload{act::Reset{}};

  ActionKind kind() const noexcept { return static_cast<ActionKind>(payload.index()); }
  template <class T>
  const T* get() const noexcept { return std::get_if<T>(&payload); }
  template <class T>
  T* get() noexcept { return std::get_if<T>(&payload); }
};

// The index of payload type T, which is its kind.
template <class T, std::size_t I = 0>
constexpr ActionKind action_kind_of() noexcept {
  if constexpr (std::is_same_v<T, std::variant_alternative_t<I, ActionPayload>>) return static_cast<ActionKind>(I);
  else return action_kind_of<T, I + 1>();
}
static_assert(action_kind_of<act::SpindleOverride>() == ActionKind::spindle_override);
static_assert(action_kind_of<act::OverrideValid>() == ActionKind::override_valid);
static_assert(action_kind_of<act::FeedOverride>() == ActionKind::feed_override);
static_assert(action_kind_of<act::RapidOverride>() == ActionKind::rapid_override);
static_assert(action_kind_of<act::Feedhold>() == ActionKind::feedhold);
static_assert(action_kind_of<act::SpindleFeedhold>() == ActionKind::spindle_feedhold);
static_assert(action_kind_of<act::SpindleStopAtEnd>() == ActionKind::spindle_stop_at_end);
static_assert(action_kind_of<act::Reset>() == ActionKind::reset);
static_assert(action_kind_of<act::SpindleReset>() == ActionKind::spindle_reset);
static_assert(action_kind_of<act::OptionalStop>() == ActionKind::optional_stop);
static_assert(action_kind_of<act::Silent>() == ActionKind::silent);
static_assert(action_kind_of<act::SpindleCmd>() == ActionKind::spindle_cmd);
static_assert(action_kind_of<act::Handwheel>() == ActionKind::handwheel);
static_assert(action_kind_of<act::Variable>() == ActionKind::variable);
static_assert(action_kind_of<act::CycleStart>() == ActionKind::cycle_start);
static_assert(action_kind_of<act::AutoCycleStart>() == ActionKind::auto_cycle_start);
static_assert(action_kind_of<act::SingleStep>() == ActionKind::single_step);
static_assert(action_kind_of<act::SkipMask>() == ActionKind::skip_mask);
static_assert(action_kind_of<act::BlockSearch>() == ActionKind::block_search);
static_assert(action_kind_of<act::Stop>() == ActionKind::stop);
static_assert(action_kind_of<act::Mdi>() == ActionKind::mdi);
static_assert(action_kind_of<act::Jog>() == ActionKind::jog);
static_assert(action_kind_of<act::JogIncrement>() == ActionKind::jog_increment);
static_assert(action_kind_of<act::Mode>() == ActionKind::mode);
static_assert(action_kind_of<act::DriveFault>() == ActionKind::drive_fault);
static_assert(action_kind_of<act::Estop>() == ActionKind::estop);
static_assert(action_kind_of<act::MachineOn>() == ActionKind::machine_on);
static_assert(action_kind_of<act::AmpFault>() == ActionKind::amp_fault);
static_assert(action_kind_of<act::LimitSwitch>() == ActionKind::limit_switch);
static_assert(std::variant_size_v<ActionPayload> == static_cast<std::size_t>(ActionKind::limit_switch) + 1);

// Actions cross the live kernel's queue (LiveKernel::operate) and the
// machine's fixed-size list of operator actions: copied as bytes.
static_assert(std::is_trivially_copyable_v<ScenarioAction>);

// An action built by T's fields, for channel ch (1-based).
template <class T>
ScenarioAction make_action(std::uint8_t ch, const T& payload) {
  ScenarioAction a;
  a.channel = ch;
  a.payload = payload;
  return a;
}

}  // namespace nck::sim
