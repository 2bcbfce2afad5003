#include "nck/serve/snapshot_json.hpp"

#include "nck/core/utf8.hpp"
#include "nck/output/output_writers.hpp"
#include "nck/output/time_by_cause.hpp"

namespace nck::app::serve {
namespace {

using json = nlohmann::ordered_json;

// PCS from MCS through a block's map MCS = rot * PCS + shift (rot orthonormal).
motion::AxisVector to_pcs(const kernel::AffineMap& f, const motion::AxisVector& mcs, std::size_t n) {
  motion::AxisVector pcs{};
  for (std::size_t j = 0; j < n; ++j) pcs[j] = mcs[j] - f.shift[j];
  if (f.pure_translation) return pcs;
  std::array<double, 3> d{};
  for (std::size_t i = 0; i < 3; ++i) d[i] = f.main[i] >= 0 ? pcs[static_cast<std::size_t>(f.main[i])] : 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    if (f.main[i] < 0) continue;
    double v = 0;
    for (std::size_t k = 0; k < 3; ++k) v += f.rot[k][i] * d[k];  // rot transposed
    pcs[static_cast<std::size_t>(f.main[i])] = v;
  }
  return pcs;
}

json channel_json(const LiveChannel& c, const config::ChannelConfig& cfg, const sim::DryRun& run, std::size_t ch,
                  const BlockContext& context) {
  json mcs = json::object(), pcs = json::object();
  motion::AxisVector set{};
  for (std::size_t j = 0; j < cfg.axes.size() && j < set.size(); ++j) set[j] = c.axis_mcs[j];
  const motion::AxisVector program = to_pcs(context.frame, set, cfg.axes.size());
  for (std::size_t j = 0; j < cfg.axes.size() && j < set.size(); ++j) {
    mcs[cfg.axes[j].name] = set[j];
    pcs[cfg.axes[j].name] = program[j];
  }
  const RunNames names{&run};
  json block = {{"file", names.file(ch, c.at.file_id)}, {"line", c.at.line}, {"n", c.at.n ? json(*c.at.n) : json()}};
  json j = {{"channel", ch + 1},
            {"state", std::string(kernel::state_name(c.program_state))},
            {"mcs", std::move(mcs)},
            {"pcs", std::move(pcs)},
            {"path_velocity_mm_s", c.path_velocity_mm_s},
            {"feed_mm_s", c.feed_mm_s},
            {"distance_to_go_mm", c.distance_to_go_mm},
            // an idle channel's cycles go to nothing (time by cause would call them starved)
            {"cause", channel_free(c.program_state) ? json() : json(cause_name(c.cause))},
            {"block", std::move(block)},
            {"feed_override_pct", c.hli.feed_override_percent},
            {"rapid_override_pct", c.hli.rapid_override_percent},
            {"feedhold", c.hli.feedhold},
            {"single_step", c.hli.single_step},
            {"optional_stop", c.hli.optional_stop},
            {"manual_mode", c.hli.manual_mode},
            {"skip_mask", c.hli.skip_mask}};
  j["wait"] = c.cause == kernel::CycleCause::wait ? json(wait_reason_name(c.wait_reason)) : json();
  j["modal"] = context.modal ? json(modal_json(*context.modal)) : json();
  return j;
}

json spindle_json(const LiveSnapshot& s, std::size_t i, const sim::DryRun& run) {
  const kernel::SpindleOutput& o = s.spindles[i];
  const plc::SpindleStatus& h = s.hli_spindles[i];
  return {{"name", run.kernel().spindle_name(i)},
          {"set_rpm", o.set_rpm},
          {"act_rpm", o.act_rpm},
          {"pos_deg", o.set_pos_deg},
          {"gear", h.gear_stage},
          {"override_pct", s.spindle_override_pct[i]},
          {"speed_reached", h.speed_reached},
          {"stopped", h.stopped}};
}

}  // namespace

nlohmann::ordered_json snapshot_json(const LiveSnapshot& s, const config::Machine& m, const sim::DryRun& run,
                                     const ChannelFrames& frames) {
  json channels = json::array();
  for (std::size_t ch = 0; ch < s.channel_count && ch < m.channels.size(); ++ch)
    channels.push_back(channel_json(s.channels[ch], m.channels[ch], run, ch, frames[ch]));
  json spindles = json::array();
  for (std::size_t i = 0; i < s.spindle_count; ++i) spindles.push_back(spindle_json(s, i, run));
  return {{"t_s", s.t_s},
          {"cycle", s.cycle},
          {"run", s.generation},
          {"paused", s.paused},
          {"speed", s.speed},
          {"channels", std::move(channels)},
          {"spindles", std::move(spindles)},
          {"lateness", {{"wakeups", s.lateness.wakeups},
                        {"late_cycles", s.lateness.late_cycles},
                        {"p50_us", s.lateness.p50_us},
                        {"p99_us", s.lateness.p99_us},
                        {"worst_us", s.lateness.worst_us}}},
          {"events_lost", s.events_lost}};
}

}  // namespace nck::app::serve
