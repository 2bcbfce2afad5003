#pragma once
// The coupling groups of one channel as preparation sees them (setup side):
// definitions (#SET AX LINK / #AX LINK [NBR], group 0 from the channel list),
// which groups are enabled, and the rules of TF5200 #SET AX LINK and the
// spindle_link seed. Pure bookkeeping: no kernel, no time. The planner turns what it
// answers into kernel::LinkCommand and fans spindle functions out.
#include <cstdint>
#include <expected>
#include <optional>
#include <string>
#include <vector>

#include "nck/config/machine.hpp"
#include "nck/core/diagnostic.hpp"
#include "nck/kernel/ax_link.hpp"
#include "nck/nc/hash_commands.hpp"

namespace nck::prep {

// One end of a pair: a channel path axis or a channel spindle.
struct LinkMember {
  bool spindle = false;
  int index = -1;               // channel axis index or channel spindle index
  bool via_main_name = false;   // named by the main spindle's name ("S")
};

struct LinkPairDef {
  LinkMember slave, master;
  bool gantry = false;
  double limit1_mm = 0, limit2_mm = 0;  // gantry deviation limits (0 = the slave's defaults)
  double ratio = 1.0;
};

struct LinkGroupDef {
  std::vector<LinkPairDef> pairs;
  int main_spindle = -1;        // the main spindle when the group was defined
  bool enabled = false;
};

class AxLinkGroups {
 public:
  // setup: group 0 from synchro_data.koppel_gruppe[0] (already checked by config).
  explicit AxLinkGroups(const config::ChannelConfig& channel, int main_spindle);

  std::expected<void, Diagnostic> define(const nc::SetAxLink& s);
  // Enables group g (nullopt: group 0); the group's pairs on success.
  std::expected<const LinkGroupDef*, Diagnostic> enable(std::optional<int> group);
  // Disables: the named group, the group enabled last, or all. Returns the
  // mask of groups switched off (0: nothing was enabled, without a group).
  std::expected<std::uint32_t, Diagnostic> disable(const nc::DisableAxLink& d);
  // Program end: every group off (P-CHAN-00105 decides whether the kernel
  // keeps them; preparation starts the next program from the kernel's state).
  std::uint32_t disable_all();
  // #MAIN SPINDLE: the new main spindle (channel spindle index) must not be
  // linked in an enabled group.
  std::expected<void, Diagnostic> change_main_spindle(int spindle);

  // Is the channel spindle / path axis the slave of an enabled group?
  bool spindle_is_slave(int spindle) const;
  bool axis_is_slave(int axis) const;
  // The slaves of channel spindle `master` in enabled groups.
  std::vector<int> slaves_of_spindle(int master) const;
  // The enabled path-axis pairs.
  std::vector<const LinkPairDef*> axis_pairs() const;
  int main_spindle() const { return main_spindle_; }
  std::string member_name(const LinkMember& m) const;

 private:
  std::expected<LinkMember, Diagnostic> resolve(const std::string& token, bool by_number) const;
  std::expected<void, Diagnostic> check_pair(const nc::AxLinkPair& p, const LinkPairDef& d) const;
  std::expected<void, Diagnostic> check_against_enabled(int group) const;
  static bool same(const LinkMember& a, const LinkMember& b) { return a.spindle == b.spindle && a.index == b.index; }

  const config::ChannelConfig& channel_;
  std::vector<LinkGroupDef> groups_;   // by group number 0..kMaxLinkGroupNr
  std::vector<int> enable_order_;      // enabled groups, the last enabled at the back
  int main_spindle_ = -1;
};

}  // namespace nck::prep
