// Tool radius compensation stage (radius_comp.hpp): the bottleneck tests of
// a held element once both its ends are known — it must not run backwards,
// and its tool-centre pieces must not cross those of the elements held
// before it.
#include <cmath>
#include <fmt/format.h>

#include "nck/prep/radius_comp.hpp"

namespace nck::prep {
namespace {

namespace trc = motion::trc;
constexpr double kTiny = 1e-9;

}  // namespace

// The bottleneck test of the last element, now that both its ends are known.
bool RadiusComp::check_last(std::vector<TrcOut>& out) {
  const Item& last = queue_.back();
  if (last.role != Role::contour) return true;
  if (trc::keeps_direction(last.prog, last.comp_start, last.comp_end)) return check_crossings(out);
  const nc::Block b = last.block;
  const double r = std::abs(last.o);
  fail(b, ErrorId::KernelTrcContourViolation,
       fmt::format("with tool radius {:.4f} mm the tool centre would run backwards along this block: the tool "
                   "would cut into the contour (a bottleneck)",
                   r),
       out);
  return false;
}

namespace {

// The tool-centre piece of a closed element (nose-centre space).
trc::Element piece_of(const trc::Element& prog, trc::Vec2 from, trc::Vec2 to) {
  trc::Element e = prog;
  e.start = from;
  e.end = to;
  if (trc::length(to - from) < kTiny && trc::length(prog.end - prog.start) > kTiny) e.arc = false;  // shrunk to a point
  return e;
}

}  // namespace

// The last element, just closed, against the elements held before it on
// the same contour (same side, radius and tip): its pieces (the transition
// into it, then its own) must not cross any piece but their neighbour.
bool RadiusComp::check_crossings(std::vector<TrcOut>& out) {
  const Item& last = queue_.back();
  std::size_t first = queue_.size() - 1;  // the contour's first item still held
  while (first > 0) {
    const Item& it = queue_[first - 1];
    if (it.role != Role::contour || it.o != last.o || trc::length(it.tip - last.tip) > kTiny) break;
    --first;
  }
  // Every piece from there on, in path order, with the item it belongs to.
  std::vector<std::pair<trc::Element, std::size_t>> pieces;
  for (std::size_t i = first; i < queue_.size(); ++i) {
    const Item& it = queue_[i];
    for (const trc::Element& e : it.before_pieces) pieces.emplace_back(e, i);
    pieces.emplace_back(piece_of(it.prog, it.comp_start, it.comp_end), i);
  }
  const std::size_t own_first = pieces.size() - 1 - last.before_pieces.size();
  for (std::size_t p = own_first; p < pieces.size(); ++p)
    for (std::size_t q = 0; q + 1 < p && q < own_first; ++q) {
      if (!trc::pieces_cross(pieces[p].first, pieces[q].first)) continue;
      const nc::Block b = last.block;
      const std::uint32_t other = queue_[pieces[q].second].block.line;
      fail(b, ErrorId::KernelTrcPathsCross,
           fmt::format("with tool radius {:.4f} mm the tool-centre path of this block crosses the one of line {}: "
                       "the tool would cut into the contour (a bottleneck)",
                       std::abs(last.o), other),
           out);
      return false;
    }
  return true;
}

}  // namespace nck::prep
