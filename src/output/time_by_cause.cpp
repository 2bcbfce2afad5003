#include "nck/output/time_by_cause.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <fmt/format.h>
#include <tuple>

#include "nck/output/block_identity.hpp"
#include "nck/output/line_ledger.hpp"
#include "nck/output/output_writers.hpp"
#include "nck/prep/units/axis_table.hpp"

namespace nck::app {
namespace {

using nlohmann::ordered_json;
using kernel::CycleCause;

// Hold kinds in Class::detail.
constexpr std::int16_t kProgramHold = 0, kFeedhold = 1;

}  // namespace

// Runs of cycles share their class: the hit moves to the front (a swap
// with the first, as a new entry does).
void CauseTally::add(CauseClass c, std::uint64_t cycles) {
  const std::size_t n = size();
  for (std::size_t i = 0; i < n; ++i)
    if (at(i).first == c) {
      at(i).second += cycles;
      if (i > 0) std::swap(at(i), at(0));
      return;
    }
  if (near_count_ < kNear) near_[near_count_++] = {c, cycles};
  else far_.emplace_back(c, cycles);
  std::swap(at(n), at(0));
}

std::uint64_t CauseTally::cycles() const {
  std::uint64_t cycles = 0;
  for (std::size_t i = 0; i < size(); ++i) cycles += (*this)[i].second;
  return cycles;
}

std::vector<CauseTally::Entry> CauseTally::sorted() const {
  std::vector<Entry> entries;
  entries.reserve(size());
  for (std::size_t i = 0; i < size(); ++i) entries.push_back((*this)[i]);
  std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.second > b.second; });
  return entries;
}

const char* cause_name(CycleCause c) {
  switch (c) {
    case CycleCause::none: return "none";
    case CycleCause::transition:  // the block change at standstill belongs to the transition
    case CycleCause::corner: return "corner";
    case CycleCause::feed: return "feed";
    case CycleCause::axis_velocity: return "axis_velocity";
    case CycleCause::accelerating:  // one class: accelerating or braking
    case CycleCause::braking: return "acceleration";
    case CycleCause::override_: return "override";
    case CycleCause::rapid: return "rapid";
    case CycleCause::wait: return "wait";
    case CycleCause::hold:
    case CycleCause::feedhold: return "hold";
    case CycleCause::starved: return "starved";
  }
  return "none";
}

void TimeByCause::start(const config::Machine& m, double cycle_s, bool by_line) {
  by_line_ = by_line;
  cycle_s_ = cycle_s;
  cycle_us_ = std::llround(cycle_s * 1e6);
  channels_.resize(m.channels.size());
  for (std::size_t c = 0; c < m.channels.size(); ++c) {
    Channel& ch = channels_[c];
    const std::size_t n = std::min(m.channels[c].axes.size(), kMaxAxes);
    const prep::AxisTable table(m, m.channels[c], n, -1, nullptr);
    for (std::size_t j = 0; j < n; ++j) {
      ch.axis_names.push_back(m.channels[c].axes[j].name);
      const motion::AxisDynamics& d = table.feed()[j];
      ch.v_max.push_back(d.v_max_mm_s);
      ch.a_acc.push_back(d.a_acc_mm_s2);
      ch.a_dec.push_back(d.a_dec_mm_s2);
    }
    ch.last_mcs.assign(n, 0.0);
    ch.c_axis = m.channels[c].c_axis;
    if (!by_line) continue;
    // room for every line kept: no rehash while they come, and a line's
    // place (ch.block) stays until the next drop
    ch.blocks.reserve(kMaxLines + 1);
    ch.block_index->reserve(kMaxLines + 1);
  }
}

namespace {
bool is_tool_change(const kernel::Event& e) {
  const auto* out = e.get<kernel::ev::PlcOut>();
  return out && out->fn == plc::TechKind::t;
}
}  // namespace

void TimeByCause::take_event(const kernel::Event& e, const RunNames& names) {
  if (e.channel == 0 || e.channel > channels_.size()) return;
  Channel& ch = channels_[e.channel - 1u];
  if (!by_line_) {  // a run still ends here: the totals take their classes in the same order
    if (e.kind() == kernel::EventKind::block || is_tool_change(e))
      flush(ch);
    return;
  }
  if (is_tool_change(e)) {
    flush(ch);
    ch.tool = fmt::format("T{}", e.get<kernel::ev::PlcOut>()->number);
    ch.tool_tally = &ch.tools[ch.tool];
    return;
  }
  if (e.kind() != kernel::EventKind::block) return;
  flush(ch);
  const auto [it, added] = ch.block_index->try_emplace(key_of(e.at.file_id, e.at.line), ch.blocks.size());
  if (added) {
    Block& fresh = ch.blocks.emplace_back();
    fresh.file = e.at.file_id;
    fresh.line = e.at.line;
    fresh.has_n = e.at.n.has_value();
    fresh.n = e.at.n.value_or(0);
  }
  Block& b = ch.blocks[it->second];
  ++b.runs;
  ch.block = &b;
  if (added && ch.blocks.size() > kMaxLines) drop_least_lost(ch);
  const std::uint16_t file = e.at.file_id;
  if (ch.file != file || !ch.file_tally) ch.file_tally = &ch.files[file];
  ch.file = file;
  if (ch.file_names.size() <= file) ch.file_names.resize(file + 1u);
  if (ch.file_names[file].empty()) ch.file_names[file] = names.file(e.channel - 1u, file);
}

void TimeByCause::flush(Channel& ch) {
  if (ch.run_cycles == 0) return;
  ch.total.add(ch.run, ch.run_cycles);
  if (by_line_) flush_lines(ch);
  ch.run_cycles = 0;
}

void TimeByCause::flush_lines(Channel& ch) {
  if (!ch.tool_tally) ch.tool_tally = &ch.tools[ch.tool];
  if (!ch.file_tally) ch.file_tally = &ch.files[ch.file];
  ch.tool_tally->add(ch.run, ch.run_cycles);
  ch.file_tally->add(ch.run, ch.run_cycles);
  if (ch.block) {
    ch.block->tally.add(ch.run, ch.run_cycles);
    ch.block->cycles += ch.run_cycles;
  }
}

void TimeByCause::finish() {
  for (Channel& ch : channels_) flush(ch);
}

double TimeByCause::lost_s(const Block& b) const { return seconds(b.cycles) - b.ideal_s; }

// Keeps the half of the lines that lost the most (and the one running).
void TimeByCause::drop_least_lost(Channel& ch) {
  std::vector<double> lost;
  lost.reserve(ch.blocks.size());
  for (const Block& b : ch.blocks) lost.push_back(lost_s(b));
  const auto keep = static_cast<std::ptrdiff_t>(kMaxLines / 2);
  std::nth_element(lost.begin(), lost.begin() + keep, lost.end(), std::greater<>());
  const double threshold = lost[static_cast<std::size_t>(keep)];
  keep_lines(
      ch.blocks, ch.block_index,
      [&](const Block& b) { return !(lost_s(b) <= threshold) || &b == ch.block; },
      [&](const Block& from, Block& to) {
        if (ch.block == &from) ch.block = &to;
      });
}

// The kernel's cause, with the axis that binds read from the set points:
// the one nearest its own limit for the distance it moved this cycle.
TimeByCause::Class TimeByCause::classify(Channel& ch, const kernel::ChannelOutput& o) const {
  Class c{o.cause, -1};
  const std::vector<double>* limit = nullptr;
  switch (o.cause) {
    case CycleCause::axis_velocity: limit = &ch.v_max; break;
    case CycleCause::accelerating: limit = &ch.a_acc; break;
    case CycleCause::braking: limit = &ch.a_dec; break;
    case CycleCause::wait: c.detail = static_cast<std::int16_t>(o.wait_reason); break;
    case CycleCause::hold: c.detail = kProgramHold; break;
    case CycleCause::feedhold: c = {CycleCause::hold, kFeedhold}; break;
    case CycleCause::transition: c.cause = CycleCause::corner; break;
    default: break;
  }
  if (o.cause == CycleCause::braking) c.cause = CycleCause::accelerating;  // one class, the axis decides
  if (!limit) return c;
  // The C axis only where no other axis moved (it turns with the spindle outside #CAX).
  for (const bool with_c : {false, true}) {
    double best = 0;
    for (std::size_t j = 0; j < ch.last_mcs.size(); ++j) {
      if (!with_c && static_cast<int>(j) == ch.c_axis) continue;
      const double l = (*limit)[j];
      const double share = std::abs(o.axis_mcs[j] - ch.last_mcs[j]) / (l > 0 ? l : 1.0);
      if (share > best) best = share, c.detail = static_cast<std::int16_t>(j);
    }
    if (c.detail >= 0) break;
  }
  return c;
}

void TimeByCause::take(const kernel::TickOutput& out, const RunNames& names) {
  for (const kernel::Event& e : out.events) take_event(e, names);
  for (std::size_t c = 0; c < channels_.size(); ++c) {
    Channel& ch = channels_[c];
    const kernel::ChannelOutput& o = out.channels[c];
    if (o.cause != CycleCause::none) {
      const Class k = classify(ch, o);
      ++ch.cycles;
      if (ch.run_cycles && !(k == ch.run)) flush(ch);
      ch.run = k;
      ++ch.run_cycles;
      if (ch.block) {
        const double moved_mm = o.path_velocity_mm_s * cycle_s_;
        ch.block->length_mm += moved_mm;
        if (o.feed_mm_s > 0) ch.block->ideal_s += ch.ideal_step_s.divide(moved_mm, o.feed_mm_s);
      }
    }
    for (std::size_t j = 0; j < ch.last_mcs.size(); ++j) ch.last_mcs[j] = o.axis_mcs[j];
  }
}

std::string TimeByCause::class_name(const Channel& ch, Class c) const {
  std::string name = cause_name(c.cause);
  if (c.detail < 0) return name;
  const auto d = static_cast<std::size_t>(c.detail);
  if (c.cause == CycleCause::wait) return name + " " + wait_reason_name(static_cast<kernel::WaitReason>(c.detail));
  if (c.cause == CycleCause::hold) return name + (c.detail == kFeedhold ? " feedhold" : " program");
  return d < ch.axis_names.size() ? name + " " + ch.axis_names[d] : name;
}

// [{"cause": "accelerating", "axis": "X", "name": "accelerating X", "time_s": .., "share": ..}, ...]
ordered_json TimeByCause::tally_json(const Channel& ch, const Tally& t) const {
  const double total = static_cast<double>(std::max<std::uint64_t>(t.cycles(), 1));
  ordered_json rows = ordered_json::array();
  for (const auto& [k, n] : t.sorted()) {
    ordered_json r{{"cause", cause_name(k.cause)}};
    const auto d = static_cast<std::size_t>(k.detail);
    if (k.cause == CycleCause::wait && k.detail >= 0)
      r["reason"] = wait_reason_name(static_cast<kernel::WaitReason>(k.detail));
    else if (k.cause == CycleCause::hold) r["reason"] = k.detail == kFeedhold ? "feedhold" : "program";
    else if (k.detail >= 0 && d < ch.axis_names.size()) r["axis"] = ch.axis_names[d];
    r["name"] = class_name(ch, k);
    r["time_s"] = written_seconds(n);
    r["share"] = written(static_cast<double>(n) / total);
    rows.push_back(std::move(r));
  }
  return rows;
}

ordered_json TimeByCause::channel_json(const Channel& ch) const {
  ordered_json tools = ordered_json::array();
  for (const auto& [tool, t] : ch.tools)
    tools.push_back({{"tool", tool}, {"time_s", written_seconds(t.cycles())}, {"causes", tally_json(ch, t)}});
  ordered_json files = ordered_json::array();
  for (const auto& [id, t] : ch.files) {
    const std::string name = id < ch.file_names.size() ? ch.file_names[id] : std::string();
    files.push_back({{"file", name}, {"main", id == 0},
                     {"time_s", written_seconds(t.cycles())}, {"causes", tally_json(ch, t)}});
  }
  return {{"time_s", written_seconds(ch.cycles)},
          {"causes", tally_json(ch, ch.total)},
          {"tools", tools},
          {"subroutines", files},
          {"blocks", blocks_json(ch)}};
}

// The blocks where the most time is lost against length / feed, each with
// its identity (block_identity.hpp) for nck diff.
ordered_json TimeByCause::blocks_json(const Channel& ch) const {
  std::vector<const Block*> blocks;
  blocks.reserve(ch.blocks.size());
  for (const Block& b : ch.blocks) blocks.push_back(&b);
  const auto lost = [&](const Block* b) { return lost_s(*b); };
  const std::size_t keep = std::min(blocks.size(), kMaxBlocks);
  std::partial_sort(blocks.begin(), blocks.begin() + static_cast<std::ptrdiff_t>(keep), blocks.end(),
                    [&](const Block* a, const Block* b) {
                      const double la = lost(a), lb = lost(b);
                      return la != lb ? la > lb : std::tie(a->file, a->line) < std::tie(b->file, b->line);
                    });
  blocks.resize(keep);
  const std::vector<BlockIdentity> ids = identities(ch, blocks);
  ordered_json rows = ordered_json::array();
  for (std::size_t i = 0; i < keep; ++i) {
    const Block& b = *blocks[i];
    const std::string file = b.file < ch.file_names.size() ? ch.file_names[b.file] : std::string();
    rows.push_back({{"file", file},
                    {"line", b.line},
                    {"n", b.has_n ? ordered_json(b.n) : ordered_json(nullptr)},
                    {"text", ids[i].text},
                    {"sub", ids[i].section},
                    {"pass", ids[i].pass},
                    {"runs", b.runs},
                    {"time_s", written_seconds(b.cycles)},
                    {"length_mm", written(b.length_mm)},
                    {"ideal_s", written(b.ideal_s)},
                    {"lost_s", written(lost(&b))},
                    {"causes", tally_json(ch, b.tally)}});
  }
  return rows;
}

// The identities of `blocks`, in their order: one pair of reads per file.
std::vector<BlockIdentity> TimeByCause::identities(const Channel& ch, const std::vector<const Block*>& blocks) const {
  std::vector<BlockIdentity> ids(blocks.size());
  std::map<std::uint16_t, std::vector<std::size_t>> by_file;
  for (std::size_t i = 0; i < blocks.size(); ++i) by_file[blocks[i]->file].push_back(i);
  for (const auto& [file, index] : by_file) {
    if (file >= ch.file_names.size() || ch.file_names[file].empty()) continue;
    std::vector<std::uint32_t> lines;
    for (std::size_t i : index) lines.push_back(blocks[i]->line);
    std::vector<BlockIdentity> found = block_identities(ch.file_names[file], lines);
    for (std::size_t k = 0; k < index.size(); ++k) ids[index[k]] = std::move(found[k]);
  }
  return ids;
}

ordered_json TimeByCause::json() const {
  ordered_json channels = ordered_json::array();
  for (std::size_t c = 0; c < channels_.size(); ++c) {
    ordered_json j{{"ch", c + 1}};
    j.update(channel_json(channels_[c]));
    channels.push_back(std::move(j));
  }
  return {{"cycle_s", cycle_s_}, {"channels", channels}};
}

std::vector<std::string> TimeByCause::top_lines(std::size_t count) const {
  struct Row {
    std::size_t ch;
    Class k;
    std::uint64_t cycles;
  };
  std::vector<Row> rows;
  for (std::size_t c = 0; c < channels_.size(); ++c)
    for (std::size_t i = 0; i < channels_[c].total.size(); ++i)
      rows.push_back({c, channels_[c].total[i].first, channels_[c].total[i].second});
  std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.cycles > b.cycles; });
  std::vector<std::string> lines;
  const bool several = channels_.size() > 1;
  for (std::size_t i = 0; i < rows.size() && i < count; ++i) {
    const Channel& ch = channels_[rows[i].ch];
    const double share = 100.0 * static_cast<double>(rows[i].cycles) / static_cast<double>(std::max<std::uint64_t>(ch.cycles, 1));
    lines.push_back(fmt::format("nck: time by cause {}: {}{} {:.3f} s ({:.1f} %)", i + 1,
                                several ? fmt::format("channel {} ", rows[i].ch + 1) : std::string(),
                                class_name(ch, rows[i].k), seconds(rows[i].cycles), share));
  }
  return lines;
}

}  // namespace nck::app
