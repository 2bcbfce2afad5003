#include "nck/prep/block_search.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "nck/prep/planner.hpp"

namespace nck::prep {
namespace {

using kernel::SpindleOp;

// Rotation, stop and positioning set what a spindle does; the last one counts.
bool sets_motion(SpindleOp op) {
  return op == SpindleOp::rotate || op == SpindleOp::stop || op == SpindleOp::position;
}

template <class T, class Pred>
void erase_where(std::vector<T>& v, Pred p) {
  v.erase(std::remove_if(v.begin(), v.end(), p), v.end());
}

}  // namespace

void SearchCollector::take(const PlannedCommand& c) {
  c.each<kernel::Output>([&](const kernel::Output& o) { take(o); });
  c.each<kernel::SpindleAction>([&](const kernel::SpindleAction& a) { take(a); });
}

// The last T only (a tool change replays once); the last of each M and H number.
void SearchCollector::take(const kernel::Output& o) {
  erase_where(outputs_, [&](const kernel::Output& x) {
    return x.fn == o.fn && (o.fn == plc::TechKind::t || x.number == o.number);
  });
  outputs_.push_back(o);
}

void SearchCollector::take(const kernel::SpindleAction& a) {
  const auto same_spindle = [&](const kernel::SpindleAction& x) { return x.spindle == a.spindle; };
  if (a.op == SpindleOp::home) return;  // homing is no state to restore
  if (sets_motion(a.op)) {
    erase_where(actions_, [&](const kernel::SpindleAction& x) {
      return same_spindle(x) && (sets_motion(x.op) || x.op == SpindleOp::speed);
    });
  } else if (a.op == SpindleOp::speed) {
    // S alone: a rotating spindle takes it in its direction; else it is only stored.
    const auto rotating = std::find_if(actions_.begin(), actions_.end(), [&](const kernel::SpindleAction& x) {
      return same_spindle(x) && x.op == SpindleOp::rotate;
    });
    if (rotating != actions_.end()) {
      rotating->rpm = std::copysign(a.rpm, rotating->rpm);
      return;
    }
    erase_where(actions_, [&](const kernel::SpindleAction& x) { return same_spindle(x) && x.op == a.op; });
  } else {
    erase_where(actions_, [&](const kernel::SpindleAction& x) { return same_spindle(x) && x.op == a.op; });
  }
  actions_.push_back(a);
}

std::vector<PlannedCommand> SearchCollector::commands(const PlannedCommand& like) const {
  std::vector<PlannedCommand> out;
  PlannedCommand c;
  c.kind = CommandKind::nop;
  c.head.file_id = like.head.file_id;
  c.head.line = like.head.line;
  c.head.n = like.head.n;
  c.head.emit_block_event = false;
  std::size_t o = 0, a = 0;
  while (o < outputs_.size() || a < actions_.size()) {
    PlannedCommand batch = c;
    while (o < outputs_.size() && batch.attach_within(outputs_[o], PlannedCommand::kMaxOutputs)) ++o;
    while (a < actions_.size() && batch.attach_within(actions_[a], PlannedCommand::kMaxSpindleActions)) ++a;
    out.push_back(batch);
  }
  return out;
}

bool SearchMatcher::in_program(const nc::Block& b, const std::string& file) const {
  if (mark_.program.empty()) return mark_.kind != SearchMark::Kind::file_offset || b.file_id == 0;
  const std::filesystem::path p(file);
  return file == mark_.program || p.filename() == mark_.program || p.stem() == mark_.program;
}

bool SearchMatcher::is_mark(const nc::Block& b, const std::string& file) {
  const std::uint32_t pass = std::max<std::uint32_t>(mark_.pass, 1);
  switch (mark_.kind) {
    case SearchMark::Kind::block_counter:
      return b.row >= static_cast<std::uint64_t>(std::max<std::int64_t>(mark_.value, 0));
    case SearchMark::Kind::file_offset: {
      const auto at = static_cast<std::uint64_t>(std::max<std::int64_t>(mark_.value, 0));
      if (!in_program(b, file) || at < b.offset || at >= b.offset_end) return false;
      return ++seen_ == pass;
    }
    case SearchMark::Kind::block_number:
      if (!b.n || *b.n != mark_.value || !in_program(b, file)) return false;
      return ++seen_ == pass;
  }
  return false;
}

}  // namespace nck::prep

namespace nck::prep {

PlannedCommand SearchRun::begins() {
  PlannedCommand c;
  c.kind = CommandKind::nop;
  c.head.emit_block_event = false;
  c.head.restart = kernel::Restart::search_begins;
  return c;
}

std::expected<std::vector<PlannedBlock>, Diagnostic> SearchRun::restart(PlannedBlock planned, const Planner& planner,
                                                                        const SourceLoc& at) {
  std::vector<PlannedBlock> out;
  if (!planned.empty() && planned[0].kind == CommandKind::error) {
    out.push_back(planned);  // the mark block fails as it would in a full run
    return out;
  }
  PlannedCommand* move = nullptr;
  for (PlannedCommand& c : planned)
    if (c.kind == CommandKind::motion) {
      move = &c;
      break;
    }
  motion::AxisVector target = planner.planned_mcs();  // a block without motion: where the program stands
  if (move) {
    if (move->trafo.kind != motion::CaxTrafoKind::none)
      return std::unexpected(make_diagnostic(ErrorId::KernelBlockSearchInTransform, at,
                                             "block search cannot restart in a block under #FACE or #CYL; "
                                             "restart at a block before the transformation is switched on"));
    // Only the (rest of the) motion runs for real: its functions were met in search.
    collected_.take(*move);
    move->detach<kernel::Output>();
    move->detach<kernel::SpindleAction>();
    const double covered = std::clamp(matcher_.mark().covered_permille, 0.0, 1000.0) / 1000.0;
    if (covered > 0) move->segment = move->segment.remainder(covered * move->segment.length());
    if (!(move->segment.length() > 0)) move->kind = CommandKind::nop;
    target = move->segment.start_point();
    if (const auto* map = move->find<kernel::ProgramMap>())
      map->map.apply(move->segment.start_point(), target, planner.axis_count());
  }
  PlannedCommand back = planner.return_motion(start_mcs_, target);
  if (!planned.empty()) {
    back.head.file_id = planned[0].head.file_id;
    back.head.line = planned[0].head.line;
    back.head.n = planned[0].head.n;
  }
  back.head.emit_block_event = false;
  back.head.restart = matcher_.mark().no_hold_at_restart ? kernel::Restart::returns_no_hold : kernel::Restart::returns;
  for (PlannedCommand& c : collected_.commands(back)) {
    c.head.restart = kernel::Restart::search_begins;  // still searching: the PLC gets what was met
    PlannedBlock b;
    (void)b.push_back(c);
    out.push_back(b);
  }
  PlannedBlock b;
  (void)b.push_back(back);
  out.push_back(b);
  out.push_back(planned);
  return out;
}

std::vector<Diagnostic> SearchRun::not_found(const SourceLoc& at) const {
  std::vector<Diagnostic> out;
  const SearchMark& m = matcher_.mark();
  if (m.kind == SearchMark::Kind::block_number && !matcher_.number_seen())
    out.push_back(make_diagnostic(ErrorId::KernelBlockSearchNumberUnknown, at,
                                  fmt::format("block search: no block N{} in {}; the program ran in search to its end",
                                              m.value, m.program.empty() ? "the program" : m.program)));
  out.push_back(make_diagnostic(ErrorId::KernelBlockSearchNotFound, at,
                                fmt::format("block search: the restart mark was not found before the program end "
                                            "(type {}, {}, pass {})",
                                            static_cast<int>(m.kind), m.value, std::max<std::uint32_t>(m.pass, 1))));
  return out;
}

}  // namespace nck::prep
