#pragma once
// Modal state of a channel's decoder (kept apart from the per-block words).
#include <cstdint>

#include "nck/core/plane.hpp"
#include "nck/core/slope.hpp"
#include "nck/trc/trc.hpp"

namespace nck::nc {

enum class Motion : std::uint8_t { rapid, linear, cw, ccw, thread, tap, tap_rigid, tap_retract };
enum class FeedMode : std::uint8_t { g93 = 93, g94 = 94, g95 = 95, g194 = 194 };
enum class SpeedMode : std::uint8_t { g97 = 97, g96 = 96 };
using RadiusComp = trc::RadiusComp;  // G40 G41 G42

struct ModalState {
  Motion motion = Motion::rapid;        // G0 G1 G2 G3 G33 G63 G331 G332
  Plane plane = Plane::g17;             // G17 G18 G19
  bool absolute = true;                 // G90 / G91
  FeedMode feed_mode = FeedMode::g94;   // G93 G94 G95
  SpeedMode speed_mode = SpeedMode::g97;  // G96 G97
  RadiusComp radius_comp = RadiusComp::g40;
  bool diameter = false;                // G51 / G52
  bool inch = false;                    // G70 / G71
  int zero_offset = 0;                  // 0 = G53, 1 = G54 ... 6 = G59, 7.. = G159=n
  double feed_mm_min = 0;               // F under G94 (an F belongs to its G function)
  double feed_mm_rev = 0;               // F under G95
  double css_m_min = 0;                 // S under G96
  double max_speed_rpm = 0;             // G196
  double thread_pitch_mm = 0;           // G33 I/J/K, modal to program end
  double r = 0;                         // circle radius, modal (older manual)
  std::int64_t d = 0;                   // active tool offset

  // Added by the decoder work:
  double feed_time_s = 0;               // F under G93 (time for the block)
  double feed_pct = 0;                  // F under G194 (% of the axes' maximum speed)
  double tap_pitch_mm = 0;              // G331/G332 K (signed: the sign picks the thread hand)
  bool circle_center_absolute = false;  // G161 (true) / G162 (false, initial)
  bool manual_mode = false;             // G201 (true) / G202 (false, initial)
  bool exact_stop = false;              // G360 (true) / G359 (false, initial)
  bool contour = false;                 // G261 (true) / G260 (false, initial): corner blending
  double contour_dev_mm = 0.01;         // #CONTOUR MODE [DEV PATH_DEV=..] (docs/decisions.md, "Continuous path and corner blending")
  bool trc_arc_corners = false;         // G26 (true) / G25 (false, initial): TRC outside corners
  SlopeProfile slope = SlopeProfile::step;  // #SLOPE; initial: P-CHAN-00071 (DecoderConfig::slope_default)

  bool operator==(const ModalState&) const = default;
};

}  // namespace nck::nc
