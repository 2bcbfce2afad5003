#include "nck/prep/command_packer.hpp"

#include <cstring>

#include "nck/core/fixed_vector.hpp"

namespace nck::prep {
namespace {

using Attachments = FixedVector<kernel::Attachment, kernel::kMaxAttachments>;

kernel::Action action_of(const PlannedCommand& c) {
  switch (c.kind) {
    case CommandKind::motion:
      return kernel::Motion{c.segment.tail(), c.limits,  c.v_cmd_mm_s,          c.v_end_mm_s,        c.start_a_mm_s2,
                            c.trafo,          c.measure, c.passes_at_cruise, c.after_fillet,
                            c.into_fillet,    c.manual_offset_axes};
    case CommandKind::dwell: {
      kernel::Dwell d{c.dwell_s, std::nullopt};
      if (c.dwell_spindle >= 0) d.revolutions = kernel::Dwell::Revolutions{c.dwell_revs, c.dwell_spindle};
      return d;
    }
    case CommandKind::stop: return kernel::Hold{c.optional_stop};
    case CommandKind::end: return kernel::End{c.end_reason};
    case CommandKind::error: return kernel::Error{c.error_id, c.message_index};
    case CommandKind::nop: break;
  }
  return kernel::Nop{};
}

kernel::DistChange dist_change(const PlannedCommand& c) {
  kernel::DistChange d;
  d.sw = c.dist;
  d.axis = c.dist_axis;
  d.source = c.dist_source;
  d.variable = c.dist_var;
  if (c.dist_check_sw) d.sw_limits_mm = std::array<double, 2>{c.dist_sw_neg_mm, c.dist_sw_pos_mm};
  return d;
}

// What the channel reports with the block, in this order, then what its
// units take when it starts (docs/architecture.md).
void add_switches(const PlannedCommand& c, Attachments& a) {
  for (const kernel::Warning& w : c.warnings) (void)a.push_back(w);
  for (std::uint32_t i : c.offset_events) (void)a.push_back(kernel::OffsetEvent{i});
  if (c.trc) (void)a.push_back(*c.trc);
  if (c.cax != PlannedCommand::CaxOp::none)
    (void)a.push_back(kernel::CaxChange{c.cax == PlannedCommand::CaxOp::on, c.cax_spindle, c.cax_axis});
  if (c.link.any()) (void)a.push_back(c.link);
  if (c.dist.any()) (void)a.push_back(dist_change(c));
  if (c.feed_link.kind != kernel::FeedLinkKind::none) (void)a.push_back(c.feed_link);
  if (c.css.active) (void)a.push_back(c.css);
  if (c.manual_on != 0 || c.manual_off != 0 || c.get_manual_offsets)
    (void)a.push_back(kernel::ManualChange{c.manual_on, c.manual_off, c.get_manual_offsets});
  for (const kernel::Output& o : c.outputs) (void)a.push_back(o);
  for (const kernel::SpindleAction& s : c.spindle_actions) (void)a.push_back(s);
}

}  // namespace

bool CommandPacker::pack(const PlannedCommand& c, kernel::CommandQueue& q) {
  kernel::Command k;
  k.file_id = c.file_id;
  k.line = c.line;
  if (c.has_n) k.n = c.n;
  k.emit_block_event = c.emit_block_event;
  k.restart = c.restart;
  k.mdi = c.mdi;
  k.feed_motion = c.feed_motion;
  k.expl_syn = c.expl_syn;
  k.frame_index = c.frame_index;
  k.action = action_of(c);
  Attachments a;
  add_switches(c, a);
  const bool motion = c.kind == CommandKind::motion;
  if (motion) {
    const motion::AxisVector& start = c.segment.start_point();
    if (std::memcmp(start.data(), last_end_.data(), sizeof(motion::AxisVector)) != 0)
      (void)a.push_back(kernel::StartPoint{start});
    if (c.mapped) (void)a.push_back(kernel::ProgramMap{c.map});
  }
  k.attachments = static_cast<std::uint16_t>(a.size());
  if (!q.push(k, std::span<const kernel::Attachment>(a.begin(), a.size()))) return false;
  if (motion) last_end_ = c.segment.end_point();
  return true;
}

}  // namespace nck::prep
