#pragma once
// #DIST CTRL as the decoder gives it (channel_params_distctrl seed;
// docs/nc-language.md, "3D distance control"): the switch and its keyword
// overrides. Lengths in program units. Its syntax, name and JSON form are in
// src/distctrl/nc/dist_ctrl_syntax.cpp; the decoder finds them by the
// command's type (nc::HashCommand).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

namespace nck::nc {
namespace detail {
struct HashCtx;
}

enum class DistCtrlOp : std::uint8_t { on, freeze, off, settings };

struct DistCtrl {
  // The keywords after '#' that start the command.
  static constexpr std::array<std::string_view, 3> kKeywords{"DIST", "CTRL"};

  DistCtrlOp op = DistCtrlOp::on;
  bool const_dist = false;  // CONST_DIST mode (SURFACE otherwise)
  bool dryrun = false, wait = false, no_move = false;
  std::optional<double> set_pos_mm, set_dist_mm;
  std::optional<double> kp, i_tn, d_tv;
  std::optional<std::string> filter_type;  // MOVING_AVERAGE LOWPASS KALMAN_MA EXPO_MEAN KALMAN_EXPO
  std::optional<int> n_cycles, order;
  std::optional<double> fg_f0, smooth_fact, kalman_sigma;
  std::optional<std::string> sensor_source, sensor_var;
};

// What follows the keywords, into out; false after a diagnostic.
bool parse_hash_command(detail::HashCtx& h, DistCtrl& out);
// "#DIST CTRL ON", ... as the program writes it.
std::string command_name(const DistCtrl& d);
// Its fields in `nck parse`'s block JSON.
void write_json(nlohmann::json& j, const DistCtrl& d);

}  // namespace nck::nc
