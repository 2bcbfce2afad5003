#include "nck/prep/command_packer.hpp"

#include <utility>
#include <cstring>

#include "nck/core/fixed_vector.hpp"

namespace nck::prep {
namespace {

using Attachments = FixedVector<kernel::Attachment, kernel::kMaxAttachments>;

kernel::Motion motion_of(const PlannedCommand& c) {
  return kernel::Motion{c.segment.tail(), c.limits,  c.v_cmd_mm_s,       c.v_end_mm_s,   c.start_a_mm_s2,
                        c.brake_beyond_mm, c.trafo,  c.measure,         c.passes_at_cruise, c.pass_in_limited,
                        c.into_fillet,     c.corner_stop,       c.manual_offset_axes};
}

// The order the channel handles them in (attachment.hpp), the planned order
// within a kind: an insertion sort, stable and in place (a command has few).
void in_handling_order(Attachments& a) {
  for (std::size_t i = 1; i < a.size(); ++i)
    for (std::size_t j = i; j > 0 && a[j - 1].index() > a[j].index(); --j) std::swap(a[j - 1], a[j]);
}

}  // namespace

bool CommandPacker::pack(const PlannedCommand& c, kernel::CommandQueue& q) {
  const bool motion = c.kind == CommandKind::motion;
  kernel::Command k;
  static_cast<kernel::CommandHead&>(k) = c.head;
  if (motion) k.action = motion_of(c);
  else if (c.kind != CommandKind::nop) std::visit([&](const auto& step) { k.action = step; }, c.step);
  Attachments a;
  for (const kernel::Attachment& x : c.attachments)
    if (motion || !std::holds_alternative<kernel::ProgramMap>(x)) (void)a.push_back(x);
  if (c.feed_link.kind != kernel::FeedLinkKind::none) (void)a.push_back(c.feed_link);
  if (c.css.active) (void)a.push_back(c.css);
  if (motion) {
    const motion::AxisVector& start = c.segment.start_point();
    if (std::memcmp(start.data(), last_end_.data(), sizeof(motion::AxisVector)) != 0)
      (void)a.push_back(kernel::StartPoint{start});
  }
  in_handling_order(a);
  k.attachments = static_cast<std::uint16_t>(a.size());
  if (!q.push(k, std::span<const kernel::Attachment>(a.begin(), a.size()))) return false;
  if (motion) last_end_ = c.segment.end_point();
  return true;
}

}  // namespace nck::prep
