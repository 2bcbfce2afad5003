// Tool radius compensation stage (radius_comp.hpp): how a held element is
// ended once the next one is known, and the blocks that carry the tool-centre
// path to the planner (rewritten plane words and circle centres, corner arcs).
#include <cmath>
#include <fmt/format.h>

#include "nck/prep/planner.hpp"
#include "nck/prep/radius_comp.hpp"

namespace nck::prep {
namespace {

namespace trc = motion::trc;
constexpr double kTiny = 1e-9;

}  // namespace

// The last held element ends where `next` starts (next.comp_start is set
// here, and next.arc_before at an outside corner). Once the last element is
// known to be sound, the one before it leaves. False after an error.
bool RadiusComp::close_last(Item& next, std::vector<TrcOut>& out) {
  Item& last = queue_.back();
  if (last.role == Role::link) {
    // A link ends square to the element it leads onto.
    last.comp_end = next.comp_start = last.prog.end + last.o * trc::left_of(trc::tangent_start(next.prog));
  } else if (next.role == Role::contour) {
    const trc::Corner k = trc::corner(last.prog, next.prog, last.o);
    if (k.error != trc::CornerError::none) {
      const bool circles = last.prog.arc && next.prog.arc;
      fail(next.block, circles ? ErrorId::KernelTrcCirclesApart : ErrorId::KernelTrcNoCorner,
           fmt::format("the tool-centre paths of this block and the one before do not meet with tool radius "
                       "{:.4f} mm (the tool does not fit into the inside corner)",
                       std::abs(last.o)),
           out);
      return false;
    }
    last.comp_end = k.end_a;
    next.comp_start = k.start_b;
    if (k.kind == trc::CornerKind::outside && trc::length(k.end_a - k.start_b) > kTiny)
      next.arc_before = corner_arc(last.block, next.block, k.center, k.end_a, k.start_b, k.arc_ccw);
  } else {
    last.comp_end = next.comp_start = trc::offset_end(last.prog, last.o);  // next leaves the contour
  }
  if (!check_last(out)) return false;
  while (queue_.size() > 1) emit_front(out);
  return true;
}

// The bottleneck test of the last element, now that both its ends are known.
bool RadiusComp::check_last(std::vector<TrcOut>& out) {
  const Item& last = queue_.back();
  if (last.role != Role::contour || trc::keeps_direction(last.prog, last.comp_start, last.comp_end)) return true;
  const nc::Block b = last.block;
  const double r = std::abs(last.o);
  fail(b, ErrorId::KernelTrcContourViolation,
       fmt::format("with tool radius {:.4f} mm the tool centre would run backwards along this block: the tool "
                   "would cut into the contour (a bottleneck)",
                   r),
       out);
  return false;
}

void RadiusComp::emit_front(std::vector<TrcOut>& out) {
  Item it = std::move(queue_.front());
  queue_.erase(queue_.begin());
  if (it.arc_before) {
    TrcOut a = TrcOut::of(std::move(*it.arc_before));
    a.inserted = true;
    out.push_back(std::move(a));
  }
  out.push_back(TrcOut::of(rewrite(it)));
  for (nc::Block& h : it.held) out.push_back(TrcOut::of(std::move(h)));
}

void RadiusComp::flush(std::vector<TrcOut>& out) {
  if (queue_.empty()) return;
  Item& last = queue_.back();
  last.comp_end = last.prog.end;  // departure: the programmed point
  if (last.role == Role::link) last.comp_end = last.prog.end + last.o * trc::left_of(trc::tangent_end(last.prog));
  if (last.role == Role::contour) last.comp_end = trc::offset_end(last.prog, last.o);
  if (!check_last(out)) return;
  while (!queue_.empty()) emit_front(out);
}

void RadiusComp::set_plane_words(nc::Block& r, Vec2 from, Vec2 to) const {
  const Vec2 v = r.modal.absolute ? to : to - from;
  const double values[2] = {v.a, v.b};
  const int axes[2] = {ax_a_, ax_b_};
  for (int k = 0; k < 2; ++k) {
    const auto j = static_cast<std::size_t>(axes[k]);
    r.axes[j] = values[k] * (planner_ && planner_->word_is_diameter(r, j) ? 2.0 : 1.0);
  }
}

// The item's block with the tool-centre element instead of the programmed one.
nc::Block RadiusComp::rewrite(const Item& p) const {
  const Vec2 end = p.comp_end;
  nc::Block r = p.block;
  set_plane_words(r, p.comp_start, end);
  if (!p.prog.arc) return r;
  r.r.reset();
  if (trc::length(end - p.comp_start) < kTiny && trc::length(p.prog.end - p.prog.start) > kTiny) {
    // Shrunk to a point between two inside corners: no full circle.
    r.modal.motion = nc::Motion::linear;
    r.ijk[ia_].reset();
    r.ijk[ib_].reset();
    return r;
  }
  const Vec2 base = r.modal.circle_center_absolute ? Vec2{} : p.comp_start;
  r.ijk[ia_] = p.prog.center.a - base.a;
  r.ijk[ib_] = p.prog.center.b - base.b;
  return r;
}

// The arc about an outside corner: with the motion and feed of the element
// before it, reported at the line of the element after it.
nc::Block RadiusComp::corner_arc(const nc::Block& before, const nc::Block& after, Vec2 center, Vec2 from,
                                 Vec2 to, bool ccw) const {
  nc::Block c;
  c.file_id = after.file_id;
  c.line = after.line;
  c.depth = after.depth;
  c.modal = before.modal;
  c.modal.motion = ccw ? nc::Motion::ccw : nc::Motion::cw;
  set_plane_words(c, from, to);
  const Vec2 base = c.modal.circle_center_absolute ? Vec2{} : from;
  c.ijk[ia_] = center.a - base.a;
  c.ijk[ib_] = center.b - base.b;
  return c;
}

}  // namespace nck::prep
