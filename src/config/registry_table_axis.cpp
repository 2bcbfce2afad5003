// Axis list keys (P-AXIS, docs/parameters.md). getriebe[i] = gear stage i+1.
// Row layout as in registry_table_channel.cpp. Where a unit depends on the
// axis type, both list units convert by the same factor (0.1 um and 0.0001
// deg are both 1e-4 of mm / deg), so one scale serves all axis types.
#include "registry_internal.hpp"

namespace nck::config::detail {
namespace {

using T = ParamType;
constexpr auto A = ListKind::axis;
constexpr char kPos[] = "0.1 µm · 0.0001°";
constexpr char kPosI[] = "mm · deg";
constexpr char kVel[] = "µm/s · 0.001°/s";
constexpr char kVelI[] = "mm/s · deg/s";
constexpr char kAcc[] = "mm/s² · °/s²";
constexpr char kAccI[] = "mm/s² · deg/s²";

constexpr ParamInfo kTable[] = {
    {"kopf.achs_nr", "P-AXIS-00016", A, T::integer, 1, kU16 - 1, 1, 1, "—", "—", "System-wide unique logical axis number (not 0)."},
    {"kopf.log_achs_name", "P-AXIS-00297", A, T::string, 0, 16, 0, 1, "—", "—", "Default system name of the axis.", {}, {}, "X_Achse"},
    {"kenngr.achs_typ", "P-AXIS-00018", A, T::achstyp, 1, 4, 1, 1, "—", "—", "Axis kind: ACHSTYP_TRANSLATOR 0x1, ACHSTYP_ROTATOR 0x2, ACHSTYP_SPINDEL 0x4.", {}, {}, "ACHSTYP_TRANSLATOR"},
    {"kenngr.achs_mode", "P-AXIS-00015", A, T::integer, 0, 0x7fffffff, 1, 1, "bits", "bits", "Axis mode bits (0x4 modulo, 0x0204 spindle that may become the C axis, 0x40000 PLC spindle, ...)."},
    {"kenngr.antr_typ", "P-AXIS-00020", A, T::integer, 1, 32, 4, 1, "—", "—", "Drive interface (1 = conventional: a velocity set point, the NC closes the position loop with kv, 4 = simulation, 8 = CANopen: CiA 402 drive profile, 16 = virtual)."},
    {"kenngr.drive_simulation", "P-AXIS-00790", A, T::boolean, 0, 1, 0, 1, "—", "—", "1: the drive is simulated whatever antr_typ says (one machine folder for the dry run and the real machine)."},
    {"antr.enable_timeout_ms", "nck", A, T::real, 1, 600000, 1000, 1e-3, "ms", "s", "CiA 402 / conventional drive: the time it may take to reach operation enabled before the NC raises an error (TF5200 has no such key)."},
    {"antr.homing_timeout_ms", "nck", A, T::real, 1, 3600000, 60000, 1e-3, "ms", "s", "The time G74 may take on a real drive before the NC raises an error: a CiA 402 drive's own homing (mode 6), or the NC's search for the home cam (TF5200 has no such key)."},
    {"kenngr.swe_neg", "P-AXIS-00177", A, T::real, kS32Min, kS32, -100000000, 1e-4, kPos, kPosI, "Negative software limit."},
    {"kenngr.swe_pos", "P-AXIS-00178", A, T::real, kS32Min, kS32, 100000000, 1e-4, kPos, kPosI, "Positive software limit."},
    {"kenngr.getriebe_stufe", "P-AXIS-00079", A, T::integer, 1, 6, 1, 1, "—", "—", "Gear stage active after start."},
    {"kenngr.vorz_richtung", "P-AXIS-00224", A, T::boolean, 0, 1, 0, 1, "—", "—", "Only one direction of rotation allowed (see beweg_richt; else 60254)."},
    {"kenngr.beweg_richt", "P-AXIS-00031", A, T::boolean, 0, 1, 0, 1, "—", "—", "Allowed direction under vorz_richtung: 0 negative, 1 positive."},
    {"kenngr.vb_prozent", "P-AXIS-00217", A, T::integer, 0, 1000, 100, 1, "0.1 %", "0.1 %", "Band around the commanded speed for 'speed reached'."},
    {"kenngr.ref_ohne_nocken", "P-AXIS-00156", A, T::boolean, 0, 1, 0, 1, "—", "—", "Homing without cam (requires ref_ohne_rev 1)."},
    {"kenngr.ref_ohne_rev", "P-AXIS-00157", A, T::boolean, 0, 1, 0, 1, "—", "—", "Homing without direction reversal."},
    {"kenngr.prog_move_requires_homing", "P-AXIS-00277", A, T::boolean, 0, 1, 0, 1, "—", "—", "1: a programmed motion (program or MDI) of this path axis needs it homed first (G74); unhomed it is refused with 930740. Jogging stays allowed."},
    {"kenngr.no_stop_by_channel_reset", "P-AXIS-00455", A, T::boolean, 0, 1, 0, 1, "—", "—", "A rotating spindle keeps running through a channel reset."},
    {"kenngr.def_cax_gear_st", "P-AXIS-00052", A, T::integer, 1, 6, 1, 1, "—", "—", "Gear stage used when the spindle becomes a C axis."},
    {"kenngr.durchm_prog_abs", "P-AXIS-00058", A, T::boolean, 0, 1, 0, 1, "—", "—", "Diameter programming for G90 values of this face axis."},
    {"kenngr.durchm_prog_rel", "P-AXIS-00059", A, T::boolean, 0, 1, 0, 1, "—", "—", "Diameter programming for G91 values of this face axis."},
    {"kenngr.ref_richt", "P-AXIS-00158", A, T::boolean, 0, 1, 0, 1, "—", "—", "Homing searches the cam in the positive (1) or negative (0) direction."},
    {"kenngr.homing.homing_type", "P-AXIS-00299", A, T::choice, 0, 0, 0, 1, "—", "—", "Who homes on a real drive: the NC (searches the cam through the axis's home switch) or a CiA 402 drive itself (homing mode 6).", {},
     "CNC_CONTROLLED DRIVE_CONTROLLED", "CNC_CONTROLLED"},
    {"kenngr.fast_from_cam", "P-AXIS-00064", A, T::boolean, 0, 1, 1, 1, "—", "—", "Homing leaves the cam fast (1) or slowly (0)."},
    {"kenngr.gantry_max_diff_reset_locked", "P-AXIS-00071", A, T::integer, 0, kU32, 0, 1e-4, kPos, kPosI, "Gantry difference that reset cannot clear; accepted."},
    {"kenngr.gantry_max_diff_resetable", "P-AXIS-00072", A, T::integer, 0, kU32, 0, 1e-4, kPos, kPosI, "Gantry difference that reset clears; accepted."},
    {"kenngr.messachse", "P-AXIS-00118", A, T::boolean, 0, 1, 0, 1, "—", "—", "Axis takes part in measuring moves."},
    {"kenngr.vb_messen", "P-AXIS-00215", A, T::integer, 1, kU32, 16666, 1e-3, kVel, kVelI, "Feed of measuring type 2."},
    {"kenngr.indp_feedhold_mode", "P-AXIS-00540", A, T::integer, 0, 1, 0, 1, "—", "—", "Feedhold source of independent axes; accepted."},
    {"kenngr.feedhold_deceleration_mode", "P-AXIS-00556", A, T::choice, 0, 0, 0, 1, "—", "—", "Deceleration used under feedhold.", {},
     "DEFAULT_DECELERATION FEEDHOLD_DECELERATION MIN_TOOL_ACC_FEEDHOLD_DECELERATION", "DEFAULT_DECELERATION"},
    {"handbetrieb.tipp.geschw[]", "P-AXIS-00077", A, T::integer, 0, kU32, 16666, 1e-3, kVel, kVelI, "Continuous jog speeds; [0] is the speed of a jog without one.", {6}},
    {"handbetrieb.jog.geschw[]", "P-AXIS-00076", A, T::integer, 0, kU32, 16666, 1e-3, kVel, kVelI, "Incremental jog speeds; [0] is the speed of a jog increment.", {6}},
    {"handbetrieb.hb.vb_max", "P-AXIS-00213", A, T::integer, 1, kU32, 166666, 1e-3, kVel, kVelI, "Highest manual-mode speed; caps every jog (and at most getriebe[].dynamik.vb_max)."},
    {"handbetrieb.hb.a_max", "P-AXIS-00009", A, T::integer, 1, kU32, 1000, 1, kAcc, kAccI, "Manual-mode acceleration; a jog ramps with the smaller of it and getriebe[].dynamik.a_max."},
    {"handbetrieb.ipo.hb_proz_a_max", "P-AXIS-00082", A, T::integer, 0, 100, 30, 1, "%", "%", "Share of acceleration for manual mode; accepted."},
    {"lr_hw[].cntr_channel", "P-AXIS-00041", A, T::integer, 0, kU32, 0, 1, "—", "—", "Hardware counter channel; accepted.", {8}},
    {"lr_param.mod_komp", "P-AXIS-00120", A, T::boolean, 0, 1, 0, 1, "—", "—", "Modulo error compensation in the position loop."},
    {"lr_param.distance_control_on", "P-AXIS-00328", A, T::boolean, 0, 1, 0, 1, "—", "—", "Axis-specific distance control allowed."},
    {"antr.operation_mode", "P-AXIS-00320", A, T::choice, 0, 0, 0, 1, "—", "—", "Where the position loop is closed; OPEN_POSITION_LOOP_* = speed-controlled.", {},
     "DRIVE_DEFAULT DRIVE_POSITION_CONTROL CNC_POSITION_CONTROL DSC_POSITION_CONTROL OPEN_POSITION_LOOP_MODE OPEN_POSITION_LOOP_MODE_EXACT "
     "OPEN_POSITION_LOOP_POS_FEEDBACK OPEN_POSITION_LOOP_VEL_FEEDBACK OPEN_POSITION_LOOP_NO_FEEDBACK", "DRIVE_DEFAULT"},
    {"antr.v_reso_num", "P-AXIS-00206", A, T::integer, 0, kU32, 1, 1, "increments", "increments", "Speed scaling numerator: drive output value."},
    {"antr.v_reso_denom", "P-AXIS-00205", A, T::integer, 1, kU32, 36, 1, "µm · 0.001°", "µm · 0.001°", "Speed scaling denominator: distance per time base at v_reso_num."},
    {"antr.v_time_base", "P-AXIS-00207", A, T::integer, 0, 2, 0, 1, "—", "—", "Speed scaling time base: 0 per min, 1 per s, 2 per cycle."},
    {"antr.velocity_position_control_on", "P-AXIS-00265", A, T::integer, 0, kS32, 2000000000, 1e-3, "0.001°/s", "deg/s", "SERCOS drives: above this speed the spindle switches to speed control (accepted, no effect in simulation)."},
    {"antr.velocity_position_control_off", "P-AXIS-00266", A, T::integer, 0, kS32, 0, 1e-3, "0.001°/s", "deg/s", "SERCOS drives: M19 brakes to this speed before position control resumes (accepted, no effect in simulation)."},
    {"antr.feed_const_num", "P-AXIS-00362", A, T::integer, 1, kU32, 1, 1, "0.1 µm · 0.0001°", "—", "Feed constant numerator; accepted."},
    {"antr.feed_const_denom", "P-AXIS-00363", A, T::integer, 1, kU32, 1, 1, "rev", "—", "Feed constant denominator; accepted."},
    {"antr.secondary_encoder", "P-AXIS-00824", A, T::string, 0, 64, 0, 1, "—", "—", "Drive signal used as secondary encoder.", {}, {}, "''"},
    {"vorsteuer.vs_a_faktor", "P-AXIS-00225", A, T::integer, 0, kS32, 1, 1, "µs", "s (Ta)", "Numerator of the drive time constant Ta for acceleration feedforward."},
    {"vorsteuer.vs_a_nenner", "P-AXIS-00226", A, T::integer, 0, kS32, 1, 1, "—", "—", "Denominator of Ta."},
    // ---- per gear stage ------------------------------------------------------
    {"getriebe[].slope_profil.a_beschl", "P-AXIS-00001", A, T::integer, 1, 100000000, 1000, 1, kAcc, kAccI, "Acceleration on feed moves (≤ dynamik.a_max).", {6}},
    {"getriebe[].slope_profil.a_brems", "P-AXIS-00002", A, T::integer, 1, 100000000, 1000, 1, kAcc, kAccI, "Deceleration on feed moves (≤ dynamik.a_max).", {6}},
    {"getriebe[].slope_profil.a_grenz", "P-AXIS-00004", A, T::integer, 1, 100000000, 1000, 1, kAcc, kAccI, "Acceleration for G0 (≤ dynamik.a_max).", {6}},
    {"getriebe[].slope_profil.tr_beschl_ab", "P-AXIS-00195", A, T::integer, 0, kU32, 50000, 1e-6, "µs", "s", "TRAPEZ/SIN2: ramp time to reduce the acceleration a_beschl to 0 (≥ dynamik.tr_min).", {6}},
    {"getriebe[].slope_profil.tr_beschl_zu", "P-AXIS-00196", A, T::integer, 0, kU32, 50000, 1e-6, "µs", "s", "TRAPEZ/SIN2: ramp time to build up the acceleration a_beschl (≥ dynamik.tr_min).", {6}},
    {"getriebe[].slope_profil.tr_brems_ab", "P-AXIS-00197", A, T::integer, 0, kU32, 50000, 1e-6, "µs", "s", "TRAPEZ/SIN2: ramp time to reduce the deceleration a_brems to 0 (≥ dynamik.tr_min).", {6}},
    {"getriebe[].slope_profil.tr_brems_zu", "P-AXIS-00198", A, T::integer, 0, kU32, 50000, 1e-6, "µs", "s", "TRAPEZ/SIN2: ramp time to build up the deceleration a_brems (≥ dynamik.tr_min).", {6}},
    {"getriebe[].dynamik.tr_geom", "P-AXIS-00199", A, T::integer, 0, kU32, 10000, 1e-6, "µs", "s", "TRAPEZ/SIN2: bounds the jerk the contour's curvature causes (arcs: speed limit from it).", {6}},
    {"getriebe[].slope_profil.tr_grenz", "P-AXIS-00200", A, T::integer, 0, kU32, 10000, 1e-6, "µs", "s", "TRAPEZ/SIN2: every ramp time of G0 (with a_grenz; ≥ dynamik.tr_min).", {6}},
    {"getriebe[].dynamik.tr_min", "P-AXIS-00201", A, T::integer, 0, kU32, 10000, 1e-6, "µs", "s", "Smallest ramp time the drive allows: the lower bound of P-AXIS-00195…00198 and 00200.", {6}},
    {"getriebe[].dynamik.a_w_max", "P-AXIS-00292", A, T::integer, 0, 100000000, 0, 1, kAcc, kAccI, "Highest acceleration a weighting G130/G131 may give a_beschl/a_brems (max(a_beschl, a_brems) … a_max); 0 or absent: a_max.", {6}},
    {"getriebe[].dynamik.tr_w_min", "P-AXIS-00293", A, T::integer, 0, kU32, 0, 1e-6, "µs", "s", "Shortest feed ramp time a weighting G132/G133 may give (tr_min … the shortest of P-AXIS-00195…00198); below tr_min: tr_min.", {6}},
    {"getriebe[].dynamik.a_trans_weight", "P-AXIS-00013", A, T::integer, 0, 1000, 0, 1e-3, "0.1 %", "factor", "TRAPEZ/SIN2/HSC: the acceleration a kink may cause for one cycle, as a share of a_beschl/a_brems; 0: cycle time / ramp time (the jerk stays within a / tr). 1000 lets a kink jump by a (the jerk exceeds its bound).", {6}},
    {"getriebe[].dynamik.a_max", "P-AXIS-00008", A, T::integer, 1, 100000000, 1000, 1, kAcc, kAccI, "Upper limit of every acceleration of the axis.", {6}},
    {"getriebe[].dynamik.a_emergency", "P-AXIS-00003", A, T::integer, 0, 200000000, 0, 1, kAcc, kAccI, "Emergency-stop braking (≤ 2·a_max); 0 = a_max.", {6}},
    {"getriebe[].dynamik.vb_max", "P-AXIS-00212", A, T::integer, 1, 2000000000, 200000, 1e-3, kVel, kVelI, "Velocity limit (10000 rpm = 60000000).", {6}},
    {"getriebe[].vb_eilgang", "P-AXIS-00209", A, T::integer, 1, 2000000000, 166666, 1e-3, kVel, kVelI, "Rapid velocity; also gear-change approach speed (≤ vb_max).", {6}},
    {"getriebe[].vb_min_null", "P-AXIS-00216", A, T::integer, 0, kU32, 100, 1e-3, "0.001°/s", "deg/s", "Below this speed the spindle counts as standing.", {6}},
    {"getriebe[].vb_regelgrenze", "P-AXIS-00220", A, T::integer, 0, kU32, 200000, 1e-3, "0.001°/s", "deg/s", "Above this speed the position loop opens (reference lost).", {6}},
    {"getriebe[].kv", "P-AXIS-00099", A, T::integer, 1, kU32, 1000, 0.01, "0.01/s", "1/s", "Position-loop gain (1000 = 10 1/s).", {6}},
    {"getriebe[].moduloo", "P-AXIS-00126", A, T::integer, kS32Min, kS32, 3600000, 1e-4, "0.0001°", "deg", "Upper end of the modulo range (> modulou).", {6}},
    {"getriebe[].modulou", "P-AXIS-00127", A, T::integer, kS32Min, kS32, 0, 1e-4, "0.0001°", "deg", "Lower end of the modulo range.", {6}},
    {"getriebe[].modulo_fehler", "P-AXIS-00124", A, T::integer, -32768, 32767, 0, 1, "increments", "increments", "Missing increments per modulo_umdreh revolutions.", {6}},
    {"getriebe[].modulo_umdreh", "P-AXIS-00125", A, T::integer, 0, 32767, 0, 1, "—", "—", "Revolutions that modulo_fehler refers to.", {6}},
    {"getriebe[].multi_gain_z", "P-AXIS-00129", A, T::integer, 1, kU32, 2000, 1, "bit", "bit", "D/A value for 1 m/min or 1000 °/min (numerator).", {6}},
    {"getriebe[].multi_gain_n", "P-AXIS-00128", A, T::integer, 1, kU32, 1, 1, "—", "—", "D/A scaling denominator.", {6}},
    {"getriebe[].wegaufz", "P-AXIS-00234", A, T::integer, 0, kU32, 1, 1, "increments", "increments", "Encoder increments (≥ 1; 0 → warning 110386, set to 1).", {6}},
    {"getriebe[].wegaufn", "P-AXIS-00233", A, T::integer, 0, kU32, 1, 1, kPos, kPos, "Encoder distance (≥ 1; 0 → warning 110086, set to 1).", {6}},
    {"getriebe[].getr_schalt_pos", "P-AXIS-00078", A, T::integer, kS32Min, kS32, 0, 1e-4, kPos, kPosI, "Position approached before shifting to another stage.", {6}},
    {"getriebe[].pos_refpkt", "P-AXIS-00152", A, T::integer, kS32Min, kS32, 0, 1e-4, kPos, kPosI, "Position set when homing completes.", {6}},
    {"getriebe[].vb_refmax", "P-AXIS-00219", A, T::integer, 1, kU32, 83333, 1e-3, kVel, kVelI, "Homing: fast speed towards the cam (capped by dynamik.vb_max).", {6}},
    {"getriebe[].vb_reflow", "P-AXIS-00218", A, T::integer, 1, kU32, 16666, 1e-3, kVel, kVelI, "Homing: slow speed off the cam (≤ vb_refmax).", {6}},
    {"getriebe[].a_ref", "P-AXIS-00285", A, T::integer, 0, 100000000, 0, 1, kAcc, kAccI, "Homing acceleration of the NC's cam search; 0: the smaller of slope_profil.a_grenz and dynamik.a_max.", {6}},
    {"getriebe[].reverse", "P-AXIS-00159", A, T::boolean, 0, 1, 0, 1, "—", "—", "Flip the sign of command and actual values.", {6}},
    {"getriebe[].slope_type", "P-AXIS-00270", A, T::integer, 0, kU16, 0, 1, "—", "—", "Spindle ramps: 0 STEP, 1 TRAPEZ (jerk a/tr), 2 SIN2 with the ramp times P-AXIS-00195…00198; another number is warning 60226 and 0; with a beschl_kennlinie curve 0 (930900).", {6}},
    {"getriebe[].beschl_kennlinie.typ", "P-AXIS-00202", A, T::integer, 0, 3, 0, 1, "—", "—", "Acceleration curve: 0 none, 1 hyperbola, 2 polynomial, 3 asynchronous drive.", {6}},
    {"getriebe[].beschl_kennlinie.n_grenz", "P-AXIS-00130", A, T::real, 0, kU32, 0, 1e-3, "0.001°/s", "deg/s", "Speed below which a_konst applies.", {6}},
    {"getriebe[].beschl_kennlinie.a_konst", "P-AXIS-00007", A, T::real, 0, kU32, 0, 1, "°/s²", "deg/s²", "Constant acceleration below n_grenz.", {6}},
    {"getriebe[].beschl_kennlinie.a_min", "P-AXIS-00010", A, T::real, 0, kU32, 0, 1, "°/s²", "deg/s²", "Lowest acceleration the curve may give.", {6}},
    {"getriebe[].beschl_kennlinie.b1", "P-AXIS-00026", A, T::real, -kInf, kInf, 0, 1, "1/s (poly) · °/s² (hyperbola)", "same", "Curve coefficient b1.", {6}},
    {"getriebe[].beschl_kennlinie.b2", "P-AXIS-00027", A, T::real, -kInf, kInf, 0, 1, "1/° (poly) · — (hyperbola)", "same", "Curve coefficient b2.", {6}},
    {"getriebe[].beschl_kennlinie.b3", "P-AXIS-00028", A, T::real, -kInf, kInf, 0, 1, "s/°² (poly) · — (hyperbola)", "same", "Curve coefficient b3.", {6}},
    {"getriebe[].beschl_kennlinie.a_max", "P-AXIS-00240", A, T::real, 0, 100000000, 0, 1, "°/s²", "deg/s²", "Type 3: acceleration up to N1 (≤ dynamik.a_max).", {6}},
    {"getriebe[].beschl_kennlinie.n1", "P-AXIS-00241", A, T::real, 0, kU32, 0, 1e-3, "0.001°/s", "deg/s", "Type 3: end of the constant-acceleration range (≤ n2).", {6}},
    {"getriebe[].beschl_kennlinie.n2", "P-AXIS-00242", A, T::real, 0, kU32, 0, 1e-3, "0.001°/s", "deg/s", "Type 3: start of the 1/n² range (≤ vb_max).", {6}},
};

}  // namespace

std::span<const ParamInfo> axis_table() { return kTable; }

}  // namespace nck::config::detail
