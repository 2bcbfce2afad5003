#include "nck/report/report_writer.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <nlohmann/json.hpp>

#include "nck/output/line_ledger.hpp"
#include "nck/output/machine_names.hpp"
#include "nck/output/output_writers.hpp"
#include "nck/output/time_by_cause.hpp"
#include "nck/report/backplot_axes.hpp"
#include "nck/sim/dry_run.hpp"
#include "nck/spindle/spindle_status.hpp"

namespace nck::app {
namespace {

// The G words of one NC line that the backplot needs: motion G0..G3 and
// plane G17..G19 (comments in parentheses and after ';' skipped). The
// report reads the program text for this because events do not carry the
// motion type; blocks are scanned in execution order, so jumps and loops
// keep the modal state right.
void scan_g_words(const std::string& text, int& motion, int& plane) {
  int depth = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == ';') return;
    if (c == '(') ++depth;
    if (c == ')' && depth > 0) --depth;
    if (depth > 0 || (c != 'G' && c != 'g')) continue;
    const char before = i > 0 ? text[i - 1] : ' ';
    if (std::isalnum(static_cast<unsigned char>(before)) || before == '_' || before == '$' || before == '#') continue;
    std::size_t j = i + 1;
    int number = 0, digits = 0;
    while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j])) && digits < 4) {
      number = number * 10 + (text[j] - '0');
      ++j;
      ++digits;
    }
    if (digits == 0 || (j < text.size() && (text[j] == '.' || std::isdigit(static_cast<unsigned char>(text[j])))))
      continue;
    if (number <= 3) motion = number;
    if (number >= 17 && number <= 19) plane = number;
  }
}
}  // namespace

void ReportWriter::start(const config::Machine& m, const ReportInputs& inputs, sim::DryRun& run) {
  enabled_ = true;
  blocks_.reserve(kMaxBlockLines + 1);
  block_index_->reserve(kMaxBlockLines + 1);
  const kernel::Kernel& k = run.kernel();
  const double cycle_s = k.cycle_time_s();
  cycle_s_ = cycle_s;
  machine_ = inputs.machine;
  plc_ = inputs.plc;
  programs_ = inputs.programs;
  const std::vector<std::string> columns = path_axis_columns(m);
  std::size_t col = 0;
  plots_ = std::make_unique<ReportPlots>(m.channels.size());
  for (std::size_t c = 0; c < m.channels.size(); ++c) {
    Channel ch;
    const auto& axes = m.channels[c].axes;
    ch.axis = backplot_axes(m.channels[c]);
    for (int a = 0; a < 3; ++a)
      if (ch.axis[a] >= 0) ch.axis_name[a] = columns[col + static_cast<std::size_t>(ch.axis[a])];
    const std::string ch_name = fmt::format("channel {}", c + 1);
    series_meta_.push_back(fmt::format(R"({{"name":{},"unit":"mm/min","panel":{},"kind":"velocity","ch":{}}})",
                                       json_quoted(fmt::format("{}path velocity", c > 0 ? fmt::format("{}.", c + 1) : "")),
                                       json_quoted(ch_name + ": path velocity"), c + 1));
    decimals_.push_back(1);
    plots_->channel(c).velocity_column = series_meta_.size() - 1;
    plots_->channel(c).path_deriv = PathDerivatives(cycle_s);
    add_path_derivative_series(c);
    for (std::size_t j = 0; j < axes.size(); ++j) {
      const bool rot = is_rotary_name(axes[j].name);
      // the C axis of #CAX follows the spindle while it turns: plotted only when #CAX was used
      const bool c_axis = static_cast<int>(j) == m.channels[c].c_axis;
      series_meta_.push_back(fmt::format(R"({{"name":{},"unit":"{}","kind":"{}","panel":{},"ch":{}}})",
                                         json_quoted(columns[col + j]), rot ? "deg" : "mm", c_axis ? "c_axis" : "axis",
                                         json_quoted(ch_name + (rot ? ": rotary axes" : ": axis positions (MCS)")), c + 1));
      decimals_.push_back(4);
    }
    col += axes.size();
    ch.axis_count = axes.size();
    ch.limits = backplot_limits(m, m.channels[c], ch.axis);
    for (int a = 0; a < 3 && m.channels[c].display_diameter_pos; ++a) {
      const int j = ch.axis[a];
      const int idx = j < 0 ? -1 : axes[static_cast<std::size_t>(j)].axis_index;
      if (idx >= 0 && m.axes[static_cast<std::size_t>(idx)].is_face_turning()) ch.diameter_slot = a;
    }
    if (c < k.channel_count()) {  // the path starts where the axes stand
      const kernel::ChannelState st = k.channel_state(c);
      std::array<double, 3> p{};
      for (int a = 0; a < 3; ++a)
        if (ch.axis[a] >= 0) p[a] = st.axis_mcs[static_cast<std::size_t>(ch.axis[a])];
      plots_->channel(c).path.add({.pos = p});
    }
    if (c < run.channel_count()) {
      ch.contour = std::make_unique<ProgrammedContour>(ch.axis);
      run.observe(c, ch.contour.get());
    }
    channels_.push_back(std::move(ch));
  }
  const std::vector<SpindleName> spindles = machine_spindles(m);
  for (std::size_t s = 0; s < spindles.size(); ++s) {
    spindles_.push_back(spindles[s].name);
    spindle_override_pct_.push_back(100);
    spindle_hold_.emplace_back();
    const std::string panel = json_quoted(fmt::format("spindle {}: speed", spindles[s].name));
    series_meta_.push_back(fmt::format(R"({{"name":{},"unit":"rpm","panel":{},"kind":"set_rpm","spindle":{}}})",
                                       json_quoted(spindles[s].name + " set"), panel, s));
    series_meta_.push_back(fmt::format(R"({{"name":{},"unit":"rpm","panel":{},"kind":"act_rpm","spindle":{}}})",
                                       json_quoted(spindles[s].name + " actual"), panel, s));
    decimals_.push_back(2);
    decimals_.push_back(2);
  }
  for (std::size_t c = 0; c < m.channels.size(); ++c) {  // 3D distance control: sensor, offset, error
    if (!m.channels[c].dist_ctrl_enabled()) continue;
    dist_channels_.push_back(c);
    const std::string panel = json_quoted(fmt::format("channel {}: distance control", c + 1));
    for (const char* n : {"dist.sensor", "dist.offset", "dist.error"}) {
      series_meta_.push_back(fmt::format(R"({{"name":{},"unit":"mm","panel":{},"kind":"dist"}})", json_quoted(n), panel));
      decimals_.push_back(4);
    }
  }
  plots_->start(series_meta_.size(), cycle_s);
}

// Channel c's path acceleration and jerk (trace_columns.hpp's names): one
// panel, a scale per unit.
void ReportWriter::add_path_derivative_series(std::size_t c) {
  const std::string prefix = c > 0 ? fmt::format("{}.", c + 1) : std::string();
  const std::string panel = json_quoted(fmt::format("channel {}: path acceleration and jerk", c + 1));
  series_meta_.push_back(fmt::format(R"({{"name":{},"unit":"mm/s²","panel":{},"kind":"path_a","ch":{}}})",
                                     json_quoted(prefix + "path.a"), panel, c + 1));
  decimals_.push_back(1);
  series_meta_.push_back(fmt::format(R"({{"name":{},"unit":"mm/s³","panel":{},"kind":"path_j","ch":{}}})",
                                     json_quoted(prefix + "path.j"), panel, c + 1));
  decimals_.push_back(0);
}

std::uint16_t ReportWriter::file_index(const std::string& name) {
  if (auto it = file_ids_.find(name); it != file_ids_.end()) return it->second;
  const auto id = static_cast<std::uint16_t>(files_.size());
  files_.emplace_back(name);
  file_ids_.emplace(name, id);
  return id;
}

// The report's index of a program file, remembered per decoder file id (a
// block event names its file by that id: looked up by name once per file).
std::uint16_t ReportWriter::file_of(Channel& ch, std::size_t c, std::uint16_t id, const RunNames& names) {
  if (id < ch.file_of_id.size() && ch.file_of_id[id] != kNoFile) return ch.file_of_id[id];
  const std::uint16_t index = file_index(names.file(c, id));
  if (ch.file_of_id.size() <= id) ch.file_of_id.resize(id + 1u, kNoFile);
  ch.file_of_id[id] = index;
  return index;
}

const std::string& ReportWriter::line_text(std::uint16_t file, std::uint32_t line) const {
  static const std::string none;
  if (file >= files_.size()) return none;
  // A program may call thousands of subroutine files: few stay open at a time.
  constexpr std::size_t kMaxOpenFiles = 16;
  if (!files_[file].is_open() && ++open_files_ > kMaxOpenFiles) {
    for (SourceLines& f : files_) f.close();
    open_files_ = 1;
  }
  return files_[file].line(line);
}

void ReportWriter::take(const kernel::Event& e, const RunNames& names) {
  if (e.channel == 0 || e.channel > channels_.size()) return;
  const std::size_t c = e.channel - 1u;
  Channel& ch = channels_[c];
  auto spindle_name = [&](std::optional<std::int8_t> s) {
    const nlohmann::ordered_json j = names.spindle(s);
    return j.is_string() ? j.get<std::string>() : std::string();
  };
  if (e.get<kernel::ev::Block>()) take_block(ch, c, e, names);
  else if (const auto* out = e.get<kernel::ev::PlcOut>()) take_output(ch, c, *out);
  else if (const auto* w = e.get<kernel::ev::Wait>()) take_wait(ch, c, e, *w, spindle_name(w->spindle));
  else if (const auto* end = e.get<kernel::ev::WaitEnd>()) end_wait(ch, e.t_s, *end, spindle_name(end->spindle));
  else if (const auto* s = e.get<spindle::ModeEvent>(); s && s->mode == spindle::SpindleMode::axis) c_axis_used_ = true;
}

void ReportWriter::take_block(Channel& ch, std::size_t c, const kernel::Event& e, const RunNames& names) {
  ch.file = file_of(ch, c, e.at.file_id, names);
  ch.line = e.at.line;
  if (const auto frame = e.get<kernel::ev::Block>()->frame_index) take_frame(ch, *frame, names);
  scan_g_words(line_text(ch.file, ch.line), ch.motion, ch.plane);
  const BlockKey key{c, ch.file, ch.line};
  const auto [it, added] = block_index_->try_emplace(packed(key), blocks_.size());
  if (added) blocks_.emplace_back(key, Accum{});
  ch.block = &blocks_[it->second].second;
  ++ch.block->count;
  block_lines_ += added;
  if (blocks_.size() > kMaxBlockLines) drop_shortest_blocks();
}

void ReportWriter::take_output(Channel& ch, std::size_t c, const kernel::ev::PlcOut& out) {
  const std::string fn = plc::function_name(out.fn, out.number);
  ch.last_sync[fn] = out.sync;
  if (out.fn == plc::TechKind::t) {
    ch.tool = fn;
    ch.tool_acc = &tools_[{c, ch.tool}];
    ++ch.tool_acc->count;
  }
}

void ReportWriter::take_wait(Channel& ch, std::size_t c, const kernel::Event& e, const kernel::ev::Wait& wait,
                             const std::string& spindle) {
  Wait w{c + 1, e.t_s, -1, wait_reason_name(wait.reason), plc::function_name(wait.fn, wait.number),
         spindle, "", e.at.line ? e.at.line : ch.line, ch.file};
  if (auto it = ch.last_sync.find(w.fn); it != ch.last_sync.end() && !w.fn.empty()) w.sync = sync_name(it->second);
  if (waits_.size() >= kMaxListed) return;
  ch.open_waits.push_back(waits_.size());
  waits_.push_back(std::move(w));
}

// Ends the wait for the same spindle, function and reason.
void ReportWriter::end_wait(Channel& ch, double t_s, const kernel::ev::Wait& wait, const std::string& spindle) {
  const std::string reason = wait_reason_name(wait.reason);
  const std::string fn = plc::function_name(wait.fn, wait.number);
  const auto it = std::find_if(ch.open_waits.begin(), ch.open_waits.end(), [&](std::size_t i) {
    const Wait& w = waits_[i];
    return w.reason == reason && w.fn == fn && w.spindle == spindle;
  });
  if (it == ch.open_waits.end()) return;
  waits_[*it].t1 = t_s;
  ch.open_waits.erase(it);
}

// Keeps the half of the lines with the most time (and the lines the
// channels are in): the table shows the longest 300, memory stays bounded.
void ReportWriter::drop_shortest_blocks() {
  std::vector<double> times;
  times.reserve(blocks_.size());
  for (const auto& [key, acc] : blocks_) times.push_back(acc.time_s);
  const auto keep = static_cast<std::ptrdiff_t>(kMaxBlockLines / 2);
  std::nth_element(times.begin(), times.begin() + keep, times.end(), std::greater<>());
  const double threshold = times[static_cast<std::size_t>(keep)];
  auto in_use = [&](const Accum* a) {
    for (const Channel& ch : channels_)
      if (ch.block == a) return true;
    return false;
  };
  keep_lines(
      blocks_, block_index_,
      [&](const std::pair<BlockKey, Accum>& line) { return !(line.second.time_s <= threshold) || in_use(&line.second); },
      [&](const std::pair<BlockKey, Accum>& from, std::pair<BlockKey, Accum>& to) {
        for (Channel& ch : channels_)
          if (ch.block == &from.second) ch.block = &to.second;
      });
}

void ReportWriter::set_ghost(const nlohmann::ordered_json& ghost) {
  if (enabled_) ghost_json_ = dump_json(ghost);
}

void ReportWriter::set_causes(const nlohmann::ordered_json& causes) {
  if (!enabled_ || !causes.contains("channels")) return;
  nlohmann::ordered_json page = causes;
  // The page keeps per block what its table shows (up to 2,000 rows stay small).
  for (auto& ch : page["channels"])
    for (auto& b : ch["blocks"]) {
      const std::uint16_t fid = file_index(b["file"].get<std::string>());
      cause_lines_.emplace_back(fid, b["line"].get<std::uint32_t>());
      const std::string main = b["causes"].empty() ? std::string() : b["causes"][0]["name"].get<std::string>();
      b = nlohmann::ordered_json{{"fid", fid},         {"line", b["line"]},       {"runs", b["runs"]},
                                 {"time_s", b["time_s"]}, {"ideal_s", b["ideal_s"]}, {"lost_s", b["lost_s"]},
                                 {"cause", main}};
    }
  causes_json_ = dump_json(page);
}

void ReportWriter::add_mark(Mark m) {
  if (marks_.size() < kMaxListed) marks_.push_back(std::move(m));
}

// A cycle is recorded as it comes (what it counts towards, after its own
// events, and its plot values); ReportPlots folds the batches into the
// plots on its own thread.
void ReportWriter::sample(std::uint64_t cycle, const kernel::TickOutput& out, const RunNames& names,
                          const plc::HliImage& hli) {
  if (!enabled_) return;
  for (const kernel::Event& e : out.events) {
    take(e, names);
    mark_spindle(e);
  }
  watch_plc(out.t_s, hli);
  record(cycle, out);
}

// A spindle's gear change, speed reached and programmed S as marks on its plot.
void ReportWriter::mark_spindle(const kernel::Event& e) {
  auto index = [&](std::int8_t s) { return s >= 0 && static_cast<std::size_t>(s) < spindles_.size(); };
  if (const auto* g = e.get<spindle::GearEvent>(); g && index(g->spindle))
    add_mark({e.t_s, static_cast<std::size_t>(g->spindle), 0, "gear", fmt::format("M{} gear stage {}", g->m, g->stage)});
  else if (const auto* r = e.get<spindle::SpeedReachedEvent>(); r && index(r->spindle))
    add_mark({e.t_s, static_cast<std::size_t>(r->spindle), 0, "speed_reached",
              fmt::format("speed reached {:g} rpm", r->act_rpm)});
  else if (const auto* o = e.get<kernel::ev::PlcOut>(); o && o->fn == plc::TechKind::s && o->spindle && index(*o->spindle))
    add_mark({e.t_s, static_cast<std::size_t>(*o->spindle), 0, "s", fmt::format("S {:g} rpm programmed", o->s_rpm)});
}

void ReportWriter::record(std::uint64_t cycle, const kernel::TickOutput& out) {
  ReportBatch& batch = plots_->batch();
  const std::size_t i = batch.add(cycle, out.t_s);
  double* row = batch.row(i);
  std::size_t k = 0;
  for (std::size_t c = 0; c < channels_.size(); ++c) {
    Channel& ch = channels_[c];
    const kernel::ChannelOutput& o = out.channels[c];
    if (o.status == kernel::ChannelStatus::running || o.status == kernel::ChannelStatus::waiting) {
      if (ch.block) ch.block->time_s += cycle_s_;  // the cycle counts towards its block and tool
      if (!ch.tool_acc) ch.tool_acc = &tools_[{c, ch.tool}];
      ch.tool_acc->time_s += cycle_s_;
    }
    ReportBatch::ChannelSample& pc = batch.channel(i, c);
    for (int a = 0; a < 3; ++a) pc.pos[a] = ch.axis[a] >= 0 ? o.axis_mcs[static_cast<std::size_t>(ch.axis[a])] : 0.0;
    pc.line = ch.line;
    pc.frame = ch.frame;
    pc.file = ch.file;
    pc.rapid = ch.motion == 0;
    pc.cause = o.cause;
    pc.wait_reason = o.wait_reason;
    pc.path_velocity_mm_s = o.path_velocity_mm_s;
    row[k] = o.path_velocity_mm_s * 60.0;
    k += 3;  // path.a and path.j: the folding thread's
    for (std::size_t j = 0; j < ch.axis_count; ++j) row[k++] = o.axis_mcs[j];
  }
  for (std::size_t s = 0; s < spindles_.size(); ++s) {
    row[k++] = out.spindles[s].set_rpm;
    row[k++] = out.spindles[s].act_rpm;
  }
  for (std::size_t c : dist_channels_) {
    row[k++] = out.channels[c].dist_sensor_mm;
    row[k++] = out.channels[c].dist_offset_mm;
    row[k++] = out.channels[c].dist_error_mm;
  }
  if (batch.full()) plots_->publish();
}

// A block's map (the PlanStore index in its block event): a new entry in the
// channel's list when it differs from the one before.
void ReportWriter::take_frame(Channel& ch, std::uint32_t store_index, const RunNames& names) {
  if (store_index == ch.store_frame || !names.run) return;
  const kernel::AffineMap* map = names.run->frame(store_index);
  if (!map) return;
  ch.store_frame = store_index;
  const nc::ModalState* modal = names.run->modal(store_index);
  const Frame f{*map, modal && modal->diameter ? ch.diameter_slot : -1};
  // a map seen before keeps its index (a program switching between G54 and
  // G55 a million times still has two); beyond kMaxFrames the last one stays
  for (std::size_t i = 0; i < ch.frames.size(); ++i)
    if (ch.frames[i] == f) {
      ch.frame = static_cast<std::uint32_t>(i);
      return;
    }
  if (ch.frames.size() >= kMaxFrames) return;
  ch.frames.push_back(f);
  ch.frame = static_cast<std::uint32_t>(ch.frames.size() - 1);
}

// The PLC's overrides and feedholds as the cycle just computed used them
// (the simulated HLI image): each change a mark, each feedhold a shaded span.
void ReportWriter::watch_plc(double t_s, const plc::HliImage& hli) {
  // make_wait: called only when a hold starts (a Wait holds strings: not built every cycle)
  auto hold = [&](bool on, std::optional<std::size_t>& open, const auto& make_wait) {
    if (on && !open && waits_.size() < kMaxListed) {
      open = waits_.size();
      waits_.push_back(make_wait());
    } else if (!on && open) {
      waits_[*open].t1 = t_s;
      open.reset();
    }
  };
  for (std::size_t c = 0; c < channels_.size() && c < hli.channel.size(); ++c) {
    Channel& ch = channels_[c];
    const double ovr = hli.channel[c].feed_override_percent;
    if (ovr == ch.feed_override_pct && hli.channel[c].feedhold == ch.hold.has_value()) continue;  // most cycles
    if (ovr != ch.feed_override_pct)
      add_mark({t_s, 0, c + 1, "override", fmt::format("feed override {:g} %", ovr)});
    ch.feed_override_pct = ovr;
    hold(hli.channel[c].feedhold, ch.hold, [&] { return Wait{c + 1, t_s, -1, "feedhold", "", "", "", ch.line, ch.file}; });
  }
  for (std::size_t s = 0; s < spindles_.size() && s < hli.spindle_control.size(); ++s) {
    const double ovr = hli.spindle_control[s].effective_override_percent();
    if (ovr == spindle_override_pct_[s] && hli.spindle_control[s].feedhold == spindle_hold_[s].has_value()) continue;
    if (ovr != spindle_override_pct_[s])
      add_mark({t_s, s, 0, "override", fmt::format("spindle override {:g} %", ovr)});
    spindle_override_pct_[s] = ovr;
    hold(hli.spindle_control[s].feedhold, spindle_hold_[s],
         [&] { return Wait{0, t_s, -1, "feedhold", "", spindles_[s], "", 0, 0}; });
  }
}

void ReportWriter::event(const kernel::Event& e, const std::string& json_line, const RunNames& names) {
  if (!enabled_) return;
  if (const auto* link = e.get<kernel::LinkEvent>()) note_link(e, *link, names);
  const bool block = e.kind() == kernel::EventKind::block;
  if (block ? table_blocks_++ < kMaxTableBlocks : events_.size() - std::min(table_blocks_, kMaxTableBlocks) < kMaxTableEvents)
    events_.push_back(json_line);
  else
    ++events_dropped_;
  if (block) return;
  const bool error = e.kind() == kernel::EventKind::error;
  if (error || e.kind() == kernel::EventKind::warning) {
    if (diagnostics_.size() < kMaxListed) diagnostics_.push_back(json_line);
    ++(error ? errors_ : warnings_);
    file_index(names.file(e.channel_index(), e.at.file_id));
  }
  if (const auto* end = e.get<kernel::ev::End>()) {
    const std::string r = kernel::end_name(end->reason);
    if (end_reason_.find(r) == std::string::npos) end_reason_ += (end_reason_.empty() ? "" : ", ") + r;
  }
}

}  // namespace nck::app
