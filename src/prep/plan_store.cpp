#include "nck/prep/plan_store.hpp"

#include <fmt/format.h>

namespace nck::prep {

void add_warnings(PlannedCommand& c, const std::vector<Diagnostic>& warnings, PlanStore& store) {
  for (std::size_t i = 0; i < warnings.size(); ++i) {
    const Diagnostic& w = warnings[i];
    const std::size_t held = c.count<kernel::Warning>();
    if (held + 1 < PlannedCommand::kMaxWarnings || i + 1 == warnings.size()) {
      if (!c.attach_within(kernel::Warning{{w.id, store.add_message(w.message), {}}}, PlannedCommand::kMaxWarnings)) break;
      continue;
    }
    const std::size_t more = warnings.size() - i;  // this one and the rest
    const std::uint32_t text =
        store.add_message(fmt::format("{} more warning(s) of this block, the first: {}", more, w.message));
    (void)c.attach_within(kernel::Warning{{ErrorId::KernelWarningsDropped, text, {}}}, PlannedCommand::kMaxWarnings);
    break;
  }
}

}  // namespace nck::prep
