#include "nck/run/state_document.hpp"

#include <algorithm>
#include <cmath>

#include "nck/core/shown_number.hpp"
#include "nck/core/utf8.hpp"
#include "nck/output/output_writers.hpp"
#include "nck/output/time_by_cause.hpp"

namespace nck::app {
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

bool face_turning(const config::Machine& m, const config::ChannelAxis& a) {
  return a.axis_index >= 0 && m.axes[static_cast<std::size_t>(a.axis_index)].is_face_turning();
}

json channel_json(const LiveChannel& c, const config::Machine& m, const prep::RunRecords& run, std::size_t ch,
                  const ChannelPlace& place, const LastErrors* errors) {
  const config::ChannelConfig& cfg = m.channels[ch];
  json mcs = json::object(), pcs = json::object(), dtg = json::object(), axes = json::object();
  for (std::size_t j = 0; j < cfg.axes.size() && j < place.pcs.size(); ++j) {
    const std::string& name = cfg.axes[j].name;
    mcs[name] = shown(c.axis_mcs[j]);
    pcs[name] = shown(place.pcs[j]);
    dtg[name] = shown(c.axis_dtg[j]);
    axes[name] = {{"mcs", mcs[name]}, {"pcs", pcs[name]}, {"dtg", dtg[name]},
                  {"homed", (c.homed_axes >> j & 1u) != 0},
                  {"requires_homing", (c.homing_required >> j & 1u) != 0}};
    // a face-turning axis also as the diameter G51 programs (as --final writes it)
    if (face_turning(m, cfg.axes[j])) axes[name]["pcs_diameter"] = shown(2 * place.pcs[j]);
  }
  const RunNames names{&run};
  json block = {{"file", names.file(ch, c.at.file_id)}, {"line", c.at.line}, {"n", c.at.n ? json(*c.at.n) : json()}};
  const std::string state(kernel::state_name(c.program_state));
  json j = {{"channel", ch + 1},
            {"state", state},
            {"program_state", state},  // the Python session's name for it (both stay)
            {"mcs", std::move(mcs)},
            {"pcs", std::move(pcs)},
            {"dtg", std::move(dtg)},
            {"axes", std::move(axes)},  // per axis: the Python session's layout
            {"path_velocity_mm_s", shown(c.path_velocity_mm_s)},
            {"feed_mm_s", shown(c.feed_mm_s)},
            {"distance_to_go_mm", shown(c.distance_to_go_mm)},
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
  j["modal"] = place.modal ? json(modal_json(*place.modal)) : json();
  if (place.modal) j["modal"]["D"] = place.modal->d;
  // P-CHAN-00256: under G51 a display shows the face-turning axis's PCS position as a diameter
  j["diameter_display"] = cfg.display_diameter_pos && place.modal && place.modal->diameter;
  j["last_error"] = errors ? errors->channel(ch + 1) : json();
  return j;
}

json spindle_json(const LiveSnapshot& s, std::size_t i, const prep::RunRecords& run) {
  const kernel::SpindleOutput& o = s.spindles[i];
  const plc::SpindleStatus& h = s.hli_spindles[i];
  return {{"name", run.spindle_name(i) ? *run.spindle_name(i) : std::string()},
          {"set_rpm", shown(o.set_rpm)},
          {"act_rpm", shown(o.act_rpm)},
          {"pos_deg", shown(o.set_pos_deg)},
          {"gear", h.gear_stage},
          {"override_pct", s.spindle_override_pct[i]},
          {"speed_reached", h.speed_reached},
          {"stopped", h.stopped}};
}

}  // namespace

nlohmann::ordered_json state_json(const LiveSnapshot& s, const config::Machine& m, const prep::RunRecords& run,
                                  std::span<const ChannelPlace> places, const LastErrors* errors) {
  json channels = json::array();
  for (std::size_t ch = 0; ch < s.channel_count && ch < m.channels.size() && ch < places.size(); ++ch)
    channels.push_back(channel_json(s.channels[ch], m, run, ch, places[ch], errors));
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
          {"events_lost", s.events_lost},
          // E-stop and machine on (issue 48 item 9): reset_needed until a reset after the E-stop's release
          {"estop", s.machine.estop},
          {"machine_on", s.machine.machine_on},
          {"reset_needed", s.machine.reset_needed},
          {"drives_enabled", s.machine.drives_enabled},
          // the newest error of any channel (or of none: a spindle's), until a reset
          {"last_error", errors ? errors->latest() : json()}};
}

void note_event(ChannelFrames& frames, const kernel::Event& e, const prep::RunRecords& run) {
  if (e.channel < 1 || static_cast<std::size_t>(e.channel) > frames.size()) return;
  BlockContext& b = frames[e.channel - 1u];
  if (const auto* o = e.get<nck::frames::OffsetEvent>()) {
    const std::string& kind = run.offset(o->index).kind;
    if (kind == "acs") b.acs_offset = o->index;
    if (kind == "cs") b.cs_offset = o->index;
    return;
  }
  const auto* block = e.get<kernel::ev::Block>();
  if (!block || !block->frame_index) return;
  const kernel::AffineMap* f = run.frame(*block->frame_index);
  if (!f) return;
  b.frame = *f;
  if (const nc::ModalState* m = run.modal(*block->frame_index)) b.modal = *m;
}

std::array<ChannelPlace, config::kMaxChannels> channel_places(const LiveSnapshot& s, const config::Machine& m,
                                                             const ChannelFrames& frames) {
  std::array<ChannelPlace, config::kMaxChannels> places{};
  for (std::size_t ch = 0; ch < s.channel_count && ch < m.channels.size() && ch < places.size(); ++ch) {
    const std::size_t n = m.channels[ch].axes.size();
    motion::AxisVector set{};
    for (std::size_t j = 0; j < n && j < set.size(); ++j) set[j] = s.channels[ch].axis_mcs[j];
    places[ch].pcs = to_pcs(frames[ch].frame, set, std::min(n, set.size()));
    places[ch].modal = frames[ch].modal;
  }
  return places;
}

nlohmann::ordered_json snapshot_json(const LiveSnapshot& s, const config::Machine& m, const prep::RunRecords& run,
                                     const ChannelFrames& frames, const LastErrors* errors) {
  return state_json(s, m, run, channel_places(s, m, frames), errors);
}

}  // namespace nck::app
