// Startup and channel list keys (P-STUP / P-CHAN, TF5200 parameter pages; docs/parameters.md).
// Row: key, ID, list, type, min, max, default, scale (list -> internal),
// list unit, internal unit, meaning, index counts, choices, text default.
#include "registry_internal.hpp"

namespace nck::config::detail {
namespace {

using L = ListKind;
using T = ParamType;
constexpr auto S = L::startup;
constexpr auto C = L::channel;

constexpr ParamInfo kTable[] = {
    // ---- startup.lis -------------------------------------------------------
    {"kanal_anzahl", "P-STUP-00001", S, T::integer, 1, 12, 0, 1, "—", "—", "Number of channels; counted from sda_mds[i] when omitted, must match when given."},
    {"listen", "P-STUP-00008", S, T::choice, 0, 0, 0, 1, "—", "—", "List format; nck reads ASCII lists only.", {}, "ASCII BINAER", "ASCII"},
    {"sda_mds[]", "P-STUP-00009", S, T::path, 0, 256, 0, 1, "path", "path", "Channel parameter list of channel i+1.", {12}, {}, "''"},
    {"werkz_data[]", "P-STUP-00010", S, T::path, 0, 256, 0, 1, "path", "path", "Tool list of channel i+1 (optional).", {12}, {}, "''"},
    {"nullp_data[]", "P-STUP-00011", S, T::path, 0, 256, 0, 1, "path", "path", "Zero-offset list of channel i+1 (optional).", {12}, {}, "''"},
    {"pzv_data[]", "P-STUP-00012", S, T::path, 0, 256, 0, 1, "path", "path", "Clamp-offset list of channel i+1 (optional).", {12}, {}, "''"},
    {"hand_mds", "P-STUP-00013", S, T::path, 0, 256, 0, 1, "path", "path", "Manual-mode list; accepted and not read by nck.", {}, {}, "''"},
    {"zahl_mds", "P-STUP-00014", S, T::integer, 1, 32, 0, 1, "—", "—", "Number of axis lists; counted from achs_mds[i] when omitted, must match when given."},
    {"achs_mds[]", "P-STUP-00015", S, T::path, 0, 256, 0, 1, "path", "path", "Axis parameter list i (one per path axis or spindle).", {32}, {}, "''"},
    {"zahl_kw", "P-STUP-00016", S, T::integer, 0, 32, 0, 1, "—", "—", "Number of compensation lists; accepted, not used."},
    {"achs_kw[]", "P-STUP-00017", S, T::path, 0, 256, 0, 1, "path", "path", "Compensation list i; accepted, not read.", {32}, {}, "''"},
    {"default_sda_mds", "P-STUP-00034", S, T::path, 0, 256, 0, 1, "path", "path", "Channel list read before every channel list (its values are defaults).", {}, {}, "''"},
    {"default_achs_mds", "P-STUP-00035", S, T::path, 0, 256, 0, 1, "path", "path", "Axis list read before every axis list (its values are defaults).", {}, {}, "''"},
    {"achs_kw_log_ax_nr[]", "P-STUP-00036", S, T::integer, 1, kU16, 0, 1, "—", "—", "Axis of compensation list i; accepted, not used.", {32}},
    {"ads_32_bit_comp_mode", "P-STUP-00175", S, T::integer, 0, 3, 1, 1, "—", "—", "HLI positions as scaled 32-bit values (1) or 64-bit (0, 2)."},
    {"sim_data", "nck", S, T::path, 0, 256, 0, 1, "path", "path", "Simulation list (PLC, drives, distance sensor), optional.", {}, {}, "''"},
    {"cycle_time_us", "nck", S, T::integer, 100, 100000, 1000, 1, "µs", "µs", "Interpolation cycle time."},
    {"cycle_path[]", "nck", S, T::path, 0, 256, 0, 1, "path", "path", "Folder searched for L CYCLE files after the program's folder (relative to the machine folder), in index order.", {8}, {}, "''"},

    // ---- channel list: axes and spindles ---------------------------------
    {"grp_anzahl", "P-CHAN-00023", C, T::integer, 0, 1, 1, 1, "—", "—", "Number of axis groups (always 1); accepted."},
    {"gruppe[].bezeichnung", "P-CHAN-00005", C, T::string, 0, 16, 0, 1, "—", "—", "Name of the axis group; accepted.", {1}, {}, "''"},
    {"gruppe[].achs_anzahl", "P-CHAN-00003", C, T::integer, 0, 32, 0, 1, "—", "—", "Number of path axes; informative, nck counts the entries.", {1}},
    {"gruppe[].achse[].bezeichnung", "P-CHAN-00006", C, T::string, 0, 16, 0, 1, "—", "—", "NC name of channel axis j (starts with A B C U V W X Y Z Q).", {1, 32}, {}, "''"},
    {"gruppe[].achse[].log_achs_nr", "P-CHAN-00035", C, T::integer, 0, kU16, 0, 1, "—", "—", "Logical axis number behind channel axis j.", {1, 32}},
    {"spdl_anzahl", "P-CHAN-00082", C, T::integer, 0, 16, 0, 1, "—", "—", "Number of spindles of the channel; counted when omitted, must match spindel[i]."},
    {"spindel[].bezeichnung", "P-CHAN-00007", C, T::string, 0, 16, 0, 1, "—", "—", "Name of spindle i (starts with S).", {16}, {}, "''"},
    {"spindel[].log_achs_nr", "P-CHAN-00036", C, T::integer, 1, kU16, 0, 1, "—", "—", "Logical axis number of spindle i.", {16}},
    {"spindel[].plc_control", "P-CHAN-00069", C, T::boolean, 0, 1, 0, 1, "—", "—", "Spindle run by the PLC over the channel interface; needs no axis list.", {16}},
    {"spindel[].autom_range", "P-CHAN-00004", C, T::boolean, 0, 1, 0, 1, "—", "—", "Gear stage chosen from S automatically (1) or by M40..M45 (0).", {16}},
    {"spindel[].range_way", "P-CHAN-00074", C, T::integer, 0, kU16 - 1, 0, 1, "—", "—", "Gear table search order: 0 from stage 1 up, >0 from stage 6 down.", {16}},
    {"spindel[].range_table[].min_speed", "P-CHAN-00058", C, T::integer, 0, kU16, 0, 1, "rpm", "rpm", "Lowest speed of gear stage j+1 (M40+j); 0/0 = unused.", {16, 6}},
    {"spindel[].range_table[].max_speed", "P-CHAN-00055", C, T::integer, 0, kU16, 0, 1, "rpm", "rpm", "Highest speed of gear stage j+1 (M40+j); 0/0 = unused.", {16, 6}},
    {"spindel[].s_synch", "P-CHAN-00081", C, T::sync, 0, 0, 2, 1, "—", "bits", "Sync type of the S word (nck default MVS_SVS; ISG NO_SYNCH).", {16}, {}, "MVS_SVS"},
    {"spindel[].m3_synch", "P-CHAN-00045", C, T::sync, 0, 0, 2, 1, "—", "bits", "Sync type of M3 (NO_SYNCH: M3 not executed, check warns).", {16}, {}, "MVS_SVS"},
    {"spindel[].m4_synch", "P-CHAN-00047", C, T::sync, 0, 0, 2, 1, "—", "bits", "Sync type of M4.", {16}, {}, "MVS_SVS"},
    {"spindel[].m5_synch", "P-CHAN-00049", C, T::sync, 0, 0, 2, 1, "—", "bits", "Sync type of M5.", {16}, {}, "MVS_SVS"},
    {"spindel[].m19_synch", "P-CHAN-00043", C, T::sync, 0, 0, 2, 1, "—", "bits", "Sync type of M19.", {16}, {}, "MVS_SVS"},
    {"spindel[].s_prozess_zeit", "P-CHAN-00080", C, T::integer, 0, kU32, 0, 1e-6, "µs", "s", "PLC acknowledgement timeout of S (0 = none).", {16}},
    {"spindel[].m3_prozess_zeit", "P-CHAN-00044", C, T::integer, 0, kU32, 0, 1e-6, "µs", "s", "PLC acknowledgement timeout of M3 (0 = none).", {16}},
    {"spindel[].m4_prozess_zeit", "P-CHAN-00046", C, T::integer, 0, kU32, 0, 1e-6, "µs", "s", "PLC acknowledgement timeout of M4 (0 = none).", {16}},
    {"spindel[].m5_prozess_zeit", "P-CHAN-00048", C, T::integer, 0, kU32, 0, 1e-6, "µs", "s", "PLC acknowledgement timeout of M5 (0 = none).", {16}},
    {"spindel[].m19_prozess_zeit", "P-CHAN-00042", C, T::integer, 0, kU32, 0, 1e-6, "µs", "s", "PLC acknowledgement timeout of M19 (0 = none).", {16}},
    {"main_spindle_ax_nr", "P-CHAN-00051", C, T::integer, 0, kU16, 0, 1, "—", "—", "Logical axis number of the main spindle after start (must be a spindel[i])."},
    {"main_spindle_name", "P-CHAN-00053", C, T::string, 0, 16, 0, 1, "—", "—", "Name under which the main spindle is programmed (DIN syntax).", {}, {}, "S"},
    {"main_spindle_gear_change", "P-CHAN-00052", C, T::boolean, 0, 1, 0, 1, "—", "—", "Enables M40..M45 gear changes of the main spindle."},
    {"default_ax_name_of_spindle", "P-CHAN-00010", C, T::string, 0, 16, 0, 1, "—", "—", "Axis name of the spindle as C axis (#CAX); path-axis naming rules apply.", {}, {}, "''"},
    {"cax_face_id", "P-CHAN-00008", C, T::integer, 0, 2, 0, 1, "—", "—", "Face machining variant: 1 lathe, 2 milling machine."},
    {"m_synch[]", "P-CHAN-00041", C, T::sync, 0, 0, 0, 1, "—", "bits", "Sync type of M function n (index = M number); unset = NO_SYNCH in nck.", {1000}, {}, "NOT_VALID"},
    {"spindle_m_fct_free", "P-CHAN-00098", C, T::boolean, 0, 1, 0, 1, "—", "—", "M3/M4/M5/M19 lose their spindle meaning."},
    {"synchro_data.koppel_gruppe[].paar[].log_achs_nr_slave", "P-CHAN-00038", C, T::integer, 1, kU16, 0, 1, "—", "—", "Slave of default coupling pair j (group 0).", {1, 15}},
    {"synchro_data.koppel_gruppe[].paar[].log_achs_nr_master", "P-CHAN-00037", C, T::integer, 1, kU16, 0, 1, "—", "—", "Master of default coupling pair j (group 0).", {1, 15}},
    {"synchro_data.koppel_gruppe[].paar[].mode", "P-CHAN-00061", C, T::integer, 0, 1, 0, 1, "—", "—", "Pair kind: 0 path axes, 1 spindles.", {1, 15}},
    {"synchro_data.preserve_coupling_after_prog_end", "P-CHAN-00105", C, T::boolean, 0, 1, 0, 1, "—", "—", "Active couplings survive program end."},

    // ---- channel list: technology switches --------------------------------
    {"einrechnen_mit_t", "P-CHAN-00014", C, T::boolean, 0, 1, 0, 1, "—", "—", "T also selects D with the same number."},
    {"mass_einh", "P-CHAN-00054", C, T::integer, 0, 1, 0, 1, "—", "—", "Program unit of linear axes: 0 mm, 1 inch."},
    {"messtyp", "P-CHAN-00057", C, T::integer, 1, 7, 1, 1, "—", "—", "Measuring-move variant."},
    {"versch_im_durchm", "P-CHAN-00091", C, T::boolean, 0, 1, 0, 1, "—", "—", "Face-axis offsets are diameters."},
    {"einzelschrittmodus", "P-CHAN-00015", C, T::integer, -1, 1, 0, 1, "—", "—", "Single step stops after: -1 motion blocks only, 0 motion blocks and blocks with functions (M, H, T, S, dwell), 1 every block."},
    {"prog_start.slope.profile", "P-CHAN-00071", C, T::integer, 0, 3, 0, 1, "—", "—", "Acceleration profile of path motions at program start and after #SLOPE DEFAULT: 0 step, 1 trapezoid, 2 sine-square, 3 HSC (trapezoid across the blocks the path passes at speed)."},
    {"g00_override_mode", "P-CHAN-00181", C, T::choice, 0, 0, 0, 1, "—", "—", "Which override scales G0 blocks: NOT_USED (0) the feed override, MINIMUM_OF_G0_G1 (1) the smaller of feed and rapid override, ACTIVE (2) the rapid override, ACTIVE_EXTENDED (3) as ACTIVE and continuous jog too.", {},
     "NOT_USED MINIMUM_OF_G0_G1 ACTIVE ACTIVE_EXTENDED 0 1 2 3", "NOT_USED"},
    {"exact_stop_after_g00", "P-CHAN-00235", C, T::boolean, 0, 1, 0, 1, "—", "—", "Every G0 block ends with an exact stop (G60)."},
    {"configuration.interpolator.number_blocks_lah", "P-CHAN-00653", C, T::integer, 10, 500, 120, 1, "blocks", "blocks", "Motion blocks in the velocity look-ahead window; nck takes at most 120 (its command queue must hold every block the window planned with: docs/decisions.md, Preparation and look-ahead)."},
    {"move_tool_offsets_directly", "P-CHAN-00100", C, T::boolean, 0, 1, 0, 1, "—", "—", "Tool offsets move with the D word (1) or at the next absolute move (0)."},
    {"modal_i_j_k_for_circle", "P-CHAN-00159", C, T::boolean, 0, 1, 0, 1, "—", "—", "Circle centre I/J/K stay modal."},
    {"multi_dimension_in_block", "P-CHAN-00116", C, T::boolean, 0, 1, 0, 1, "—", "—", "G90 and G91 in one block, each acting on the positions after it; nck takes them when all positions of the block get one dimension (else 920052)."},
    {"multi_axes_in_block", "P-CHAN-00148", C, T::boolean, 0, 1, 0, 1, "—", "—", "An axis several times in one block (needs multi_dimension_in_block, else 21404): under G90 the last value counts, under G91 they add up; without it 20203."},
    {"use_alias_name_in_ax_list", "P-CHAN-00253", C, T::boolean, 0, 1, 0, 1, "—", "—", "Alias names A1..A32 allowed in axis-specific moves."},
    {"display_diameter_pos", "P-CHAN-00256", C, T::boolean, 0, 1, 0, 1, "—", "—", "HLI shows PCS positions as diameter under G51."},
    {"trafo[].id", "P-CHAN-00262", C, T::integer, 1, kU16, 0, 1, "—", "—", "Kinematic ID of transformation slot i: #FACE needs 13 (cax_face_id 1) or 14 (cax_face_id 2), #CYL 15.", {10}},
    {"enable_unit_feet_cut_speed", "P-CHAN-00360", C, T::boolean, 0, 1, 0, 1, "—", "—", "G96 cutting speed in ft/min under G70."},
    {"coordinate_system.rotation_mode_fixed", "P-CHAN-00393", C, T::boolean, 0, 1, 0, 1, "—", "—", "#CS angles about fixed (1) or rotated (0) axes."},
    {"coordinate_system.rotation_sequence", "P-CHAN-00394", C, T::choice, 0, 0, 0, 1, "—", "—", "Order of the three #CS rotations.", {}, "XYZ XYX XZY XZX YXZ YXY YZX YZY ZXY ZXZ ZYX ZYZ", "ZYX"},
    {"thread_cutting.ignore_override", "P-CHAN-00836", C, T::boolean, 0, 1, 0, 1, "—", "—", "Feed override ignored during G33."},
    {"thread_cutting.thread_chain", "P-CHAN-00837", C, T::boolean, 0, 1, 0, 1, "—", "—", "Consecutive G33 blocks run without stop."},

    // ---- channel list: decoder ------------------------------------------------
    {"configuration.decoder.function", "P-CHAN-00500", C, T::decoder_fct, 0, 0, 0, 1, "—", "bits", "Decoder features (FCT_USE_CACHED_FILES, FCT_3D_DIST_CTRL, ...), OR-ed.", {}, {}, "''"},
    {"configuration.decoder.max_cache_number", "P-CHAN-00503", C, T::integer, 0, kU32, 4, 1, "—", "—", "Most subprogram files kept in the file cache."},
    {"configuration.decoder.max_cache_size", "P-CHAN-00504", C, T::integer, 0, kU32, 4096, 1, "kB", "kB", "Largest file that is cached."},
    {"configuration.decoder.fct_enable[]", "P-CHAN-00507", C, T::decoder_fct, 0, 0, 0, 1, "—", "bits", "Decoder features enabled under condition i.", {2}, {}, "''"},
    {"configuration.decoder.fct_condition[]", "P-CHAN-00508", C, T::choice, 0, 0, 0, 1, "—", "—", "Start mode that enables fct_enable[i].", {2},
     "ISG_STANDARD SV BLOCK_SEARCH SOLLKON CONTOUR_VISU ON_LINE SYNCHCK SYNTAX_CHECK PROD_TIME ONLINE_PROD_TIME MACHINE_LOCK DRY_RUN SCENE", "ISG_STANDARD"},

    // ---- channel list: 3D distance control (dist_ctrl[0]) ---------------------
    {"dist_ctrl[].n_cycles", "P-CHAN-00800", C, T::integer, 0, 99, 4, 1, "—", "—", "Sensor samples averaged (moving average).", {1}},
    {"dist_ctrl[].max_deviation", "P-CHAN-00801", C, T::integer, 0, kS32 - 1, 50000, 1e-4, "0.1 µm", "mm", "Largest correction offset; beyond it: error and clamp.", {1}},
    {"dist_ctrl[].v_max", "P-CHAN-00802", C, T::integer, 0, kS32 - 1, 5000, 1e-3, "µm/s", "mm/s", "Speed limit of the correction motion.", {1}},
    {"dist_ctrl[].a_max", "P-CHAN-00803", C, T::integer, 0, kS32 - 1, 0, 1, "mm/s²", "mm/s²", "Acceleration limit of the correction; must be > 0 when enabled (315001).", {1}},
    {"dist_ctrl[].max_act_value_change", "P-CHAN-00804", C, T::integer, 0, kS32 - 1, 5000, 1e-3, "µm/s", "mm/s", "Largest allowed rate of change of the measured distance.", {1}},
    {"dist_ctrl[].ref_offset", "P-CHAN-00805", C, T::integer, kS32Min, kS32 - 1, 0, 1e-4, "0.1 µm", "mm", "Shift of the sensor range (reference point).", {1}},
    {"dist_ctrl[].max_pos", "P-CHAN-00806", C, T::integer, 0, kS32 - 1, 50000, 1e-4, "0.1 µm", "mm", "Upper sensor limit.", {1}},
    {"dist_ctrl[].min_pos", "P-CHAN-00807", C, T::integer, kS32Min, kS32 - 1, -50000, 1e-4, "0.1 µm", "mm", "Lower sensor limit (negative allowed, as its default).", {1}},
    {"dist_ctrl[].tolerance", "P-CHAN-00808", C, T::integer, 0, kS32 - 1, 0, 1e-4, "0.1 µm", "mm", "Safety band inside the sensor limits (310019/310020).", {1}},
    {"dist_ctrl[].check_sw_limit_switch", "P-CHAN-00809", C, T::boolean, 0, 1, 0, 1, "—", "—", "Include the correction in software-limit checks.", {1}},
    {"dist_ctrl[].mode_dist_use_both_encoder", "P-CHAN-00810", C, T::boolean, 0, 1, 0, 1, "—", "—", "Couple distance sensor and motor encoder (accepted, no effect in simulation).", {1}},
    {"dist_ctrl[].use_adaptive_acceleration", "P-CHAN-00811", C, T::boolean, 0, 1, 0, 1, "—", "—", "Acceleration grows with the distance error (a_min..a_max).", {1}},
    {"dist_ctrl[].a_min", "P-CHAN-00812", C, T::integer, 1, kU32, 500, 1, "mm/s²", "mm/s²", "Acceleration at small errors (adaptive mode).", {1}},
    {"dist_ctrl[].dist_error_a_min", "P-CHAN-00813", C, T::integer, 0, kU32 - 1, 1000, 1e-4, "0.1 µm", "mm", "Error up to which a_min applies.", {1}},
    {"dist_ctrl[].dist_error_a_max", "P-CHAN-00814", C, T::integer, 0, kU32 - 1, 5000, 1e-4, "0.1 µm", "mm", "Error from which a_max applies.", {1}},
    {"dist_ctrl[].low_pass_filter_enable", "P-CHAN-00815", C, T::boolean, 0, 1, 0, 1, "—", "—", "Low-pass filter on the sensor value.", {1}},
    {"dist_ctrl[].low_pass_filter_order", "P-CHAN-00816", C, T::integer, 0, 6, 4, 1, "—", "—", "Low-pass order (-20 dB/decade each).", {1}},
    {"dist_ctrl[].low_pass_filter_fg_f0", "P-CHAN-00817", C, T::real, 0, kInf, 25, 1, "Hz", "Hz", "Low-pass corner frequency.", {1}},
    {"dist_ctrl[].optimized_scheduling", "P-CHAN-00818", C, T::boolean, 0, 1, 0, 1, "—", "—", "Reduced dead time (accepted, no effect in simulation).", {1}},
    {"dist_ctrl[].v_weight_down", "P-CHAN-00819", C, T::integer, 0, 1999, 0, 1e-3, "0.1 %", "factor", "Speed weight towards the workpiece (0 = off).", {1}},
    {"dist_ctrl[].a_weight_down", "P-CHAN-00820", C, T::integer, 0, 1999, 0, 1e-3, "0.1 %", "factor", "Acceleration weight towards the workpiece (0 = off).", {1}},
    {"dist_ctrl[].kp", "P-CHAN-00821", C, T::real, 1e-9, 2.0, 1.0, 1, "—", "—", "Gain on the cyclic correction.", {1}},
    {"dist_ctrl[].i_tn", "P-CHAN-00822", C, T::real, 0, 50, 0, 1, "s", "s", "Integral time of the PID (0 = no I part).", {1}},
    {"dist_ctrl[].d_tv", "P-CHAN-00823", C, T::real, 0, 2, 0, 1, "s", "s", "Derivative time of the PID (0 = no D part).", {1}},
    {"dist_ctrl[].kalman_max_dist_change", "P-CHAN-00824", C, T::real, -kInf, kInf, 1, 1, "—", "—", "Kalman filter parameter (semantics not documented).", {1}},
    {"dist_ctrl[].filter_type", "P-CHAN-00825", C, T::choice, 0, 0, 0, 1, "—", "—", "Sensor smoothing filter.", {1},
     "DEFAULT MOVING_AVERAGE LOWPASS KALMAN_MA EXPO_MEAN KALMAN_EXPO KALMAN_DYN", "DEFAULT"},
    {"dist_ctrl[].kalman_sigma", "P-CHAN-00826", C, T::real, 1, 10000, 4, 1, "—", "—", "Kalman measurement uncertainty.", {1}},
    {"dist_ctrl[].smoothing_factor", "P-CHAN-00827", C, T::real, 1e-9, 1, 0.7, 1, "—", "—", "Weight of the newest sample in the exponential mean.", {1}},
};

}  // namespace

std::span<const ParamInfo> startup_channel_table() { return kTable; }

}  // namespace nck::config::detail
