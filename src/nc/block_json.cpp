#include "nck/nc/block_json.hpp"

#include <fmt/format.h>

namespace nck::nc {

namespace {

using nlohmann::json;

const char* motion_name(Motion m) {
  static constexpr const char* n[] = {"G0", "G1", "G2", "G3", "G33", "G63", "G331", "G332"};
  return n[static_cast<int>(m)];
}

template <class T>
void put(json& j, const char* key, const std::optional<T>& v) {
  if (v) j[key] = *v;
}

struct HashJson {
  json j;
  void operator()(const SetAxLink& s) {
    j["group"] = s.group;
    j["by_number"] = s.by_number;
    json pairs = json::array();
    for (const auto& p : s.pairs) {
      json q{{"slave", p.slave}, {"master", p.master}};
      if (p.gantry) q["gantry"] = true;
      put(q, "limit1_mm", p.limit1_mm);
      put(q, "limit2_mm", p.limit2_mm);
      put(q, "numerator", p.numerator);
      put(q, "denominator", p.denominator);
      pairs.push_back(q);
    }
    j["pairs"] = pairs;
  }
  void operator()(const EnableAxLink& e) { put(j, "group", e.group); }
  void operator()(const DisableAxLink& e) { put(j, "group", e.group); j["all"] = e.all; }
  void operator()(const MainSpindle& m) { put(j, "spindle", m.name); put(j, "log_axis_nr", m.log_axis_nr); }
  void operator()(const CAxis& c) { j["on"] = c.on; j["spindle"] = c.spindle; j["axis"] = c.axis; }
  void operator()(const Face& c) { j["on"] = c.on; j["axes"] = {c.axis1, c.axis2}; }
  void operator()(const Cylinder& c) {
    j["on"] = c.on;
    j["axes"] = {c.axis1, c.axis2, c.axis3};
    j["radius_mm"] = c.radius_mm;
  }
  void operator()(const ExplSyn&) {}
  void operator()(const ToolData& t) {
    j["fields"] = json::array();
    for (int i = 0; i < t.count; ++i) j["fields"].push_back(t.fields[i]);
  }
  void operator()(const CoordSystem& c) {
    put(j, "id", c.id);
    if (!c.name.empty()) j["name"] = c.name;
    if (c.has_values) j["values"] = c.values;
    if (!c.mode_option.empty()) j["mode_option"] = c.mode_option;
  }
  void operator()(const Ecs& c) { j["on"] = c.on; }
  void operator()(const Mcs& c) { j["on"] = c.on; j["ex_tool"] = c.ex_tool; }
  void operator()(const Rotation& r) {
    j["on"] = r.on;
    put(j, "angle_deg", r.angle_deg);
    put(j, "center1_mm", r.center1_mm);
    put(j, "center2_mm", r.center2_mm);
  }
  void operator()(const PSet& p) {
    j["axes"] = json::object();
    for (auto [a, v] : p.axes) j["axes"][std::to_string(a)] = v;
  }
  void operator()(const PReset& p) { j["axes"] = p.axes; }
  void operator()(const Tlc& t) { j["on"] = t.on; j["delta_mm"] = t.delta_mm; }
  void operator()(const SuppressOffsets& s) {
    j["all"] = s.all;
    json k = json::array();
    if (s.zero) k.push_back("ZERO");
    if (s.add_zero) k.push_back("ADD_ZERO");
    if (s.pset) k.push_back("PSET");
    if (s.clamp) k.push_back("CLAMP");
    if (s.tool) k.push_back("TOOL");
    if (s.measure) k.push_back("MEASURE");
    if (s.manual) k.push_back("MANUAL");
    j["kinds"] = k;
  }
  void operator()(const GetManualOffsets&) {}
  // a technology's command: its write_json, beside its syntax
  template <class Command>
  void operator()(const Command& c) {
    write_json(j, c);
  }
};

}  // namespace

json to_json(const ModalState& m) {
  return json{{"motion", motion_name(m.motion)},
              {"plane", fmt::format("G{}", static_cast<int>(m.plane))},
              {"absolute", m.absolute},
              {"feed_mode", fmt::format("G{}", static_cast<int>(m.feed_mode))},
              {"speed_mode", fmt::format("G{}", static_cast<int>(m.speed_mode))},
              {"radius_comp", fmt::format("G{}", static_cast<int>(m.radius_comp))},
              {"diameter", m.diameter},
              {"inch", m.inch},
              {"zero_offset", m.zero_offset},
              {"feed_mm_min", m.feed_mm_min},
              {"feed_mm_rev", m.feed_mm_rev},
              {"css_m_min", m.css_m_min},
              {"max_speed_rpm", m.max_speed_rpm},
              {"thread_pitch_mm", m.thread_pitch_mm},
              {"d", m.d}};
}

json to_json(const SpindleCommand& s) {
  json j{{"name", s.name}, {"target", s.target}, {"din", s.din}};
  if (s.m != SpindleM::none) j["m"] = fmt::format("M{}", static_cast<int>(s.m));
  if (s.direction != SpindleM::none) j["direction"] = fmt::format("M{}", static_cast<int>(s.direction));
  put(j, "rev_rpm", s.rev_rpm);
  put(j, "pos_deg", s.pos_deg);
  put(j, "pos_shift_deg", s.pos_shift_deg);
  put(j, "offset_deg", s.offset_deg);
  put(j, "gear_stage", s.gear_stage);
  put(j, "g112_stage", s.g112_stage);
  if (!s.user_m.empty()) j["user_m"] = s.user_m;
  if (!s.user_h.empty()) j["user_h"] = s.user_h;
  if (s.g74) j["g74"] = true;
  if (s.g167) j["g167"] = true;
  put(j, "g130_pct", s.g130_pct);
  if (s.g135) j["g135"] = true;
  if (s.g137) j["g137"] = true;
  put(j, "g136_pct", s.g136_pct);
  if (s.callax) j["callax"] = true;
  if (s.putax) j["putax"] = true;
  if (s.get_dynamic_data) j["get_dynamic_data"] = true;
  if (s.default_dynamic_data) j["default_dynamic_data"] = true;
  put(j, "override_speed_fact_pct", s.override_speed_fact_pct);
  if (s.feed_link) {
    json f{{"auto", s.feed_link->automatic}, {"main", s.feed_link->main}, {"src", s.feed_link->src}};
    put(f, "on", s.feed_link->on);
    put(f, "fact_pct", s.feed_link->fact_pct);
    put(f, "corr", s.feed_link->corr);
    j["feed_link"] = f;
  }
  return j;
}

json to_json(const HashCommand& h) {
  HashJson v;
  std::visit(v, h);
  v.j["command"] = hash_command_name(h);
  return v.j;
}

json to_json(const Block& b, const Decoder& d) {
  json j{{"file", d.file_name(b.file_id)}, {"line", b.line}};
  j["n"] = b.n ? json(*b.n) : json(nullptr);
  j["offset"] = b.offset;  // block search type 1 (nck run --start-at-offset)
  j["row"] = b.row;        // block search type 3 (nck run --start-at-block)
  json axes = json::object();
  const auto& names = d.config().axis_names;
  for (std::size_t i = 0; i < b.axes.size(); ++i)
    if (b.axes[i]) axes[i < names.size() && !names[i].empty() ? names[i] : std::to_string(i)] = *b.axes[i];
  if (!axes.empty()) j["axes"] = axes;
  static constexpr const char* ijk[] = {"I", "J", "K"};
  for (int i = 0; i < 3; ++i)
    if (b.ijk[i]) j[ijk[i]] = *b.ijk[i];
  put(j, "R", b.r);
  put(j, "F", b.f);
  if (!b.g_nonmodal.empty()) {
    json g = json::array();  // G numbers, ascending
    for (GCode code : b.g_nonmodal) g.push_back(g_number(code));
    j["g_nonmodal"] = std::move(g);
  }
  if (!b.m.empty()) j["m"] = b.m;
  if (!b.h.empty()) j["h"] = b.h;
  for (const auto& [key, values] : {std::pair{"m_values", &b.m_values}, std::pair{"h_values", &b.h_values}})
    for (const FunctionValue& v : *values) j[key][std::to_string(v.number)] = v.value;
  put(j, "T", b.t);
  put(j, "D", b.d);
  put(j, "dwell_s", b.dwell_s);
  put(j, "dwell_revs", b.dwell_revs);
  if (!b.spindles.empty()) {
    j["spindles"] = json::array();
    for (const auto& s : b.spindles) j["spindles"].push_back(to_json(s));
  }
  if (b.hash) j["hash"] = to_json(*b.hash);
  if (!b.kernel_writes.empty()) {
    j["kernel_writes"] = json::array();
    for (const auto& w : b.kernel_writes) j["kernel_writes"].push_back({{"name", w.name}, {"value", w.value}});
  }
  if (b.program_end) j["program_end"] = true;
  if (b.stop) j["stop"] = true;
  if (b.optional_stop) j["optional_stop"] = true;
  if (b.depth) j["depth"] = b.depth;
  j["modal"] = to_json(b.modal);
  return j;
}

}  // namespace nck::nc
