// Display names of the typed # commands.
#include <fmt/format.h>

#include "nck/nc/hash_commands.hpp"

namespace nck::nc {

namespace {
struct NameOf {
  std::string operator()(const SetAxLink& s) const { return s.by_number ? "#AX LINK NBR" : "#SET AX LINK"; }
  std::string operator()(const EnableAxLink&) const { return "#ENABLE AX LINK"; }
  std::string operator()(const DisableAxLink&) const { return "#DISABLE AX LINK"; }
  std::string operator()(const MainSpindle&) const { return "#MAIN SPINDLE"; }
  std::string operator()(const CAxis& c) const { return c.on ? "#CAX" : "#CAX OFF"; }
  std::string operator()(const Face& c) const { return c.on ? "#FACE" : "#FACE OFF"; }
  std::string operator()(const Cylinder& c) const { return c.on ? "#CYL" : "#CYL OFF"; }
  std::string operator()(const ExplSyn&) const { return "#EXPL SYN"; }
  std::string operator()(const ToolData& t) const { return t.prep ? "#TOOL PREP" : "#TOOL DATA"; }
  std::string operator()(const CoordSystem& c) const {
    static constexpr const char* ops[] = {"DEF", "ON", "OFF", "OFF ALL", "ADD", "SELECT", "MODE ON", "MODE OFF"};
    return fmt::format("#{} {}", c.acs ? "ACS" : "CS", ops[static_cast<int>(c.op)]);
  }
  std::string operator()(const Ecs& c) const { return c.on ? "#ECS ON" : "#ECS OFF"; }
  std::string operator()(const Mcs& c) const { return c.on ? "#MCS ON" : "#MCS OFF"; }
  std::string operator()(const Rotation& c) const { return c.on ? "#ROTATION ON" : "#ROTATION OFF"; }
  std::string operator()(const PSet&) const { return "#PSET"; }
  std::string operator()(const PReset&) const { return "#PRESET"; }
  std::string operator()(const Tlc& c) const { return c.on ? "#TLC ON" : "#TLC OFF"; }
  std::string operator()(const SuppressOffsets&) const { return "#SUPPRESS OFFSETS"; }
  std::string operator()(const GetManualOffsets&) const { return "#GET MANUAL OFFSETS"; }
  // a technology's command names itself, beside its syntax
  template <class Command>
  std::string operator()(const Command& c) const {
    return command_name(c);
  }
};
}  // namespace

std::string hash_command_name(const HashCommand& c) { return std::visit(NameOf{}, c); }

}  // namespace nck::nc
