// #DIST CTRL in the decoder: the switch with its keyword overrides
// (docs/nc-language.md, "3D distance control"), its name and its JSON form.
// The decoder tracks the mode to report 310024/310025 (modal_apply.cpp).
#include <cmath>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "nc/hash_parse_util.hpp"

namespace nck::nc {

using detail::args_error;
using detail::eval_value;
using detail::keywords;
using detail::to_upper;

bool parse_hash_command(detail::HashCtx& h, DistCtrl& d) {
  detail::Cursor& c = h.c;
  detail::BlockCtx& b = h.b;
  const std::size_t pos = h.pos;
  if (!b.cfg.dist_ctrl_available)
    return b.x.err.fail(ErrorId::NcDistCtrlNotEnabled, pos,
                        "3D distance control is not enabled in this start mode: add FCT_3D_DIST_CTRL to "
                        "configuration.decoder.function, or to fct_enable[i] whose fct_condition[i] is the "
                        "start mode (nck run: ISG_STANDARD)");
  d.op = DistCtrlOp::settings;
  if (keywords(c, {"WAIT"})) d.wait = true;
  if (keywords(c, {"ON"})) d.op = DistCtrlOp::on;
  else if (keywords(c, {"DRYRUN"})) { d.op = DistCtrlOp::on; d.dryrun = true; }
  else if (keywords(c, {"FREEZE"})) d.op = DistCtrlOp::freeze;
  else if (keywords(c, {"OFF"})) { d.op = DistCtrlOp::off; d.no_move = keywords(c, {"NO_MOVE"}); }
  c.skip_spaces();
  if (c.match('[')) {
    for (;;) {
      c.skip_spaces();
      if (c.match(']')) break;
      if (c.at_end()) return args_error(b, pos, "']' expected to close the #DIST CTRL options");
      std::size_t kp = c.pos;
      std::string key = to_upper(c.read_ident());
      if (key == "SURFACE") { d.const_dist = false; continue; }
      if (key == "CONST_DIST") { d.const_dist = true; continue; }
      c.skip_spaces();
      if (key.empty() || !c.match('='))
        return args_error(b, kp, "option expected as KEY=value (SET_POS= SET_DIST= KP= I_TN= D_TV= FILTER_TYPE= "
                                 "N_CYCLES= FG_F0= ORDER= SMOOTH_FACT= KALMAN_SIGMA= SENSOR_SOURCE= SENSOR_VAR=)");
      c.skip_spaces();
      if (key == "FILTER_TYPE" || key == "SENSOR_SOURCE" || key == "SENSOR_VAR") {
        std::size_t b0 = c.pos;
        while (!c.at_end() && c.peek() != ' ' && c.peek() != ']' && c.peek() != ',') ++c.pos;
        std::string v = to_upper(c.s.substr(b0, c.pos - b0));
        if (key == "FILTER_TYPE") {
          static constexpr std::string_view kTypes[] = {"MOVING_AVERAGE", "LOWPASS", "KALMAN_MA",
                                                        "EXPO_MEAN", "KALMAN_EXPO"};
          bool ok = false;
          for (auto t : kTypes) ok = ok || v == t;
          if (!ok)
            return args_error(b, b0, fmt::format("FILTER_TYPE {} unknown: MOVING_AVERAGE, LOWPASS, KALMAN_MA, "
                                                 "EXPO_MEAN or KALMAN_EXPO", v));
          d.filter_type = v;
        } else if (key == "SENSOR_SOURCE") {
          d.sensor_source = v;
        } else {
          d.sensor_var = v;
        }
        c.match(',');
        continue;
      }
      double v = 0;
      if (!eval_value(c, b.x, v)) return false;
      c.match(',');
      auto positive = [&](bool ok) {
        return ok ? true : args_error(b, kp, fmt::format("{}={} is out of range", key, v));
      };
      if (key == "SET_POS") d.set_pos_mm = v;
      else if (key == "SET_DIST") { if (!positive(v >= 0)) return false; d.set_dist_mm = v; }
      else if (key == "KP") { if (!positive(v >= 0)) return false; d.kp = v; }
      else if (key == "I_TN") { if (!positive(v >= 0)) return false; d.i_tn = v; }
      else if (key == "D_TV") { if (!positive(v >= 0)) return false; d.d_tv = v; }
      else if (key == "N_CYCLES") { if (!positive(v >= 0 && v <= 100000 && v == std::round(v))) return false; d.n_cycles = static_cast<int>(v); }
      else if (key == "ORDER") { if (!positive(v >= 0 && v <= 10 && v == std::round(v))) return false; d.order = static_cast<int>(v); }
      else if (key == "FG_F0") { if (!positive(v > 0)) return false; d.fg_f0 = v; }
      else if (key == "SMOOTH_FACT") { if (!positive(v > 0 && v <= 1)) return false; d.smooth_fact = v; }
      else if (key == "KALMAN_SIGMA") { if (!positive(v > 0)) return false; d.kalman_sigma = v; }
      else return args_error(b, kp, fmt::format("{} is not a #DIST CTRL option", key));
    }
  }
  if (d.op == DistCtrlOp::on) {
    int want = d.const_dist ? 2 : 1;
    if ((b.dist_state == 1 || b.dist_state == 2) && b.dist_state != want)
      return b.x.err.fail(ErrorId::NcDistCtrlModeChange, pos,
                          "switch #DIST CTRL OFF or FREEZE before changing between SURFACE and CONST_DIST");
    if (!d.const_dist && !d.set_pos_mm && !b.dist_set_pos_known)
      return b.x.err.fail(ErrorId::NcDistCtrlNoSetPos, pos,
                          "surface mode needs the surface position: #DIST CTRL ON [SURFACE SET_POS=..]");
  }
  return true;
}

std::string command_name(const DistCtrl& d) {
  static constexpr const char* kOps[] = {"ON", "FREEZE", "OFF", ""};
  const std::string op = kOps[static_cast<int>(d.op)];
  return op.empty() ? "#DIST CTRL" : "#DIST CTRL " + op;
}

namespace {
template <class T>
void put(nlohmann::json& j, const char* key, const std::optional<T>& v) {
  if (v) j[key] = *v;
}
}  // namespace

void write_json(nlohmann::json& j, const DistCtrl& d) {
  j["mode"] = d.const_dist ? "CONST_DIST" : "SURFACE";
  put(j, "set_pos_mm", d.set_pos_mm);
  put(j, "set_dist_mm", d.set_dist_mm);
  put(j, "kp", d.kp);
  put(j, "i_tn", d.i_tn);
  put(j, "d_tv", d.d_tv);
  put(j, "filter_type", d.filter_type);
  put(j, "n_cycles", d.n_cycles);
  put(j, "order", d.order);
  put(j, "fg_f0", d.fg_f0);
  put(j, "smooth_fact", d.smooth_fact);
  put(j, "kalman_sigma", d.kalman_sigma);
  put(j, "sensor_source", d.sensor_source);
  put(j, "sensor_var", d.sensor_var);
}

}  // namespace nck::nc
