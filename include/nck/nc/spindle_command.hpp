#pragma once
// One spindle's words in a block: DIN (main spindle: M3 S1000, M19 S.POS=..,
// G74 S1, G167 S..) or spindle syntax (S1[M3 REV1000 ...], docs/nc-language.md).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace nck::nc {

enum class SpindleM : std::uint8_t { none = 0, m3 = 3, m4 = 4, m5 = 5, m19 = 19 };

// FEED_LINK [ON|OFF] [[FACT=..] [CORR=..] | AUTO] [MAIN] SRC=..  (TF5200 FEED_LINK)
struct FeedLink {
  std::optional<bool> on;           // ON / OFF (absent: keep)
  std::optional<double> fact_pct;   // FACT= (programmed in 0.1 %, stored in %)
  std::optional<double> corr;       // CORR=
  bool automatic = false;           // AUTO
  bool main = false;                // MAIN
  std::string src;                  // SRC= (an identifier or a number as written)
};

struct SpindleCommand {
  std::string name;             // as programmed: "S" (main), "S1", "S2"...
  bool din = false;             // true: DIN words of the main spindle
  std::uint32_t column = 0;     // where it was programmed (diagnostics)
  SpindleM m = SpindleM::none;  // M3/M4/M5/M19
  std::optional<double> rev_rpm;      // S / REV
  std::optional<double> pos_deg;      // S.POS / POS
  std::optional<double> pos_shift_deg;  // S.POS_SHIFT
  std::optional<double> offset_deg;   // S.OFFSET (G33 start angle)
  std::optional<int> gear_stage;      // M40..M45 -> 1..6 (DIN, main spindle)
  std::optional<int> g112_stage;      // G112 S<stage>
  std::vector<int> user_m;            // M=.. in spindle syntax
  std::vector<int> user_h;            // H=..
  bool g74 = false;                   // homing
  bool g167 = false;                  // override forced to 100 % for this speed
  std::optional<double> g130_pct;     // acceleration weighting
  bool g135 = false, g137 = false;    // feedforward on / off
  std::optional<double> g136_pct;     // feedforward weighting
  bool callax = false, putax = false;
  bool get_dynamic_data = false;
  bool default_dynamic_data = false;
  std::optional<double> override_speed_fact_pct;  // OVERRIDE SPEED_FACT=

  // Added by the decoder work:
  SpindleM direction = SpindleM::none;  // M3/M4 programmed together with M19
  std::string target;                 // configured spindle this addresses ("S1"...), main resolved
  // The same spindle as an index into DecoderConfig::spindle_names (the
  // channel's spindle list), resolved once by the decoder so that planning
  // never compares names; empty when target is not a channel spindle.
  std::optional<std::uint8_t> spindle_index;
  std::optional<FeedLink> feed_link;  // FEED_LINK ..
};

}  // namespace nck::nc
