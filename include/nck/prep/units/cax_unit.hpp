#pragma once
// C-axis machining in block preparation (FCT-S1 §2.8.8): #CAX / #CAX OFF,
// #FACE / #FACE OFF, #CYL / #CYL OFF, the rules around them, and the path
// limits of a transformed motion. The math is in motion/cax_transform.
// Under a transformation the planned position (PlanContext::planned) holds
// the Cartesian values of the transformed axes.
#include <cstdint>
#include <string>
#include <vector>

#include "nck/motion/cax_transform.hpp"
#include "nck/prep/lookahead_window.hpp"
#include "nck/prep/units/axis_table.hpp"
#include "nck/prep/units/plan_context.hpp"

namespace nck::prep {

class CaxUnit {
 public:
  // spindles: the kernel spindle index of each of the channel's spindles.
  CaxUnit(const config::Machine& machine, const config::ChannelConfig& channel, std::size_t n_axes,
          const std::vector<std::int8_t>& spindles);
  // The channel axis that becomes the C axis (-1: none) and its axis list.
  int c_axis() const { return c_axis_; }
  const config::AxisConfig* c_axis_list() const { return c_list_; }

  // What a block may not do around C-axis mode.
  PlanResult check(const nc::Block& b, const PlanContext& ctx) const;
  // The block's #CAX / #FACE / #CYL.
  PlanResult plan(const nc::Block& b, PlannedCommand& c, PlanContext& ctx);
  // After #CAX (preparation held further blocks back until it ran): C
  // starts where the spindle stood.
  void take_c_axis_position(double c_deg, PlanContext& ctx);

  // Machine set point m as the program sees it: Cartesian under #FACE /
  // #CYL, unchanged otherwise.
  motion::AxisVector cartesian(const motion::AxisVector& m, std::size_t n_axes) const;
  // The axes whose travel counts for the path length.
  motion::AxisMask length_axes() const;
  // The transformation's plane (#FACE: radial and C, #CYL: 1st axis and C);
  // false without a transformation.
  bool trafo_plane(int& a, int& b) const;
  // Limits of motion c under #FACE / #CYL (dyn: the axes' dynamics of its mode).
  void limit_transformed(PlannedCommand& c, const AxisDynamicsArray& dyn, std::size_t n_axes);
  // A face motion as the commands that run it (C turns at the face's centre).
  void face_centre_commands(const PlannedCommand& c, PlannedBlock& out, const PlanContext& ctx);

 private:
  PlanResult plan_cax_on(const nc::Block& b, const nc::CAxis& a, PlannedCommand& c, const PlanContext& ctx);
  PlanResult plan_trafo(const nc::Block& b, PlanContext& ctx);
  const std::string& c_axis_name(const PlanContext& ctx) const;
  void set_trafo(const motion::CaxTrafo& t, PlanContext& ctx);
  PlannedCommand face_turn(const PlannedCommand& like, const motion::AxisVector& centre_cart, double from_deg, double to_deg,
                    const PlanContext& ctx) const;

  bool on_ = false;                 // #CAX in force
  motion::CaxTrafo trafo_{};        // #FACE / #CYL in force
  Plane plane_ = Plane::g17;        // in force when the transformation started
  int plane_first_ = -1;            // the transformation's first plane axis (#FACE: radial, #CYL: 1st)
  double machine_c_deg_ = 0;        // machine C where the planned path leaves it
  // #FACE: C turns at most 45 deg per cycle, so the channel's choice of
  // the nearer solution every cycle follows the contour (set from the cycle time).
  double c_cycle_limit_deg_s_ = 45000;
  double c_before_deg_ = 0;         // machine C where the last planned face motion started
  std::string name_;                // the C axis's name as the last #CAX gave it
  int c_axis_ = -1;                 // channel index of the C axis (ChannelConfig::c_axis)
  std::int8_t c_spindle_ = -1;      // its spindle: kernel index
  int c_spindle_channel_ = -1;      // and index in the channel's spindle list
  const config::AxisConfig* c_list_ = nullptr;
};

}  // namespace nck::prep
