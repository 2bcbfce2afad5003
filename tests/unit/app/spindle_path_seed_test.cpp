// The thread-cutting programs of FCT-S1 2.8.7 run end to end; the start
// angles of the passes are read from the trace (S1.pos). Where the seed's
// text is inconsistent the reading is in docs/decisions.md, "Spindle-path couplings": the calls
// `LL longitudinal thread` name the subroutine defined as `%L longit_thread`;
// repeated N numbers stay. The lathe programs run with their G51 (the
// lathe's X takes diameters); the tapered thread runs on the mill, which has
// no face-turning axis, so its G51 reads as G52 (the start angles and
// pitches do not depend on it).
#include <gtest/gtest.h>

#include <cmath>

#include "spindle_path_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;

// The lathe's Z software limit (50 mm) is below the seed's Z105 / Z200.
std::string seed_lathe(const std::string& name) {
  return patched_example("lathe", name + "_machine", "z.lis", "kenngr.swe_pos 3000000").dir.string();
}

// Last trace row before `axis` moves in the block starting at t (from the
// first row at or after t: with --trace-every the row before t may still
// belong to the block before).
std::size_t start_row(const PathRun& r, double t, const std::string& axis) {
  return before_move(r, static_cast<std::size_t>(std::ceil(t / r.row_dt - 1e-9)), axis);
}

constexpr const char* kM70 = R"(%L longit_thread

N100 G33 Z48 K1.5                ;Cut thread turn
N110 G00 X72                    ;Retract and move
N120 Z105                        ;to start position
N130 M29                        ;Subroutine end

%G33 (thread depth 0.92 mm)
N10 G51                          ;Diameter programming
N15 T1 D1 M03 S400              ;Select tool, start spindle
N20 G00 X72 Z105                ;Approach

N25 G01 X69.54 F1000            ;Position at 1st cutting depth
N30 LL longit_thread      ;1st thread cut

N35 G01 X69.08                  ;Position at 2nd cutting depth
N30 LL longit_thread      ;2nd thread cut

N35 G01 X68.62                  ;Position at 3rd cutting depth
N30 LL longit_thread      ;3rd thread cut

N35 G01 X68.16                  ;Position at final depth
N30 LL longit_thread      ;4th thread cut

N35 G01 X68.16                  ;Reposition at final depth
N30 LL longit_thread      ;Empty cut

N60 M05 X150 Z200                ;Moving to end position
N65 M30                          ;Program end
)";

TEST(SpindlePathSeed, M70x15InFivePassesStartsEveryPassOnTheZeroMark) {
  const PathRun r = run_text(seed_lathe("m70"), kM70, "m70");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const double step_deg = 400 * 6 * kDt;  // 2.4 deg per cycle at S400
  int passes = 0;
  for (const json& e : r.of("block")) {
    if (e["line"] != 3) continue;  // N100 G33 in the subroutine
    const std::size_t k = start_row(r, e["t"].get<double>(), "Z");
    // The spindle passed 0 deg in the cycle before Z moved.
    EXPECT_GE(r.rows[k].at("S1.pos"), 0.0);
    EXPECT_LT(r.rows[k].at("S1.pos"), step_deg);
    // 400 rpm x 1.5 mm = 600 mm/min = 10 mm/s along Z, 1 s into the pass.
    EXPECT_NEAR(r.rows[k + 1000].at("Z") - r.rows[k + 2000].at("Z"), 10.0, 1e-4);
    ++passes;
  }
  EXPECT_EQ(passes, 5);
}

TEST(SpindlePathSeed, TwoStartThreadStartsTheSecondTurnAt180Degrees) {
  const PathRun r = run_text(seed_lathe("two"), R"(%G33_2 (2-turn thread, thread depth 0.92 mm)
N10 G51                          ;Diameter programming
N15 T1 D1 M03 S400              ;Select tool, start spindle
N20 G00 X72 Z105                ;Approach
N25 G01 X68.16 F1000            ;Position at thread depth
N30 G33 Z48 K1.5                ;Cut 1st thread turn
N35 G00 X72                    ;Retract and move
N40 Z105                        ;to next
N45 G01 X68.16                  ;start position
N50 G33 Z48 K1.5 S.OFFSET=180   ;Cut 2nd thread turn at 180 deg
N55 G00 X72                    ;Retract and move
N60 M05 X150 Z200                ;to end position
N65 M30                          ;Program end
)", "two");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const double step_deg = 400 * 6 * kDt;
  const std::size_t first = start_row(r, r.block_t(30), "Z"), second = start_row(r, r.block_t(50), "Z");
  EXPECT_GE(r.rows[first].at("S1.pos"), 0.0);
  EXPECT_LT(r.rows[first].at("S1.pos"), step_deg);
  EXPECT_GE(r.rows[second].at("S1.pos"), 180.0);
  EXPECT_LT(r.rows[second].at("S1.pos"), 180.0 + step_deg);
  // Both turns start the same way after their mark: 360 / 2 apart.
  EXPECT_NEAR(r.rows[second].at("S1.pos") - r.rows[first].at("S1.pos"), 180.0, 1e-6);
}

// The tapered thread (>= 45 deg: pitch I on X) on the mill (it has the
// seed's Y axis), S1 rpm: the path waits for the zero mark, then X moves
// 5 mm per turn, 5/60 mm/s. Traced every 10th cycle (the pass takes 20 min).
TEST(SpindlePathSeed, TaperedThreadWithPitchIOnX) {
  PathRun r = run_text("mill", R"(%L tapered thread
N010 G33 Z90 X1 I5.0           ;Cut thread turn (reference I)
; N010 G33 Z90 X1 K5.0         ;Cut thread turn (reference K)
N020 G00 X72                   ;Retract and move
N030 Z105                      ;to start position
N040 M29                       ;Subroutine end

%G33
N050 G00 X0 Y0 Z0
N060 G18
N070 G52                       ;G51 read as G52: the mill has no face axis
N080 D1 M03 S1                 ;Select tool, start spindle
N090 G00 X105 Z105             ;Start
N100 G01 X100 F1000            ;Position at 1st cutting depth
N110 LL tapered thread         ;1st thread cut
N120 M05 X150 Z200            ;Move to end position
N130 M30                      ;Program end
)", "taper", "--trace-every 10");
  r.row_dt = 10 * kDt;
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const std::size_t k = start_row(r, r.line_t(2), "X");
  // 1 rpm = 0.006 deg per cycle: the start is on the mark within 10 cycles.
  EXPECT_GE(r.rows[k].at("S1.pos"), 0.0);
  EXPECT_LT(r.rows[k].at("S1.pos"), 0.07);
  // X: 5 mm per turn at 1 rpm; Z follows the taper (15 / 99 of X).
  const double dx = r.rows[k + 1000].at("X") - r.rows[k + 2000].at("X");
  EXPECT_NEAR(dx, 5.0 / 60.0 * 10.0, 1e-4);
  const double dz = r.rows[k + 1000].at("Z") - r.rows[k + 2000].at("Z");
  EXPECT_NEAR(dz, dx * 15.0 / 99.0, 1e-4);
}

}  // namespace
}  // namespace nck::app
