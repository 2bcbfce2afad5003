// What a block must satisfy before planning, and its PLC outputs; see block_rules.hpp.
#include "nck/prep/block_rules.hpp"

#include <fmt/format.h>

namespace nck::prep {
namespace {

bool is_fixed_m(int m) {
  switch (m) {
    case 0: case 1: case 2: case 17: case 29: case 30:
      return true;
    default:
      return false;
  }
}

// The non-modal G functions this version executes.
constexpr nc::GCodeSet kExecutedNonModal{nc::GCode::g4,   nc::GCode::g60,  nc::GCode::g61,  nc::GCode::g74,  nc::GCode::g92,  nc::GCode::g100,
                                         nc::GCode::g101, nc::GCode::g102, nc::GCode::g112, nc::GCode::g130,
                                         nc::GCode::g131, nc::GCode::g132, nc::GCode::g133, nc::GCode::g134,
                                         nc::GCode::g233, nc::GCode::g135, nc::GCode::g136, nc::GCode::g137, nc::GCode::g167,
                                         nc::GCode::g196};

// Names what the block asks for that this version does not execute yet, or "".
// (Every # command the decoder yields is executed: it rejects the others.)
std::string unsupported(const nc::Block& b) {
  for (nc::GCode g : b.g_nonmodal)
    if (!kExecutedNonModal.has(g)) return fmt::format("G{} is not executed yet", nc::g_number(g));
  for (const nc::VariableWrite& w : b.kernel_writes)
    if (w.name.rfind("V.G.NP[", 0) != 0) return fmt::format("writing {} is not executed yet", w.name);
  return {};
}

std::uint32_t m_sync(const config::ChannelConfig& channel, int m) {
  return m >= 0 && static_cast<std::size_t>(m) < channel.m_synch.size() ? channel.m_synch[static_cast<std::size_t>(m)]
                                                                         : config::sync::NOT_VALID;
}

PlanResult undefined_m(const nc::Block& b, int m) {
  return block_error(ErrorId::KernelMFunctionUndefined, b,
                     fmt::format("M{} is not defined: the channel list has no m_synch[{}] (P-CHAN-00041)", m, m));
}

// The user M functions in spindle syntax (S[M=63]) are ones the channel
// defines too (TF5200: an unknown M function aborts decoding).
PlanResult check_spindle_m_defined(const nc::Block& b, const config::ChannelConfig& channel) {
  for (const nc::SpindleCommand& s : b.spindles)
    for (int m : s.user_m)
      if (m_sync(channel, m) == config::sync::NOT_VALID) return undefined_m(b, m);
  return {};
}

}  // namespace

PlanResult check_supported(const nc::Block& b) {
  if (std::string why = unsupported(b); !why.empty())
    return block_error(ErrorId::KernelNotYetSupported, b, why + " in this version of nck");
  return {};
}

PlanResult check_spindle_scope(const nc::Block& b) {
  for (const nc::SpindleCommand& s : b.spindles) {
    if (s.callax || s.putax)
      return block_error(ErrorId::SpindleFunctionOutOfScope, b,
                         fmt::format("{}: CALLAX / PUTAX (axis exchange) are not modelled by nck", s.name));
    if (s.feed_link)
      return block_error(ErrorId::SpindleFunctionOutOfScope, b,
                         fmt::format("{}: FEED_LINK (spindle speed from the path feed) is not modelled by nck", s.name));
    if (s.override_speed_fact_pct)
      return block_error(ErrorId::SpindleFunctionOutOfScope, b,
                         fmt::format("{}: OVERRIDE SPEED_FACT (programmed spindle override) is not modelled by nck",
                                     s.name));
  }
  return {};
}

PlanResult check_plc_spindles(const nc::Block& b, const config::ChannelConfig& channel) {
  for (const nc::SpindleCommand& s : b.spindles) {
    if (!s.spindle_index || *s.spindle_index >= channel.spindles.size()) continue;
    const config::ChannelSpindle& sp = channel.spindles[*s.spindle_index];
    if (!sp.plc_control) continue;
    if (s.g74 || s.g167 || s.g130_pct || s.g135 || s.g137 || s.g136_pct || s.gear_stage || s.g112_stage ||
        s.get_dynamic_data || s.default_dynamic_data || !s.user_m.empty() || !s.user_h.empty())
      return block_error(ErrorId::KernelPlcSpindleFunction, b,
                         fmt::format("{} is a PLC spindle over the channel interface: only its speed and "
                                     "M3/M4/M5/M19 can be programmed",
                                     sp.name));
  }
  return {};
}

PlanResult add_outputs(const nc::Block& b, PlannedCommand& c, const config::ChannelConfig& channel) {
  auto overflow = [&] { return block_error(ErrorId::KernelQueueOverflow, b, "more than 8 PLC outputs in one block"); };
  for (int m : b.m) {
    if (is_fixed_m(m)) continue;
    const std::uint32_t sync = m_sync(channel, m);
    if (sync == config::sync::NOT_VALID) return undefined_m(b, m);  // no m_synch entry: unknown
    // A channel M function with NO_SYNCH is not output (FCT-S1 2.5).
    if (sync == config::sync::NO_SYNCH) continue;
    if (!c.attach_within(kernel::Output{TechKind::m, m, sync, 0, nc::value_of(b.m_values, m)}, PlannedCommand::kMaxOutputs))
      return overflow();
  }
  if (auto r = check_spindle_m_defined(b, channel); !r) return r;
  for (int h : b.h)
    if (!c.attach_within(kernel::Output{TechKind::h, h, config::sync::MOS, 0, nc::value_of(b.h_values, h)},
                         PlannedCommand::kMaxOutputs))
      return overflow();
  // #TOOL PREP [basic, ...] is the T word's form (TF5200 #TOOL PREP): the PLC gets the basic number.
  std::optional<std::int64_t> t = b.t;
  if (const auto* td = b.hash ? std::get_if<nc::ToolData>(&*b.hash) : nullptr; td && td->prep) t = td->fields[0];
  if (t && !c.attach_within(kernel::Output{TechKind::t, static_cast<std::int32_t>(*t), config::sync::MOS, 0, std::nullopt}, PlannedCommand::kMaxOutputs))
    return overflow();
  return {};
}

}  // namespace nck::prep
