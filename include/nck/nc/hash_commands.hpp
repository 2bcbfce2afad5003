#pragma once
// Typed # commands (docs/nc-language.md, "# commands"). The decoder checks their
// syntax and arguments; their execution belongs to the kernel.
// Lengths are in program units (mm or inch), angles in degrees.
// A technology in a home of its own defines its command there (e.g.
// nck/distctrl/dist_command.hpp) with its keywords (kKeywords) and, found by
// the type, parse_hash_command, command_name and write_json: adding it to
// HashCommand is its only registration in the decoder.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "nck/distctrl/dist_command.hpp"

namespace nck::nc {

// --- couplings (spindle_link seed, TF5200 #SET AX LINK) --------------------
struct AxLinkPair {
  std::string slave, master;        // names, or logical axis numbers as text (NBR form)
  bool gantry = false;              // [slave=master, G, lim1, lim2]
  std::optional<double> limit1_mm, limit2_mm;
  std::optional<double> numerator, denominator;  // mirror / scale form
};
// #SET AX LINK [g, s=m, ...]  and  #AX LINK [NBR] [g, s=m, ...]
struct SetAxLink {
  int group = 1;
  bool by_number = false;           // NBR: pairs name logical axis numbers
  std::vector<AxLinkPair> pairs;
};
// #ENABLE AX LINK [g]  /  #AX LINK ON [g]; no group = group 0 (channel parameters)
struct EnableAxLink { std::optional<int> group; };
// #DISABLE AX LINK [g]  /  #AX LINK OFF [g] [ALL]; no group = the group enabled last
struct DisableAxLink { std::optional<int> group; bool all = false; };

// --- spindles (FCT-S1 §2.2.3, §2.5, §2.8.5, §2.8.8) ------------------------
// #MAIN SPINDLE [name | log_nr]; neither = back to the configured main spindle
struct MainSpindle {
  std::optional<std::string> name;
  std::optional<int> log_axis_nr;
};
// #CAX [[S,] C]  /  #CAX OFF
struct CAxis { bool on = true; std::string spindle; std::string axis; };
// #FACE [X, C]  /  #FACE OFF
struct Face { bool on = true; std::string axis1, axis2; };
// #CYL [Z, C, X60]  /  #CYL OFF
struct Cylinder {
  bool on = true;
  std::string axis1, axis2, axis3;
  double radius_mm = 0;
};
struct ExplSyn {};
// #TOOL DATA [basic, sister, variant]  (= D)  /  #TOOL PREP [..]  (= T)
struct ToolData {
  bool prep = false;
  std::array<std::int64_t, 3> fields{};  // empty field = 0
  int count = 0;                          // fields written
};

// --- coordinate systems (FCT-C2 §2.2, §2.8.1, §2.10) -----------------------
enum class CsOp : std::uint8_t { def, on, off, off_all, add, select, mode_on, mode_off };
// #CS ... and #ACS ... (same grammar, acs = true)
struct CoordSystem {
  bool acs = false;
  CsOp op = CsOp::on;
  std::optional<int> id;           // [id] of DEF/ON (1..5)
  std::string name;                // ADD / SELECT name (SELECT also MCS / IMCS)
  bool has_values = false;         // a [v1,v2,v3,a1,a2,a3] list was given
  std::array<double, 6> values{};  // translation (3) then angles (3); empty = 0
  std::string mode_option;         // #CS MODE ON [..] text (ROTATION_SEQUENCE.., ROTATION_MODE_FIXED)
};
struct Ecs { bool on = true; };
struct Mcs { bool on = true; bool ex_tool = false; };
struct Rotation {
  bool on = true;
  std::optional<double> angle_deg, center1_mm, center2_mm;
};
// #PSET X.. Y..: absolute actual-position presets, by channel axis index.
struct PSet { std::vector<std::pair<int, double>> axes; };
// #PRESET [X.. ..]: clear presets of the named axes, all when empty.
struct PReset { std::vector<int> axes; };
struct Tlc { bool on = true; double delta_mm = 0; };
// #SUPPRESS OFFSETS [kinds] X.. : the axis words stay ordinary motion words.
struct SuppressOffsets {
  bool zero = false, add_zero = false, pset = false, clamp = false,
       tool = false, measure = false, manual = false;
  bool all = true;  // no option list given
};
struct GetManualOffsets {};

using HashCommand =
    std::variant<SetAxLink, EnableAxLink, DisableAxLink, MainSpindle, CAxis, Face, Cylinder,
                 ExplSyn, ToolData, CoordSystem, Ecs, Mcs, Rotation, PSet, PReset, Tlc,
                 SuppressOffsets, GetManualOffsets, DistCtrl>;

// The command's keyword as written in the program, e.g. "#CS ON".
std::string hash_command_name(const HashCommand& c);

}  // namespace nck::nc
