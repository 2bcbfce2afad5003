// Spindle planning, the configuration-driven rules: PLC spindle detection, gear selection of the main spindle
// (FCT-S1 2.8.2; a stage that covers S is kept, also where the seed's example changes it: docs/decisions.md)
// and tool-related dynamic limits (FCT-S1 2.8.5).
#include <string_view>

#include <fmt/format.h>

#include "nck/spindle/gear_select.hpp"
#include "nck/prep/spindle_planner.hpp"

namespace nck::prep {


namespace {

// What to change, for the gear selection errors of the spindle layer.
std::string gear_message(ErrorId id, const nc::SpindleCommand& c, double speed_rpm,
                         std::optional<int> stage, std::uint32_t current) {
  switch (id) {
    case ErrorId::SpindleSpeedTooHigh:
      return fmt::format("{}{}: speed too high, no gear stage range reaches it; program a lower "
                         "speed or raise spindel[i].range_table[k].max_speed",
                         c.name, speed_rpm);
    case ErrorId::SpindleSpeedTooLow:
      return fmt::format("{}{}: speed too low, no gear stage range goes down to it; program a "
                         "higher speed or lower spindel[i].range_table[k].min_speed",
                         c.name, speed_rpm);
    case ErrorId::SpindleSpeedNoRange:
      return fmt::format("{}{}: the speed lies between the gear stage ranges; program a speed "
                         "inside one of spindel[i].range_table",
                         c.name, speed_rpm);
    case ErrorId::SpindleGearStageWrong:
      return fmt::format("M{} {}{}: gear stage {} does not cover the speed; program the stage "
                         "whose range contains it, or another speed",
                         39 + stage.value_or(1), c.name, speed_rpm, stage.value_or(1));
    case ErrorId::SpindleGearStageRequired:
      return fmt::format("{}{}: the current gear stage M{} does not cover the speed and automatic "
                         "selection is off; program M40..M45 with the speed",
                         c.name, speed_rpm, 39 + current);
    case ErrorId::SpindleGearStageInvalid:
      return fmt::format("gear stage {} has no speed range; program M40..M45 for a stage with a "
                         "range in spindel[i].range_table",
                         stage.value_or(0));
    default:
      return fmt::format("{}{}: invalid speed for the gear selection; program a finite speed",
                         c.name, speed_rpm);
  }
}

}  // namespace

// The decoder resolved the name to the channel spindle index (its spindle
// names are the channel list's, decoder_setup.cpp); only the range is checked.
std::optional<std::size_t> SpindlePlanner::find_spindle(const nc::SpindleCommand& c) const {
  if (!channel_ || !c.spindle_index || *c.spindle_index >= channel_->spindles.size()) return std::nullopt;
  return *c.spindle_index;
}

std::expected<void, Diagnostic> SpindlePlanner::plan_gear(Step& s, std::optional<double> speed_rpm) const {
  const nc::SpindleCommand& c = s.c;
  auto fail = [&](ErrorId id, std::string msg) {
    return std::unexpected(make_diagnostic(id, {"", s.b.line, c.column}, std::move(msg)));
  };
  auto push = [&](const SpindleAction& a) -> std::expected<void, Diagnostic> {
    if (s.out.push_back(a)) return {};
    return fail(ErrorId::KernelSpindleTooManyActions,
                "too many spindle actions in one block; split the spindle commands over several blocks");
  };
  // Gear changes exist only for the main spindle in DIN syntax and only when
  // enabled; otherwise M40..M45 are free M functions (FCT-S1 §3.2.1, P-CHAN-00052),
  // synchronised by their m_synch[n] like any other (NO_SYNCH: no output;
  // no entry: an unknown M function).
  if (!c.din || !channel_->main_spindle_gear_change) {
    if (!c.gear_stage) return {};
    SpindleAction a;
    a.spindle = s.kernel_spindle;
    a.op = SpindleOp::user_function;
    a.fn = TechKind::m;
    a.fn_number = 39 + *c.gear_stage;
    a.sync_bits = channel_->m_synch[static_cast<std::size_t>(a.fn_number)];
    if (a.sync_bits == config::sync::NOT_VALID)
      return fail(ErrorId::KernelMFunctionUndefined,
                  fmt::format("M{} is a free M function (gear change is off) and not defined: the channel list has "
                              "no m_synch[{}] (P-CHAN-00041)",
                              a.fn_number, a.fn_number));
    const std::optional<SyncPoint> point = sync_point(a.sync_bits);
    if (!point) return {};
    a.sync = *point;
    a.output = true;  // the PLC acknowledgement is its only wait
    return push(a);
  }
  if (!c.gear_stage && !speed_rpm) return {};
  std::optional<std::uint32_t> programmed;
  if (c.gear_stage) {
    if (*c.gear_stage < 1 || *c.gear_stage > static_cast<int>(config::kMaxGearStages))
      return fail(ErrorId::SpindleGearStageInvalid,
                  gear_message(ErrorId::SpindleGearStageInvalid, c, 0, c.gear_stage, s.st.gear_stage));
    programmed = static_cast<std::uint32_t>(*c.gear_stage);
  }
  // A stage programmed without any speed is shifted to without a range check.
  const double rpm = speed_rpm.value_or(0);
  auto d = spindle::select_gear(s.sp, s.st.gear_stage, rpm, programmed);
  if (!d) return fail(d.error(), gear_message(d.error(), c, rpm, c.gear_stage, s.st.gear_stage));
  if (!d->change) return {};
  if (c.g74)
    return fail(ErrorId::KernelSpindleGearWithHoming,
                fmt::format("gear change to M{} and G74 in one block; program them in separate blocks",
                            39 + d->stage));
  SpindleAction a;
  a.spindle = s.kernel_spindle;
  a.op = SpindleOp::gear_change;
  a.stage = d->stage;
  a.sync_bits = config::sync::MVS_SVS;  // M40..M45 are synchronised before the block (FCT-S1 §2.8.2)
  a.sync = SyncPoint::before;
  a.output = true;
  a.wait = SpindleWait::gear_change;
  a.fn = TechKind::m;
  a.fn_number = static_cast<std::int32_t>(39 + d->stage);
  s.st.gear_stage = d->stage;
  return push(a);
}

std::expected<void, Diagnostic> SpindlePlanner::plan_tool(const nc::Block& b, SpindleActions& out) const {
  std::optional<std::int64_t> d = b.d;
  if (b.hash)
    if (const auto* td = std::get_if<nc::ToolData>(&*b.hash); td && !td->prep) d = td->fields[0];
  // D0 deselects: the last tool's limits stay. An unknown tool is reported
  // by the offset handling, not here.
  if (!d || *d <= 0 || !data_ || static_cast<std::uint64_t>(*d) >= data_->tools.size()) return {};
  const config::ToolRecord& t = data_->tools[static_cast<std::size_t>(*d)];
  if (!t.given || t.log_ax_nr_spdl == 0 || !channel_) return {};  // 0: no transfer
  for (std::size_t i = 0; i < channel_->spindles.size(); ++i) {
    if (channel_->spindles[i].log_axis_nr != t.log_ax_nr_spdl) continue;
    const int k = i < kernel_index_.size() ? kernel_index_[i] : -1;
    if (k < 0 || k > 127) break;
    SpindleAction a;
    a.spindle = static_cast<std::int8_t>(k);
    a.op = SpindleOp::tool_dynamics;
    a.fn = TechKind::s;
    a.tool_vb_min_rpm = t.vb_min_rpm;
    a.tool_vb_max_rpm = t.vb_max_rpm;
    a.tool_a_max_deg_s2 = t.a_max_deg_s2;
    (void)out.push_back(a);  // the first action of the block: always fits
    return {};
  }
  return std::unexpected(make_diagnostic(
      ErrorId::KernelSpindleToolAxis, {"", b.line, 0},
      fmt::format("tool {}: wz[{}].log_ax_nr_spdl {} is not a spindle of this channel; set it to "
                  "a spindle's log_achs_nr or to 0",
                  *d, *d, t.log_ax_nr_spdl)));
}

}  // namespace nck::prep
