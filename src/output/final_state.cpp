// --final: the state at the end of the run as one JSON document (README;
// additions in docs/outputs.md).
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "nck/distctrl/controller.hpp"
#include "nck/output/diagnostic_json.hpp"
#include "nck/output/machine_names.hpp"
#include "nck/output/output_writers.hpp"
#include "nck/spindle/spindle_status.hpp"

#include "nck/core/shown_number.hpp"
#include "nck/core/utf8.hpp"
#include "nck/core/version.hpp"

namespace nck::app {
namespace {

using nlohmann::json;

// The D in force and the radius tool radius compensation takes from it.
json tool_json(const config::Machine& m, std::size_t channel, std::int64_t d) {
  double radius_mm = 0;
  if (channel < m.channel_data.size() && d > 0 && static_cast<std::size_t>(d) < m.channel_data[channel].tools.size())
    radius_mm = m.channel_data[channel].tools[static_cast<std::size_t>(d)].radius_mm;
  return json{{"d", d}, {"radius_mm", written(radius_mm)}};
}

}  // namespace

std::string motion_name(nc::Motion m) {
  switch (m) {
    case nc::Motion::rapid: return "G0";
    case nc::Motion::linear: return "G1";
    case nc::Motion::cw: return "G2";
    case nc::Motion::ccw: return "G3";
    case nc::Motion::thread: return "G33";
    case nc::Motion::tap: return "G63";
    case nc::Motion::tap_rigid: return "G331";
    case nc::Motion::tap_retract: return "G332";
  }
  return "G0";
}

nlohmann::json modal_json(const nc::ModalState& m) {
  return json{{"motion", motion_name(m.motion)},
              {"plane", fmt::format("G{}", static_cast<int>(m.plane))},
              {"distance", m.absolute ? "G90" : "G91"},
              {"feed_mode", fmt::format("G{}", static_cast<int>(m.feed_mode))},
              {"speed_mode", fmt::format("G{}", static_cast<int>(m.speed_mode))},
              {"radius_comp", fmt::format("G{}", static_cast<int>(m.radius_comp))},
              {"units", m.inch ? "G70" : "G71"},
              {"diameter", m.diameter ? "G51" : "G52"},
              {"exact_stop", m.exact_stop ? "G360" : "G359"},
              {"zero_offset", m.zero_offset == 0 ? std::string("G53")
                              : m.zero_offset <= 6 ? fmt::format("G{}", 53 + m.zero_offset)
                                                   : fmt::format("G159={}", m.zero_offset)},
              {"F", m.feed_mm_min}};
}

std::optional<std::string> write_final(const std::string& path, const config::Machine& m,
                                       const sim::DryRun& run, double time_s, const std::string& end_reason,
                                       const std::vector<FinalError>& errors,
                                       const nlohmann::ordered_json& time_by_cause) {
  OutputFile f;
  if (auto err = f.open(path)) return err;
  f.write(dump_json(final_json(m, run, time_s, end_reason, errors, time_by_cause), 2));
  f.write("\n");
  return f.commit();
}

nlohmann::ordered_json final_error_json(const FinalError& e, Severity severity) {
  nlohmann::ordered_json j{{"id", e.id}, {"ch", e.channel}, {"line", e.line}, {"file", to_utf8(e.file)}, {"msg", to_utf8(e.msg)}};
  add_diagnostic_fields(j, diagnostic_json(static_cast<ErrorId>(e.id), e.msg, SourceLoc{e.file, e.line, 0}, e.channel, severity));
  return j;
}

nlohmann::json final_json(const config::Machine& m, const sim::DryRun& run, double time_s,
                          const std::string& end_reason, const std::vector<FinalError>& errors,
                          const nlohmann::ordered_json& time_by_cause) {
  const kernel::Kernel& k = run.kernel();
  json channels = json::array();
  for (std::size_t c = 0; c < m.channels.size() && c < k.channel_count(); ++c) {
    const sim::ChannelSnapshot s = run.snapshot(c);
    const kernel::ChannelState homing = k.channel_state(c);
    json axes = json::object();
    for (std::size_t j = 0; j < m.channels[c].axes.size(); ++j) {
      json axis{{"mcs", written(s.axis_mcs[j])}, {"pcs", written(s.axis_pcs[j])}};
      // Homing only where the machine data require it (P-AXIS-00277): other
      // machines' final states stay as they were.
      if (homing.homing_required != 0) axis["homed"] = (homing.homed_axes >> j & 1u) != 0;
      // A face-turning axis also as the diameter G51 programs (the trace stays radius).
      const int list = m.channels[c].axes[j].axis_index;
      if (list >= 0 && m.axes[static_cast<std::size_t>(list)].is_face_turning())
        axis["pcs_diameter"] = written(2 * s.axis_pcs[j]);
      axes[m.channels[c].axes[j].name] = axis;
    }
    json offsets = json::object();
    for (const auto& [kind, values] : s.offsets) {
      json v = json::object();
      for (const auto& [axis, value] : values) v[axis] = written(value);
      offsets[kind] = v;
    }
    channels.push_back(json{{"axes", axes},
                            {"modal", modal_json(s.modal)},
                            {"offsets", offsets},
                            {"main_spindle", main_spindle_designation(m.channels[c])},
                            {"trc", fmt::format("G{}", static_cast<int>(s.modal.radius_comp))},
                            {"tool", tool_json(m, c, s.modal.d)}});
    if (m.channels[c].dist_ctrl_enabled()) {  // 3D distance control: its state and offset at the end
      const kernel::ChannelState st = k.channel_state(c);
      channels.back()["dist_ctrl"] = json{
          {"state", distctrl::state_name(st.dist_state)},
          {"offset", written(st.dist_offset_mm)}};
    }
  }
  json spindles = json::object();
  for (std::size_t i = 0; i < k.spindle_count(); ++i) {
    const spindle::SpindleStatus& st = k.spindle_status(i);
    spindles[k.spindle_name(i)] = json{{"rpm", written(st.set_rpm)},
                                       {"pos", written(st.set_pos_deg)},
                                       {"act_rpm", written(st.act_rpm)},
                                       {"mode", std::string(spindle::mode_name(st.mode))},
                                       {"gear", st.gear_stage},
                                       {"homed", st.homed}};
  }
  // The spindles' HLI status objects, positions in the format P-STUP-00175 selects.
  const plc::HliImage& h = run.machine().hli();
  const plc::PositionFormat fmt_pos = plc::position_format(h.ads_32_bit_comp_mode);
  json hli_spindles = json::object();
  for (std::size_t i = 0; i < k.spindle_count(); ++i) {
    const plc::SpindleStatus st = k.hli_spindle_status(i);
    // Named as the TF5200 HLI paths; the objects whose paths nck does not
    // know keep the seed's words (FCT-S1 2.9) in snake case.
    hli_spindles[k.spindle_name(i)] =
        json{{"mode_r", st.mode_bits},
             {"active_rev_r", plc::to_hli_speed(st.nominal_rpm)},
             {"current_rev_r", plc::to_hli_speed(st.actual_rpm)},
             {"cmd_rev_r", plc::to_hli_speed(st.programmed_rpm)},
             {"rev_control_aktiv_r", st.speed_monitoring_active},
             {"rev_erreicht_r", st.speed_reached},
             {"rev_null_r", st.stopped},
             {"speed_monitoring_invalid", st.monitoring_invalid},
             {"target_pos", plc::encode_position(st.target_pos_deg, fmt_pos).raw},
             {"actual_pos", plc::encode_position(st.actual_pos_deg, fmt_pos).raw},
             {"distance_to_go", plc::encode_position(st.distance_to_go_deg, fmt_pos).raw},
             {"command_error", st.job_error}};
  }
  // Each channel's state as the PLC reads it (nck 0.2, docs/outputs.md).
  json hli_channels = json::array();
  for (std::size_t c = 0; c < k.channel_count(); ++c) {
    const plc::ChannelState& cs = h.channel_state[c];
    hli_channels.push_back(
        json{{"program_state", kernel::state_name(static_cast<kernel::ProgramState>(cs.program_state))},
             {"block_search_state_r", static_cast<int>(cs.block_search)},
             {"block_search_active_r", cs.block_search_active()}});
  }
  json hli{{"position_format", fmt_pos == plc::PositionFormat::scaled_32bit ? "32-bit, 0.0001 deg"
                                                                             : "64-bit, 1e-7 deg"},
           {"spindles", hli_spindles},
           {"channels", hli_channels}};
  // enabled coupling groups (synchronous operation): channel, group, pairs
  json links = json::array();
  for (std::size_t c = 0; c < k.channel_count(); ++c)
    for (std::uint32_t payload : k.active_links(c)) {
      const prep::LinkPayload& p = run.link(payload);
      json pairs = json::array();
      for (const auto& [slave, master] : p.pairs) pairs.push_back(json::array({slave, master}));
      links.push_back(json{{"ch", c + 1}, {"group", p.group}, {"pairs", pairs}});
    }
  json errs = json::array();
  for (const FinalError& e : errors)
    errs.push_back(json(final_error_json(e)));
  // "format": 2 since nck 0.2 (docs/outputs.md); every earlier field stays as it was
  json doc{{"format", 2},
           {"time", time_s},
           {"end", end_reason},
           {"channels", channels},
           {"spindles", spindles},
           {"links", links},
           {"hli", hli},
           {"errors", errs}};
  doc["nck"] = std::string(version());  // the build that wrote it (nck 0.3; docs/outputs.md)
  // nck 0.3: where the time went (docs/outputs.md), kept in its own order
  doc["time_by_cause"] = json::parse(time_by_cause.dump(-1, ' ', false, json::error_handler_t::replace));
  return doc;
}

}  // namespace nck::app
