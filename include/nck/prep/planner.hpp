#pragma once
// Block preparation (setup side, not real-time): turns a decoded block into
// the commands for the cyclic executor. The Planner only sequences its
// technology units (prep/units/, docs/architecture.md "Preparation:
// technology units"): each unit owns its state and contributes to the
// command; a failure is a Diagnostic, turned into the error command in one
// place (error_command.hpp).
#include <cstdint>
#include <expected>
#include <optional>
#include <string>
#include <vector>

#include "nck/config/machine.hpp"
#include "nck/kernel/measure.hpp"
#include "nck/nc/block.hpp"
#include "nck/nc/decoder.hpp"
#include "nck/prep/channel_frames.hpp"
#include "nck/prep/kernel_vocabulary.hpp"
#include "nck/prep/lookahead_window.hpp"
#include "nck/prep/plan_store.hpp"
#include "nck/prep/spindle_planner.hpp"
#include "nck/prep/technologies.hpp"
#include "nck/prep/units/axis_table.hpp"
#include "nck/prep/units/cax_unit.hpp"
#include "nck/prep/units/corner_unit.hpp"
#include "nck/prep/units/coupling_unit.hpp"
#include "nck/prep/units/css_unit.hpp"
#include "nck/prep/units/diameter_unit.hpp"
#include "nck/prep/units/dyn_weights.hpp"
#include "nck/prep/units/feed_unit.hpp"
#include "nck/prep/units/manual_unit.hpp"
#include "nck/prep/units/measure_unit.hpp"
#include "nck/prep/units/plan_context.hpp"

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
  // (one per homing order group) and face motions through the centre.
  using Commands = PlannedBlock;
  Commands plan(const nc::Block& block);

  const nc::ModalState& modal() const { return modal_; }
  // The axes' feed dynamics and kink budgets, for corner blending (setup).
  BlendAxes blend_axes() const { return corner_.blend_axes(axes_); }
  std::size_t axis_count() const { return n_axes_; }
  const ChannelFrames& frames() const { return frames_; }
  // The zero-offset list edited while the program runs (ChannelPrep::offer_zero_offsets).
  void set_zero_offsets(const config::ZeroOffsets& zero) { frames_.set_zero_offsets(zero); }
  // The technologies with a home of their own (technologies.hpp).
  const PrepTechnologies& technologies() const { return technologies_; }
  // Where the machine axes stand when everything planned so far has run.
  const motion::AxisVector& planned_mcs() const { return planned_.mcs; }
  // The programmed position (program coordinates, radii) after everything
  // planned so far; whether axis word j of b is a diameter (G51). Tool
  // radius compensation (radius_comp.hpp) reads both.
  const motion::AxisVector& planned_pcs() const { return planned_.pcs; }
  bool word_is_diameter(const nc::Block& b, std::size_t j) const { return diameter_.takes_diameter(b, j); }
  // After a G100 run (the caller held further blocks back until it ended):
  // planning goes on from where the axes stopped; G101 uses the result.
  // Returns the decoder's V.A.MESS/MERF/MOFFS variables.
  std::vector<std::pair<std::string, double>> take_measurement(const kernel::MeasureResult& r);
  // V.G.WZ_AKT.*, V.G.ROT_*, V.G.NP_AKT.V.<axis>, V.A.ABS.<axis>, V.A.MEIN.<axis>.
  std::optional<double> read(std::string_view key) const override;
  // After #CAX (the caller held further blocks back until it ran): C starts
  // where the spindle stood.
  void take_c_axis_position(double c_deg);
  // A reset or an error ended the program where the path stands: planning
  // (MDI after it) goes on from there.
  void take_stopped_position(const motion::AxisVector& path_mcs);
  // Block search: the return to the contour, a rapid straight line from
  // where the axes stand to where the program restarts (exact stop at both ends).
  PlannedCommand return_motion(const motion::AxisVector& from_mcs, const motion::AxisVector& to_mcs) const;
  // Machine set point m as the program sees it: Cartesian under #FACE /
  // #CYL, unchanged otherwise (for positions in program coordinates).
  motion::AxisVector cartesian(const motion::AxisVector& m) const { return cax_.cartesian(m, n_axes_); }

 private:
  PlanContext context();
  // The block's one command, planned into c (a planned command is 3.4 KB:
  // filled in place, never passed by value).
  PlanResult plan_one(const nc::Block& b, PlannedCommand& c, PlanContext& ctx);
  PlanResult plan_technologies(const nc::Block& b, PlannedCommand& c, PlanContext& ctx);
  PlanResult apply_frames(const nc::Block& b, PlannedCommand& c);
  void apply_weights(const nc::Block& b, PlannedCommand& c);
  PlanResult plan_execution(const nc::Block& b, PlannedCommand& c, PlanContext& ctx);
  PlanResult plan_motion(const nc::Block& b, PlannedCommand& c, PlanContext& ctx);
  PlanResult plan_arc(const nc::Block& b, PlannedCommand& c, const motion::AxisVector& target, frames::SuppressMask mask,
                      AxisDynamicsArray& dyn, PlanContext& ctx);
  // The main spindle's planned state (a default one when the channel has none).
  const PlannedSpindle& main_planned() const;

  // What the units share (PlanContext): 8 data members in all.
  const config::Machine* machine_ = nullptr;
  const config::ChannelConfig& channel_;
  PlanStore& store_;
  std::size_t n_axes_ = 0;
  ChannelFrames frames_;
  PlannedPosition planned_;  // pcs, mcs
  nc::ModalState modal_;     // of the block planned last (for --final and V.G.ROT_*)
  // The technology units, in the order their data is set up.
  CaxUnit cax_;
  AxisTable axes_;
  CornerUnit corner_;
  DynWeights weights_;
  SpindlePlanner spindles_;
  FeedUnit feed_;
  CssUnit css_;
  DiameterUnit diameter_;
  MeasureUnit measure_;
  ManualUnit manual_;
  CouplingUnit couplings_;
  nc::Block with_slaves_scratch_;  // a block with its coupled spindles' commands (kept: built rarely)
  PrepTechnologies technologies_;
};

}  // namespace nck::prep
