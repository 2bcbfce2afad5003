#pragma once
// Private to the config layer: builders from checked lists to the typed model,
// and the plausibility checks (IDs 910010-910027 in docs/errors.md).
#include <vector>

#include "nck/config/machine.hpp"
#include "nck/config/param_list.hpp"

namespace nck::config::detail {

AxisConfig build_axis(const ParamList& list, Diagnostics& diags);
ChannelConfig build_channel(const ParamList& list, std::uint32_t number, Diagnostics& diags);
std::vector<ToolRecord> build_tools(const ParamList& list, Diagnostics& diags);
ZeroOffsets build_zero(const ParamList& list);
ClampOffsets build_clamp(const ParamList& list);
SimConfig build_sim(const ParamList& list);

// The checked lists behind one channel, kept for the cross-list checks.
struct ChannelLists {
  ParamList channel, tool, zero, clamp;
};
void check_machine(Machine& m, const std::vector<ParamList>& axis_lists,
                   const std::vector<ChannelLists>& channel_lists, Diagnostics& diags);

// `nck check` only (LoadOptions::capability_warnings): what a program cannot
// ask of the machine, as warnings, e.g. 70252 for a spindle that cannot
// position or home. Run after check_machine (it needs the axis links).
void check_capabilities(const Machine& m, const std::vector<ParamList>& axis_lists, Diagnostics& diags);

// After the checks: the main spindle that can become a C axis joins the
// channel's axes under default_ax_name_of_spindle (ChannelConfig::c_axis).
void add_c_axes(Machine& m);

// Reports `message` (ConfigCrossRange) unless `ok`, at the later of the two
// keys that is given; silent when neither key is given (both defaults).
void cross_check(const ParamList& list, std::string_view key_a, std::string_view key_b, bool ok,
                 std::string message, Diagnostics& diags);

// "key (value unit)" in the units the list file uses, for relation messages:
// the value as written, or the default converted back from `internal`. A unit
// written for two axis kinds ("µm/s · 0.001°/s") is cut to part `unit_part`.
std::string listed(const ParamList& list, std::string_view key, double internal, std::size_t unit_part = 0);

// Gap-free numbering 0..n-1 of `indices`; reports 910025 at `where` otherwise.
bool check_no_gaps(const std::vector<std::uint32_t>& indices, SourceLoc where, std::string_view what,
                   Diagnostics& diags);

}  // namespace nck::config::detail
