#pragma once
// The typed machine model: every list of a machine folder, validated and
// converted to internal units once at load (mm, deg, s, mm/s, deg/s, mm/s^2,
// deg/s^2; spindle speeds in rpm at the user edge). Immutable while running.
//
// Fields may be added; existing names are an interface other layers use.
#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "nck/core/axes.hpp"
#include "nck/core/rapid_override.hpp"
#include "nck/core/slope.hpp"

namespace nck::config {

inline constexpr std::size_t kMaxChannels = 12;
// Path axes per channel: core kMaxAxes (nck/core/axes.hpp).
inline constexpr std::size_t kMaxSpindles = 16;     // per channel
inline constexpr std::size_t kMaxGearStages = 6;

enum class AxisKind : std::uint8_t { translatory = 1, rotary = 2, spindle = 4 };

// Synchronisation type bits (FCT-S1 §2.5).
namespace sync {
inline constexpr std::uint32_t NO_SYNCH = 0x0;
inline constexpr std::uint32_t MOS = 0x1;
inline constexpr std::uint32_t MVS_SVS = 0x2;
inline constexpr std::uint32_t MVS_SNS = 0x4;
inline constexpr std::uint32_t MNS_SNS = 0x8;
inline constexpr std::uint32_t MNE_SNS = 0x20;
inline constexpr std::uint32_t MVS_SLM = 0x4000;
inline constexpr std::uint32_t MVS_SLP = 0x8000;
inline constexpr std::uint32_t PLC_INFO = 0x20000;
inline constexpr std::uint32_t MOS_TS = 0x40000;
inline constexpr std::uint32_t MEP_MOS = 0x100000;
inline constexpr std::uint32_t MET_MOS = 0x200000;
inline constexpr std::uint32_t BWD_SYNCH = 0x400000;
inline constexpr std::uint32_t FWD_SYNCH = 0x800000;
inline constexpr std::uint32_t MEP_SVS = 0x1000000;
inline constexpr std::uint32_t MET_SVS = 0x2000000;
inline constexpr std::uint32_t FAW_SYNCH = 0x10000000;
inline constexpr std::uint32_t NOT_VALID = 0x80000000;  // also: no m_synch entry (P-CHAN-00041 default)
}  // namespace sync

// Characteristic acceleration curve of a spindle gear stage (P-AXIS-00202...).
struct AccelCurve {
  std::uint32_t type = 0;        // 0 none, 1 hyperbola, 2 polynomial, 3 asynchronous drive
  double limit_speed_deg_s = 0;      // n_grenz: limit speed
  double const_accel_deg_s2 = 0;     // a_konst
  double a_min_deg_s2 = 0;
  double b1 = 0, b2 = 0, b3 = 0; // as in the list (units per seed)
  double a_max_deg_s2 = 0;       // type 3
  double n1_deg_s = 0, n2_deg_s = 0;
};

// One gear stage (getriebe[i]) of an axis or spindle; index 0 = stage 1.
// Velocities in mm/s (deg/s for rotary axes and spindles), accelerations
// in mm/s^2 (deg/s^2).
struct GearStage {
  double accel_mm_s2 = 1000;   // P-AXIS-00001 (a_beschl) acceleration on feed moves
  double decel_mm_s2 = 1000;    // P-AXIS-00002 (a_brems) deceleration on feed moves
  double rapid_accel_mm_s2 = 1000;    // P-AXIS-00004 (a_grenz) acceleration for G0
  double a_max = 1000;      // P-AXIS-00008 hard cap
  double max_speed_mm_s = 200;      // P-AXIS-00212 (vb_max; list 200000 um/s)
  double rapid_mm_s = 166.666;  // P-AXIS-00209 (vb_eilgang) rapid
  double position_gain_1_s = 10;       // P-AXIS-00099 (kv) position-loop gain
  double modulo_upper = 360, modulo_lower = 0;  // P-AXIS-00126/00127 (moduloo/modulou)
  // Spindle only (the list keys in parentheses):
  double zero_speed_deg_s = 0.1;      // P-AXIS-00216 (vb_min_null): standstill below this
  double control_limit_deg_s = 200;   // P-AXIS-00220 (vb_regelgrenze): position loop opens above
  double gear_change_pos_deg = 0;     // P-AXIS-00078 (getr_schalt_pos)
  double reference_pos = 0;              // P-AXIS-00152 (pos_refpkt)
  // Homing on a real drive, the NC's search for the cam (path axes):
  double homing_fast_mm_s = 83.333;   // P-AXIS-00219 (vb_refmax): towards the cam
  double homing_slow_mm_s = 16.666;   // P-AXIS-00218 (vb_reflow): off the cam (fast_from_cam 0)
  double homing_accel_mm_s2 = 0;      // P-AXIS-00285 (a_ref), 0: min(a_grenz, a_max)
  double homing_accel() const { return homing_accel_mm_s2 > 0 ? homing_accel_mm_s2 : std::min(rapid_accel_mm_s2, a_max); }
  std::uint32_t encoder_ratio_num = 1, encoder_ratio_denom = 1;  // wegaufz / wegaufn
  bool reverse_sense = false;         // P-AXIS-00159 (reverse)
  double a_emergency = 0;             // P-AXIS-00003, 0 = use a_max
  // P-AXIS-00270 (slope_type) of a spindle: 0 STEP, 1 TRAPEZ, 2 SIN2 (an
  // invalid number is warning 60226 at load and STEP). Path axes (the C
  // axis under #CAX too) follow the channel's #SLOPE instead.
  SlopeProfile slope_type = SlopeProfile::step;
  // Ramp times of the jerk-limited slopes (TRAPEZ, SIN2), s; list µs.
  double tr_acc_down_s = 0.05;  // P-AXIS-00195 slope_profil.tr_beschl_ab: acceleration back to 0
  double tr_acc_up_s = 0.05;    // P-AXIS-00196 slope_profil.tr_beschl_zu: acceleration built up
  double tr_dec_down_s = 0.05;  // P-AXIS-00197 slope_profil.tr_brems_ab: deceleration back to 0
  double tr_dec_up_s = 0.05;    // P-AXIS-00198 slope_profil.tr_brems_zu: deceleration built up
  double tr_geom_s = 0.01;      // P-AXIS-00199 dynamik.tr_geom: jerk from the contour's curvature
  double tr_rapid_s = 0.01;     // P-AXIS-00200 slope_profil.tr_grenz: every ramp of G0
  double tr_min_s = 0.01;       // P-AXIS-00201 dynamik.tr_min: lower bound of the others
  // Limits of the program's weightings: G130/G131 up to a_w_max (0: a_max),
  // G132/G133 not below tr_w_min (and never below tr_min).
  double a_w_max_mm_s2 = 0;     // P-AXIS-00292 dynamik.a_w_max
  double tr_w_min_s = 0;        // P-AXIS-00293 dynamik.tr_w_min
  // P-AXIS-00013 dynamik.a_trans_weight (list 0.1 %): the acceleration a kink
  // may cause under a jerk-limited slope, as a factor of a; 0: a times cycle
  // time / ramp time (the jerk stays within a / tr).
  double a_trans_weight = 0;
  double weighted_a_max() const { return a_w_max_mm_s2 > 0 ? a_w_max_mm_s2 : a_max; }
  double weighted_tr_min_s() const { return tr_w_min_s > tr_min_s ? tr_w_min_s : tr_min_s; }
  std::uint32_t multi_gain_z = 2000, multi_gain_n = 1;  // P-AXIS-00129/00128
  std::int32_t modulo_error_incr = 0;     // P-AXIS-00124 (modulo_fehler, increments)
  std::int32_t modulo_revolutions = 0;     // P-AXIS-00125 (modulo_umdreh)
  AccelCurve curve;
  bool given = false;       // true when the list names this stage
};

struct SourceRef {          // where a record came from, for diagnostics
  std::string file;
  std::uint32_t line = 0;
};

// configuration.decoder.function bits used by nck. The TF5200 documentation
// names the symbols but publishes no numeric values, so these are nck's own.
namespace decoder_fct {
inline constexpr std::uint32_t FCT_DEFAULT = 0x00000000;
inline constexpr std::uint32_t FCT_NO_DISPLAY = 0x00000400;            // accepted, no effect
inline constexpr std::uint32_t FCT_USE_CACHED_FILES = 0x00000800;      // docs/decisions.md, "Machine data"
inline constexpr std::uint32_t FCT_VOL_COMP_COMPUTATION = 0x00001000;  // accepted, no effect
inline constexpr std::uint32_t FCT_3D_DIST_CTRL = 0x00100000;          // docs/decisions.md, "Machine data"
}  // namespace decoder_fct

// Where a drive's position loop is closed (antr.operation_mode, P-AXIS-00320).
// The open-loop modes make a speed-controlled spindle.
enum class DriveMode : std::uint8_t {
  drive_default,           // DRIVE_DEFAULT
  drive_position_control,  // DRIVE_POSITION_CONTROL
  cnc_position_control,    // CNC_POSITION_CONTROL
  dsc_position_control,    // DSC_POSITION_CONTROL
  open_loop,               // OPEN_POSITION_LOOP_MODE
  open_loop_exact,         // OPEN_POSITION_LOOP_MODE_EXACT
  open_loop_pos_feedback,  // OPEN_POSITION_LOOP_POS_FEEDBACK: knows its position
  open_loop_vel_feedback,  // OPEN_POSITION_LOOP_VEL_FEEDBACK: knows its speed only
  open_loop_no_feedback,   // OPEN_POSITION_LOOP_NO_FEEDBACK
};
constexpr bool is_open_loop(DriveMode m) noexcept { return m >= DriveMode::open_loop; }
// The mode an antr.operation_mode symbol names, or nullopt (setup).
std::optional<DriveMode> drive_mode_from(std::string_view symbol) noexcept;

// How G74 homes a path axis: `direct` moves it to pos_refpkt (a simulated
// drive, or homing without cam); `cam`: the NC searches the home cam
// through the axis's home switch and sets the position at its edge; `drive`:
// a CiA 402 drive homes itself (mode 6) and the NC takes its position.
enum class HomingMethod : std::uint8_t { direct, cam, drive };

// One axis list (achs_mds[i]): a path axis or a spindle.
struct AxisConfig {
  SourceRef source;
  std::uint32_t log_axis_nr = 0;        // kopf.achs_nr (P-AXIS-00016)
  std::string name;                     // kopf.log_achs_name
  AxisKind kind = AxisKind::translatory;  // kenngr.achs_typ
  std::uint32_t axis_mode = 0x1;        // kenngr.achs_mode
  std::uint32_t drive_type = 4;           // kenngr.antr_typ (1 conventional, 4 simulation, 8 CiA 402, 16 virtual)
  bool drive_simulation = false;          // P-AXIS-00790 (kenngr.drive_simulation): simulate whatever antr_typ says
  double drive_enable_timeout_s = 1.0;    // antr.enable_timeout_ms (nck): time to reach operation enabled
  double drive_homing_timeout_s = 60.0;   // antr.homing_timeout_ms (nck): time a drive may take to home (G74)
  // The drive the NC talks to: antr_typ 8 is CiA 402 unless P-AXIS-00790 simulates it.
  bool is_cia402() const { return drive_type == 8 && !drive_simulation; }
  // antr_typ 1: a conventional drive that takes a velocity set point (an
  // analogue ±10 V input): the NC closes the position loop with kv.
  bool is_conventional() const { return drive_type == 1 && !drive_simulation; }
  double sw_limit_neg = -10000, sw_limit_pos = 10000;  // kenngr.swe_neg/swe_pos software limits (mm / deg)
  std::uint32_t initial_gear_stage = 1; // kenngr.getriebe_stufe
  bool has_preferred_direction = false;       // P-AXIS-00224 (kenngr.vorz_richtung), spindle
  bool preferred_direction_positive = false;  // P-AXIS-00031 (kenngr.beweg_richt), spindle
  double speed_reached_tolerance_permille = 100;  // P-AXIS-00217 (kenngr.vb_prozent), spindle
  bool homing_without_cam = false, homing_without_reversal = false;  // kenngr.ref_ohne_nocken/_rev
  bool homing_positive = false;         // P-AXIS-00158 (kenngr.ref_richt): the cam lies that way
  bool drive_controlled_homing = false; // P-AXIS-00299 (kenngr.homing.homing_type DRIVE_CONTROLLED)
  // How G74 homes this path axis (docs/decisions.md "Homing on a real drive").
  HomingMethod homing_method() const {
    if (drive_controlled_homing && is_cia402()) return HomingMethod::drive;
    if ((is_cia402() || is_conventional()) && !homing_without_cam) return HomingMethod::cam;
    return HomingMethod::direct;
  }
  bool prog_move_requires_homing = false;  // P-AXIS-00277: programmed motion refused until homed (G74)
  bool no_stop_by_channel_reset = false;  // P-AXIS-00455
  DriveMode drive_mode = DriveMode::drive_default;  // antr.operation_mode
  // Speed command scaling of a speed-controlled spindle (antr.v_reso_num,
  // v_reso_denom, v_time_base): increments per 0.001 deg per time base.
  std::uint32_t speed_increments_num = 1, speed_increments_denom = 36, speed_time_base = 0;
  std::array<GearStage, kMaxGearStages> gears{};
  // Added by the config layer (all in internal units):
  std::uint32_t cax_gear_stage = 1;            // P-AXIS-00052 (def_cax_gear_st)
  double velocity_position_control_on = 2000000;  // P-AXIS-00265 (deg/s)
  double velocity_position_control_off = 0;       // P-AXIS-00266 (deg/s)
  double feedforward_ta_s = 1e-6;               // P-AXIS-00225/00226 (Ta = faktor us / nenner)
  double measure_speed = 16.666;                    // P-AXIS-00215 (vb_messen; mm/s, deg/s)
  bool modulo_compensation = false;                        // P-AXIS-00120 (mod_komp)
  bool distance_control_on = false;             // P-AXIS-00328
  bool diameter_prog_abs = false;                 // P-AXIS-00058 (durchm_prog_abs)
  bool diameter_prog_rel = false;                 // P-AXIS-00059 (durchm_prog_rel)
  bool fast_from_cam = true;                    // P-AXIS-00064
  std::string feedhold_deceleration_mode = "DEFAULT_DECELERATION";  // P-AXIS-00556
  // Manual mode (handbetrieb.*; docs/decisions.md, "Measuring, manual mode,
  // jog and handwheel"):
  double jog_speed_mm_s = 16.666;            // P-AXIS-00077 (tipp.geschw[0]): continuous jog
  double jog_increment_speed_mm_s = 16.666;  // P-AXIS-00076 (jog.geschw[0]): incremental jog
  double manual_max_speed_mm_s = 166.666;    // P-AXIS-00213 (hb.vb_max): caps every jog
  double manual_a_max_mm_s2 = 1000;          // P-AXIS-00009 (hb.a_max): jog ramps, capped by P-AXIS-00008
  std::string secondary_encoder;                // P-AXIS-00824
  bool is_speed_controlled() const { return is_open_loop(drive_mode); }

  bool is_spindle() const { return kind == AxisKind::spindle; }
  // P-AXIS-00015 0x0204: a spindle that may become a C axis (#CAX).
  static constexpr std::uint32_t kCAxisMode = 0x0204;
  bool c_axis_capable() const { return (axis_mode & kCAxisMode) == kCAxisMode; }
  bool is_modulo() const { return (axis_mode & 0x4) != 0 || is_spindle(); }
  bool is_face_turning() const { return (axis_mode & 0x40) != 0; }  // "Plandrehachse"
  const GearStage& gear(std::uint32_t stage_1based) const {
    std::uint32_t i = stage_1based == 0 ? 0 : stage_1based - 1;
    return gears[i < kMaxGearStages ? i : 0];
  }
};

// A path axis of a channel (gruppe[0].achse[j]).
struct ChannelAxis {
  std::string name;               // bezeichnung, e.g. "X"
  std::uint32_t log_axis_nr = 0;
  int axis_index = -1;            // index into Machine::axes, -1 when none
};

struct SpindleRange {             // spindel[i].range_table[k]
  double min_speed_rpm = 0;
  double max_speed_rpm = 0;
};

// A spindle of a channel (spindel[i]).
struct ChannelSpindle {
  SourceRef source;
  std::string name;               // bezeichnung, e.g. "S1"
  std::uint32_t log_axis_nr = 0;
  int axis_index = -1;            // index into Machine::axes, -1 for plc_control
  bool plc_control = false;       // P-CHAN-00069
  bool autom_range = false;       // P-CHAN-00004
  std::array<SpindleRange, kMaxGearStages> range_table{};
  std::array<std::uint8_t, kMaxGearStages> range_way{1, 2, 3, 4, 5, 6};  // search order (stage numbers)
  std::uint32_t range_way_param = 0;  // P-CHAN-00074 as written: 0 bottom up, >0 top down
  std::uint32_t s_sync = sync::MVS_SVS, m3_sync = sync::MVS_SVS, m4_sync = sync::MVS_SVS,
                m5_sync = sync::MVS_SVS, m19_sync = sync::MVS_SVS;  // *_synch
  // PLC acknowledgement timeouts in s (0 = no timeout; *_prozess_zeit)
  double s_ack_timeout_s = 0, m3_ack_timeout_s = 0, m4_ack_timeout_s = 0,
         m5_ack_timeout_s = 0, m19_ack_timeout_s = 0;
};

struct LinkPair {
  std::string slave, master;       // channel names of the two axes/spindles
  std::uint32_t slave_nr = 0, master_nr = 0;
  std::uint32_t mode = 0;          // P-CHAN-00061: 0 path axes, 1 spindles
};
struct LinkGroup { std::vector<LinkPair> pairs; };

enum class DistFilter : std::uint8_t { defaults, moving_average, lowpass, kalman_ma, expo_mean, kalman_expo, kalman_dyn };

// 3D distance control (dist_ctrl[0], P-CHAN-00800..00827) in mm, mm/s, mm/s^2, s.
struct DistCtrlConfig {
  bool given = false;                 // any dist_ctrl[0] key in the list
  std::uint32_t n_cycles = 4;
  double max_deviation_mm = 5.0;
  double v_max_mm_s = 5.0;
  double a_max_mm_s2 = 0;             // must be > 0 when FCT_3D_DIST_CTRL (else 315001)
  double max_act_value_change_mm_s = 5.0;
  double ref_offset_mm = 0;
  double max_pos_mm = 5.0;
  double min_pos_mm = -5.0;
  double tolerance_mm = 0;
  bool check_sw_limit_switch = false;
  bool mode_dist_use_both_encoder = false;
  bool use_adaptive_acceleration = false;
  double a_min_mm_s2 = 500;
  double dist_error_a_min_mm = 0.1;
  double dist_error_a_max_mm = 0.5;
  bool low_pass_filter_enable = false;
  std::uint32_t low_pass_filter_order = 4;
  double low_pass_filter_fg_f0_hz = 25;
  bool optimized_scheduling = false;
  double v_weight_down = 0;           // factor (list 0.1 %), 0 = off
  double a_weight_down = 0;           // factor (list 0.1 %), 0 = off
  double kp = 1.0;
  double i_tn_s = 0;
  double d_tv_s = 0;
  double kalman_max_dist_change = 1;
  DistFilter filter_type = DistFilter::defaults;
  double kalman_sigma = 4;
  double smoothing_factor = 0.7;
};

struct ChannelConfig {
  SourceRef source;
  std::uint32_t number = 1;       // 1-based
  std::vector<ChannelAxis> axes;  // path axes in channel order (j)
  std::vector<ChannelSpindle> spindles;
  std::string main_spindle_name = "S";          // P-CHAN-00053
  std::uint32_t main_spindle_ax_nr = 0;         // P-CHAN-00051
  bool main_spindle_gear_change = false;        // P-CHAN-00052
  std::string default_ax_name_of_spindle;       // P-CHAN-00010
  std::uint32_t cax_face_id = 0;                // P-CHAN-00008: 1 lathe, 2 milling machine
  // C-axis machining (#CAX): when the main spindle can become a C axis
  // (default_ax_name_of_spindle set, its axis_mode has 0x200) it is also the
  // last entry of `axes`, named default_ax_name_of_spindle, with the
  // spindle's axis list; c_axis is that index (-1: none). Added after the
  // checks (config/c_axis.cpp), so the lists never name it.
  int c_axis = -1;
  std::array<std::uint32_t, 10> trafo_ids{};    // P-CHAN-00262 trafo[i].id, 0 = empty slot
  bool move_tool_offsets_directly = false;      // P-CHAN-00100
  bool exact_stop_after_g00 = false;            // P-CHAN-00235
  SlopeProfile slope_profile = SlopeProfile::step;  // P-CHAN-00071 prog_start.slope.profile
  RapidOverrideMode rapid_override_mode = RapidOverrideMode::not_used;  // P-CHAN-00181 g00_override_mode
  // P-CHAN-00015 (einzelschrittmodus): where single step holds: -1 after
  // motion blocks, 0 also after blocks with functions, 1 after every block
  std::int8_t single_step_mode = 0;
  std::uint32_t lookahead_blocks = 120;         // P-CHAN-00653 configuration.interpolator.number_blocks_lah
  std::array<std::uint32_t, 1000> m_synch{};    // P-CHAN-00041, per M number (lists: NOT_VALID where unset)
  std::uint32_t decoder_function = 0;           // configuration.decoder.function bits
  std::uint32_t max_cache_number = 0;           // configuration.decoder.max_cache_number
  std::uint32_t max_cache_size_kb = 0;          // configuration.decoder.max_cache_size
  LinkGroup default_link_group;                 // synchro_data.koppel_gruppe[0]
  bool preserve_coupling_after_prog_end = false;  // P-CHAN-00105
  std::array<std::uint32_t, 2> decoder_fct_enable{};  // P-CHAN-00507 (bits)
  std::array<std::string, 2> decoder_fct_condition{"ISG_STANDARD", "ISG_STANDARD"};  // P-CHAN-00508
  DistCtrlConfig dist_ctrl;                     // dist_ctrl[0]
  bool einrechnen_mit_t = false;                // P-CHAN-00014
  bool mass_einh_inch = false;                  // P-CHAN-00054
  std::uint32_t messtyp = 1;                    // P-CHAN-00057
  bool versch_im_durchm = false;                // P-CHAN-00091
  bool spindle_m_fct_free = false;              // P-CHAN-00098
  bool modal_i_j_k_for_circle = false;          // P-CHAN-00159
  bool display_diameter_pos = false;            // P-CHAN-00256
  bool thread_ignore_override = false;          // P-CHAN-00836
  bool thread_chain = false;                    // P-CHAN-00837
  bool rotation_mode_fixed = false;             // P-CHAN-00393
  std::string rotation_sequence = "ZYX";        // P-CHAN-00394
  // The program-start mode of the run (P-CHAN-00508's symbols; nck run
  // --start-mode); fct_enable[i] acts only when fct_condition[i] names it.
  std::string start_mode = "ISG_STANDARD";
  bool use_alias_names = false;                 // P-CHAN-00253 (0 after warning 22016)
  bool multi_dimension_in_block = false;        // P-CHAN-00116
  bool multi_axes_in_block = false;             // P-CHAN-00148 (0 after warning 21404)
  // P-CHAN-00500 with the P-CHAN-00507 entries whose condition is the start mode.
  std::uint32_t decoder_functions() const;
  bool dist_ctrl_enabled() const { return (decoder_functions() & decoder_fct::FCT_3D_DIST_CTRL) != 0; }
  // In some start mode (checks at load, which do not know the run's mode).
  bool dist_ctrl_possible() const {
    return ((decoder_function | decoder_fct_enable[0] | decoder_fct_enable[1]) &
            decoder_fct::FCT_3D_DIST_CTRL) != 0;
  }
  std::filesystem::path tool_list, zero_list, clamp_list;  // resolved, empty if none
};

struct ToolRecord {               // wz[i]; lengths in mm (inch lists converted)
  bool given = false;
  double length_mm = 0, radius_mm = 0;  // laenge, radius
  AxisArray axis_offset_mm{};   // ax_versatz[j]
  bool tool_fixed = false;
  std::uint32_t log_ax_nr_spdl = 0;
  double vb_min_rpm = 0, vb_max_rpm = 0, a_max_deg_s2 = 0;
  std::uint32_t typ = 0;       // P-TOOL-00001: 0 milling, 1 turning, 2 grinding, 3 wire
  std::uint32_t cutting_edge_pos = 0;  // P-TOOL-00002 (srk_lage): cutting-edge position 1..9 of a turning tool (0 = none)
};

struct ZeroOffsets {              // nullp list
  bool g53_available = false;
  std::uint32_t default_index = 0;
  // groups[i][j] offset of channel axis j in group i (mm / deg); inactive flags beside
  std::vector<AxisArray> versch;
  std::vector<std::array<bool, kMaxAxes>> inaktiv;
};

struct ClampOffsets {             // pzv list
  std::vector<AxisArray> versatz;
};

struct ChannelData {              // the per-channel lists besides the channel list
  std::vector<ToolRecord> tools;  // index = tool number
  ZeroOffsets zero;
  ClampOffsets clamp;
};

enum class SurfaceKind : std::uint8_t { flat, sine, step, ramp };
enum class SensorFault : std::uint8_t { none, dropout, jump, freeze };

// Simulation parameters (sim.lis, nck's own list): PLC and sensor behaviour.
// List units: times in ms, lengths in 0.1 um; stored here in s and mm.
struct SimConfig {
  double plc_ack_delay_s = 0.01;      // plc_ack_delay_ms: PLC acknowledges an output after this
  double gear_change_time_s = 0.5;    // gear_change_time_ms: PLC time to shift a gear
  std::vector<std::pair<std::uint32_t, double>> m_ack_delay_s;  // m_ack_delay_ms[n]: per M number
  double spindle_ack_delay_s = 0.01;  // spindle_ack_delay_ms: PLC ack of M3/M4/M5/M19/S (PLC_INFO)
  double tool_change_time_s = 0;      // tool_change_time_ms: T/M6 acknowledgement
  double drive_speed_time_constant_s = 0.02;  // drive.speed_time_constant_ms: actual speed lag
  double feed_override_percent = 100;         // initial HLI feed override
  double spindle_override_percent = 100;      // initial HLI spindle override
  // Distance sensor: surface height along one channel axis, plus noise and one fault.
  SurfaceKind surface = SurfaceKind::flat;    // sensor.surface
  std::string surface_axis = "X";             // sensor.surface_axis
  double surface_height_mm = 0;               // sensor.surface_height
  double surface_amplitude_mm = 0;            // sensor.surface_amplitude
  double surface_wavelength_mm = 100;         // sensor.surface_wavelength
  double surface_start_mm = 0;                // sensor.surface_start (step/ramp begin)
  double noise_sigma_mm = 0;                  // sensor.noise_sigma
  std::uint32_t noise_seed = 1;               // sensor.noise_seed
  std::uint32_t sensor_delay_cycles = 0;      // sensor.delay_cycles
  SensorFault fault = SensorFault::none;      // sensor.fault
  double fault_time_s = 0;                    // sensor.fault_time_ms
  double fault_value_mm = 0;                  // sensor.fault_value
  std::uint32_t fault_cycles = 0;             // sensor.fault_cycles (0 = to the end)
  double surface_tilt_deg = 0;                // sensor.surface_tilt
  std::string sensor_tool_axis = "Z";         // sensor.tool_axis
  double hole_start_mm = 0, hole_length_mm = 0, hole_depth_mm = 0;  // sensor.hole_*
  // Measuring probe (G100): it switches when this channel axis reaches this
  // machine position; no axis = it never switches.
  std::string probe_axis;                     // probe.axis
  double probe_position_mm = 0;               // probe.position
};

struct Machine {
  std::filesystem::path folder;
  std::uint32_t cycle_time_us = 1000;
  bool ads_32_bit_comp_mode = true;  // P-STUP-00175
  // Folders searched for cycle files after the program's folder:
  // startup.lis cycle_path[i], then the command line's --cycles.
  std::vector<std::filesystem::path> cycle_paths;
  std::vector<ChannelConfig> channels;
  std::vector<ChannelData> channel_data;  // parallel to channels
  std::vector<AxisConfig> axes;           // all axis lists, in achs_mds order
  SimConfig sim;

  const AxisConfig* axis_by_log_nr(std::uint32_t nr) const {
    for (const auto& a : axes)
      if (a.log_axis_nr == nr) return &a;
    return nullptr;
  }
};

// P-CHAN-00508's start modes: the first of a pair of synonyms ("SV" for
// "BLOCK_SEARCH", "MACHINE_LOCK" for "DRY_RUN" ...), upper case; "" when
// `name` is none of them.
std::string canonical_start_mode(std::string_view name);

// A PLC spindle: plc_control 1 (no axis list) or an axis list with
// axis_mode 0x40000; the PLC commands and acknowledges it.
inline bool is_plc_spindle(const Machine& m, const ChannelSpindle& sp) noexcept {
  if (sp.plc_control) return true;
  if (sp.axis_index < 0 || static_cast<std::size_t>(sp.axis_index) >= m.axes.size()) return false;
  return (m.axes[static_cast<std::size_t>(sp.axis_index)].axis_mode & 0x40000u) != 0;
}

// Axis list `index`'s name: its axis name, or for a spindle's list (which
// has none) the name its channel gives the spindle; empty when neither.
inline const std::string& axis_list_name(const Machine& m, std::size_t index) noexcept {
  static const std::string none;
  if (index >= m.axes.size()) return none;
  if (!m.axes[index].name.empty()) return m.axes[index].name;
  for (const ChannelConfig& ch : m.channels)
    for (const ChannelSpindle& sp : ch.spindles)
      if (sp.axis_index == static_cast<int>(index)) return sp.name;
  return none;
}

}  // namespace nck::config
