#pragma once
// Block preparation (setup side, not real-time): turns a decoded block into
// a Command for the cyclic executor — runs the block's offset functions,
// resolves absolute/incremental words through the offset chain to machine
// positions, builds the path segment and its dynamic limits, and rejects
// what this version cannot execute yet with a clear error.
#include <array>
#include <string>
#include <vector>

#include "nck/prep/ax_link_groups.hpp"
#include "nck/prep/channel_frames.hpp"
#include "nck/prep/kernel_vocabulary.hpp"
#include "nck/config/machine.hpp"
#include "nck/nc/block.hpp"
#include "nck/nc/decoder.hpp"
#include "nck/prep/plan_store.hpp"
#include "nck/kernel/measure.hpp"
#include "nck/motion/cax_transform.hpp"
#include "nck/prep/lookahead_window.hpp"
#include "nck/prep/spindle_planner.hpp"

namespace nck::prep {

struct PlannerOptions {
  std::uint32_t clamp_index = 0;  // pzv_grp chosen at program start (--clamp-index)
};

// The planner is also the decoder's source of kernel state variables: the
// decoder runs one block ahead of nothing (each block is planned as soon as
// it is decoded), so what the planner holds is the state in force at the
// block that reads it.
class Planner final : public nc::KernelStateReader {
 public:
  // spindles: the kernel spindle index of each of the channel's spindles.
  Planner(const config::Machine& machine, std::size_t channel_index, PlanStore& store,
          const PlannerOptions& options, const std::vector<std::int8_t>& spindles);

  // One block becomes one command, or several for G74 homing of path axes
  // (one per homing order group).
  using Commands = PlannedBlock;
  Commands plan(const nc::Block& block);
  Command error_command(ErrorId id, std::string message, std::uint16_t file_id,
                        std::uint32_t line);

  const nc::ModalState& modal() const { return modal_; }
  // The axes' feed dynamics and kink budgets, for corner blending (setup).
  BlendAxes blend_axes() const;
  std::size_t axis_count() const { return n_axes_; }
  const ChannelFrames& frames() const { return frames_; }
  // #DIST CTRL ON/FREEZE has been prepared in this run (the sensor is needed from now on).
  bool dist_ctrl_programmed() const { return dist_programmed_; }
  // Where the machine axes stand when everything planned so far has run.
  const motion::AxisVector& planned_mcs() const { return mcs_; }
  // The programmed position (program coordinates, radii) after everything
  // planned so far; whether axis word j of b is a diameter (G51). Tool
  // radius compensation (radius_comp.hpp) reads both.
  const motion::AxisVector& planned_pcs() const { return pcs_; }
  bool word_is_diameter(const nc::Block& b, std::size_t j) const { return takes_diameter(b, j); }
  // After a G100 run (the caller held further blocks back until it ended):
  // planning goes on from where the axes stopped; G101 uses the result.
  // Returns the decoder's V.A.MESS/MERF/MOFFS variables.
  std::vector<std::pair<std::string, double>> take_measurement(const kernel::MeasureResult& r);
  // V.G.WZ_AKT.*, V.G.ROT_*, V.G.NP_AKT.V.<axis>, V.A.ABS.<axis>, V.A.MEIN.<axis>.
  std::optional<double> read(std::string_view key) const override;
  // After #CAX (the caller held further blocks back until it ran): C starts
  // where the spindle stood (planner_cax.cpp).
  void take_c_axis_position(double c_deg);
  // Machine set point m as the program sees it: Cartesian under #FACE /
  // #CYL, unchanged otherwise (for positions in program coordinates).
  motion::AxisVector cartesian(const motion::AxisVector& m) const;

 private:
  Command plan_one(const nc::Block& block);
  Command plan_motion(const nc::Block& b, Command c);
  Command plan_measuring_run(const nc::Block& b, Command c);
  bool apply_measure_offset(const nc::Block& b, Command& c, Command& error);
  void plan_homing(const nc::Block& b, Command first, Commands& out);
  std::expected<motion::Segment, Command> arc_segment(const nc::Block& b,
                                                      const motion::AxisVector& start,
                                                      const motion::AxisVector& target,
                                                      const motion::AxisVector& origin);
  bool add_outputs(const nc::Block& b, Command& c);
  bool apply_frames(const nc::Block& b, Command& c, Command& error);
  std::string unsupported(const nc::Block& b) const;
  // continuous path (planner_corner.cpp)
  void setup_corner_budgets(const config::Machine& machine);
  motion::AxisVector machine_tangent(const Command& c, bool at_end) const;
  void note_transition(const nc::Block& b, Command& c, bool rapid);
  double start_acceleration(const Command& c) const;
  // G51/G52 (planner_diameter.cpp)
  void setup_diameter_axes(const config::Machine& machine);
  bool check_diameter(const nc::Block& b, Command& c, Command& error);
  bool takes_diameter(const nc::Block& b, std::size_t j) const;
  double programmed_radius(const nc::Block& b, std::size_t j) const;
  std::string plc_control_violation(const nc::Block& b) const;
  int axis_named(const char* name) const;
  // The main axes are found by name: nck::kMainAxisNames (core/plane.hpp).
  static constexpr const auto& kMainAxisNames = nck::kMainAxisNames;
  // spindle-path couplings (planner_links.cpp)
  void find_main_spindle(const std::vector<std::int8_t>& spindles);
  void note_spindle_words(const nc::Block& b);
  double main_vb_max_rpm() const;
  double main_cax_vb_max_rpm() const;
  std::optional<Command> plan_links(const nc::Block& b, Command& c);
  std::optional<Command> plan_feed(const nc::Block& b, const motion::AxisVector& start,
                                   const motion::AxisVector& target, double length_mm, Command& c,
                                   double& v_cmd);
  std::optional<Command> thread_link(const nc::Block& b, const motion::AxisVector& start,
                                     const motion::AxisVector& target, double length_mm, FeedLink& f);
  std::optional<double> rotation_variable(std::string_view field) const;
  std::optional<double> axis_variable(std::string_view key) const;

  const config::Machine* machine_ = nullptr;
  const config::ChannelConfig& channel_;
  PlanStore& store_;
  std::size_t n_axes_ = 0;
  ChannelFrames frames_;
  SpindlePlanner spindles_;
  motion::AxisVector pcs_{};  // programmed position (program coordinates)
  motion::AxisVector mcs_{};  // machine position at the end of the last planned block
  // Bit j: the kernel adds the handwheel offset to axis j (Command::manual_offset_axes).
  std::uint32_t manual_axes_ = ~0u;
  std::uint32_t manual_axes_after(const nc::Block& b, frames::SuppressMask mask) const;
  std::array<motion::AxisDynamics, kMaxAxes> feed_dyn_{}, rapid_dyn_{};
  AxisArray swe_neg_{}, swe_pos_{};
  AxisArray axis_a_max_{};  // dynamik.a_max
  // Velocity change a kink may cause per axis within one cycle (feed / G0).
  std::array<double, kMaxAxes> corner_dv_feed_{}, corner_dv_rapid_{};
  // The last planned motion, for the corner into the next one.
  struct LastMotion {
    bool valid = false;
    motion::AxisVector tangent{};  // at its end, machine axes
    std::array<double, kMaxAxes> corner_dv{};
    double cruise_mm_s = 0;
    double a_dec_mm_s2 = 0;  // along its path
    bool thread = false;     // a G33 block of a thread chain (P-CHAN-00837)
  };
  LastMotion last_motion_{};
  double cycle_s_ = 0.001;
  AxisArray ref_pos_{};  // pos_refpkt: where G74 homes an axis
  nc::ModalState modal_;
  // Bit j: axis j is a face-turning axis / takes diameters under G51 with G90 / with G91.
  std::uint32_t face_axes_ = 0, diameter_abs_axes_ = 0, diameter_rel_axes_ = 0;
  bool diameter_on_ = false;  // G51 in force at the last planned block
  // The last G100 run, in program coordinates (G101 reads it).
  struct Measured {
    bool any = false;        // a G100 run has ended
    bool triggered = false;  // and its probe switched
    motion::AxisVector measured_pcs{};
    motion::AxisVector target_pcs{};
  };
  Measured measured_{};
  motion::AxisVector measure_target_pcs_{};
  std::int8_t probe_axis_ = -1;
  double probe_pos_mm_ = 0;

  // C-axis machining (planner_cax.cpp): #CAX state and the #FACE / #CYL
  // transformation in force. Under a transformation pcs_/mcs_ hold the
  // Cartesian values of the transformed axes; cax_machine_c_deg_ is the
  // machine C where the planned path leaves it.
  struct CaxState {
    bool on = false;
    motion::CaxTrafo trafo{};
    Plane plane = Plane::g17;  // in force when the transformation started
    int plane_first = -1;      // the transformation's first plane axis (#FACE: radial, #CYL: 1st)
    double machine_c_deg = 0;
    // #FACE: C turns at most 45 deg per cycle, so the channel's choice of
    // the nearer solution every cycle follows the contour (set from the cycle time).
    double c_cycle_limit_deg_s = 45000;
    double c_before_deg = 0;  // machine C where the last planned face motion started
    std::string name;         // the C axis's name as the last #CAX gave it
  };
  CaxState cax_{};
  int c_axis_ = -1;               // channel index of the C axis (ChannelConfig::c_axis)
  std::int8_t c_spindle_ = -1;    // its spindle: kernel index
  int c_spindle_channel_ = -1;    // and index in the channel's spindle list
  void init_c_axis(const config::Machine& machine, const std::vector<std::int8_t>& spindles);
  const std::string& c_axis_name() const;
  bool plan_cax(const nc::Block& b, Command& c, Command& error);
  // #DIST CTRL (planner_dist.cpp)
  bool plan_dist(const nc::Block& b, Command& c, Command& error);
  bool dist_on_ = false;            // ON (or FREEZE) programmed and not OFF since
  bool dist_programmed_ = false;    // ON (or FREEZE) prepared at least once
  std::int8_t dist_source_ = 0;     // 0 the sim.lis sensor, 1 a channel variable
  bool dist_var_known_ = false;     // SENSOR_VAR given
  bool plan_cax_on(const nc::Block& b, const nc::CAxis& a, Command& c, Command& error);
  bool plan_trafo(const nc::Block& b, Command& c, Command& error);
  std::string cax_violation(const nc::Block& b, ErrorId& id) const;
  void set_trafo(const motion::CaxTrafo& t);
  void limit_transformed(Command& c, std::array<motion::AxisDynamics, kMaxAxes> dyn);
  bool trafo_plane(int& a, int& b) const;
  void face_centre_commands(const Command& c, Commands& out);
  Command face_turn(const Command& like, const motion::AxisVector& centre_cart, double from_deg, double to_deg) const;
  motion::AxisMask length_axes() const;
  // spindle couplings
  std::int8_t main_spindle_ = -1;          // kernel index of the main spindle
  std::size_t main_channel_spindle_ = 0;   // its index in the channel's list
  double last_s_rpm_ = 0;                  // last programmed S of the main spindle, signed
  nc::Motion prev_motion_ = nc::Motion::rapid;
  int thread_axis_ = 2;                    // G33 pitch letter: 0 I (X), 1 J (Y), 2 K (Z)
  double thread_offset_deg_ = 0;           // S.OFFSET, modal to program end
  bool css_on_ = false;
  double css_m_min_ = 0;
  // synchronous operation (planner_axlink.cpp): the channel's coupling
  // groups; spindle functions of a master are fanned out to its slaves here,
  // path-axis slaves follow their master in planned_mcs() as in the kernel.
  std::optional<AxLinkGroups> links_;
  std::vector<std::int8_t> kernel_spindles_;  // kernel index per channel spindle
  int configured_main_spindle_ = -1;          // channel spindle index (P-CHAN-00051)
  struct AxisFollow {
    int group = 0;
    int slave = 0, master = 0;  // channel axis indices
    double base_slave_mm = 0, base_master_mm = 0, ratio = 1;
  };
  std::vector<AxisFollow> axis_follow_;
  void init_ax_links(const std::vector<std::int8_t>& spindles);
  std::string spindle_out_of_scope(const nc::Block& b) const;
  std::optional<Command> plan_ax_link(const nc::Block& b, Command& c);
  std::optional<Command> ax_link_command(const nc::Block& b, Command& c);
  const nc::Block& with_slaves(const nc::Block& b, nc::Block& scratch) const;
  void end_ax_links(const nc::Block& b);
  void follow_axis_links();
};

}  // namespace nck::prep
