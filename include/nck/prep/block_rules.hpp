#pragma once
// What a block must satisfy before its technologies are planned, and the
// PLC outputs (M, H, T) it carries.
#include "nck/prep/units/plan_context.hpp"

namespace nck::prep {

// What this version does not execute yet (# commands, non-modal G
// functions, variable writes): KernelNotYetSupported.
PlanResult check_supported(const nc::Block& b);
// Spindle-syntax functions nck does not model (CALLAX/PUTAX, FEED_LINK,
// OVERRIDE SPEED_FACT): SpindleFunctionOutOfScope.
PlanResult check_spindle_scope(const nc::Block& b);
// A spindle commanded over the channel HLI (plc_control 1) knows only its
// speed and M3/M4/M5/M19 (FCT-S1 2.2.2.2).
PlanResult check_plc_spindles(const nc::Block& b, const config::ChannelConfig& channel);
// The block's M (with their synchronisation), H and T outputs into c.
PlanResult add_outputs(const nc::Block& b, PlannedCommand& c, const config::ChannelConfig& channel);

// With these the axis words are the function's values (homing order, G92
// offset, G101 factor, G102 selection, G130/G132 weighting in %), not a
// motion target.
inline constexpr nc::GCodeSet kAxisWordsAreValues{nc::GCode::g74,  nc::GCode::g92,  nc::GCode::g101,
                                                  nc::GCode::g102, nc::GCode::g130, nc::GCode::g132};

}  // namespace nck::prep
