#pragma once
// Preparation's technologies that live in a home of their own
// (docs/architecture.md, "Adding a technology"), listed in technologies.hpp.
// The planner has each plan its part of a block, in the order of the list,
// after the couplings and before the spindles; a unit has
//   PlanResult plan(const nc::Block&, PlannedCommand&, const PlanContext&)
// and attaches what its kernel unit takes (PlannedCommand::attach).
#include <tuple>

#include "nck/prep/units/plan_context.hpp"

namespace nck::prep {

template <class... Units>
class TechnologyUnits {
 public:
  template <class U>
  const U& get() const noexcept { return std::get<U>(units_); }

  // The first failure wins: the units after it do not see the block.
  PlanResult plan(const nc::Block& b, PlannedCommand& c, const PlanContext& ctx) {
    PlanResult r{};
    std::apply([&](auto&... u) { ((r = r ? u.plan(b, c, ctx) : r), ...); }, units_);
    return r;
  }

 private:
  std::tuple<Units...> units_;
};

}  // namespace nck::prep
