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
// here, and next.before at an outside corner). Once the last element is
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
    if (k.kind == trc::CornerKind::outside && trc::length(k.end_a - k.start_b) > kTiny) outside_corner(last, next, k);
  } else {
    last.comp_end = next.comp_start = trc::offset_end(last.prog, last.o);  // next leaves the contour
  }
  // The tip P runs on without a jump where the tool's tip vector changes
  // (a link to another turning tool, the G40 departure).
  next.comp_start = next.comp_start + last.tip - next.tip;
  if (!check_last(out)) return false;
  while (queue_.size() > kCheckDepth) emit_front(out);
  return true;
}

void RadiusComp::emit_front(std::vector<TrcOut>& out) {
  Item it = std::move(queue_.front());
  queue_.erase(queue_.begin());
  for (nc::Block& c : it.before) {
    TrcOut a = TrcOut::of(std::move(c));
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
  const Vec2 start = p.comp_start + p.tip, end = p.comp_end + p.tip;
  nc::Block r = p.block;
  set_plane_words(r, start, end);
  if (!p.prog.arc) return r;
  r.r.reset();
  if (trc::length(end - start) < kTiny && trc::length(p.prog.end - p.prog.start) > kTiny) {
    // Shrunk to a point between two inside corners: no full circle.
    r.modal.motion = nc::Motion::linear;
    r.ijk[ia_].reset();
    r.ijk[ib_].reset();
    return r;
  }
  const Vec2 base = r.modal.circle_center_absolute ? Vec2{} : start;
  r.ijk[ia_] = p.prog.center.a + p.tip.a - base.a;
  r.ijk[ib_] = p.prog.center.b + p.tip.b - base.b;
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

std::optional<RadiusComp::State> RadiusComp::report(const nc::Block& b) {
  State s;
  s.mode = b.modal.radius_comp;
  s.d = static_cast<std::int32_t>(b.modal.d);
  const auto d = static_cast<std::size_t>(std::max<std::int64_t>(b.modal.d, 0));
  s.radius_mm = d > 0 && d < tools_.size() ? tools_[d].radius_mm : 0.0;
  // Under G40 a new D changes nothing of the compensation: no event.
  if (s.mode == reported_.mode && (s.mode == nc::RadiusComp::g40 || s.d == reported_.d)) return std::nullopt;
  reported_ = s;
  return s;
}

// The transition round an outside corner (k: the offset elements leave a
// gap), in nose-centre space: an arc of the tool radius about the corner
// under G26; under G25 the elements' tangents extended (decisions.md, "Tool radius compensation").
// A line element is lengthened itself, an arc gets a line of its own.
void RadiusComp::outside_corner(Item& last, Item& next, const trc::Corner& k) {
  const Vec2 tip = last.tip;
  auto add_line = [&](Vec2 from, Vec2 to) {
    if (trc::length(to - from) < kTiny) return;
    next.before_pieces.push_back(trc::Element{false, false, from, to, {}});
    next.before.push_back(corner_line(last.block, next.block, from + tip, to + tip));
  };
  if (next.block.modal.trc_arc_corners) {
    next.before_pieces.push_back(trc::Element{true, k.arc_ccw, k.end_a, k.start_b, k.center});
    next.before.push_back(
        corner_arc(last.block, next.block, k.center + tip, k.end_a + tip, k.start_b + tip, k.arc_ccw));
    return;
  }
  const trc::LinearCorner lc = trc::linear_corner(k.end_a, trc::tangent_end(last.prog), k.start_b,
                                                  trc::tangent_start(next.prog), std::abs(last.o));
  const Vec2 first = lc.p[0], second = lc.p[lc.n - 1];
  if (last.prog.arc) add_line(k.end_a, first);
  else last.comp_end = first;
  if (lc.n == 2) add_line(first, second);
  if (next.prog.arc) add_line(second, k.start_b);
  else next.comp_start = second;
}

// A straight transition block of G25: with the feed of the element before
// it (a rapid stays rapid), reported at the line of the element after it.
nc::Block RadiusComp::corner_line(const nc::Block& before, const nc::Block& after, Vec2 from, Vec2 to) const {
  nc::Block c;
  c.file_id = after.file_id;
  c.line = after.line;
  c.depth = after.depth;
  c.modal = before.modal;
  if (c.modal.motion != nc::Motion::rapid) c.modal.motion = nc::Motion::linear;
  set_plane_words(c, from, to);
  return c;
}

}  // namespace nck::prep
