// Tool radius compensation stage (radius_comp.hpp): which blocks it holds,
// how selection, deselection and changes of side or radius link the tool
// onto and off the contour, and the checks that stop a program before the
// tool would cut into the part.
#include "nck/prep/radius_comp.hpp"

#include <cmath>
#include <fmt/format.h>

#include "nck/motion/cutting_edge.hpp"
#include "nck/prep/planner.hpp"

namespace nck::prep {
namespace {

using motion::trc::Vec2;
namespace trc = motion::trc;

constexpr const char* kMainAxisNames[] = {"X", "Y", "Z"};
constexpr double kTiny = 1e-9;

bool is_arc(const nc::Block& b) { return b.modal.motion == nc::Motion::cw || b.modal.motion == nc::Motion::ccw; }

constexpr nc::GCodeSet kNotWithTrc{nc::GCode::g74,  nc::GCode::g92,  nc::GCode::g101,
                                   nc::GCode::g102, nc::GCode::g130, nc::GCode::g132};

}  // namespace

RadiusComp::RadiusComp(const config::Machine& m, std::size_t channel) {
  if (channel < m.channel_data.size()) tools_ = m.channel_data[channel].tools;
  for (const config::ChannelAxis& a : m.channels[channel].axes) axis_names_.push_back(a.name);
}

// A motion in the working plane: the blocks compensation works on.
bool RadiusComp::relevant(const nc::Block& b) const {
  const nc::Motion m = b.modal.motion;
  if (m != nc::Motion::rapid && m != nc::Motion::linear && !is_arc(b)) return false;
  if (b.manual_g || b.g_nonmodal.has_any(kNotWithTrc) || b.g_nonmodal.has(nc::GCode::g100)) return false;
  const PlaneAxes pa = plane_axes(b.modal.plane);
  for (int k : {pa.first, pa.second}) {
    for (std::size_t j = 0; j < axis_names_.size() && j < kMaxAxes; ++j)
      if (axis_names_[j] == kMainAxisNames[k] && b.axes[j]) return true;
    if (is_arc(b) && b.ijk[static_cast<std::size_t>(k)]) return true;
  }
  return false;
}

// What may not be programmed while compensation is selected (docs/nc-language.md,
// "Tool radius compensation"; TF5200 20802, 20671, 20608, 20049, 20133).
PlanResult RadiusComp::forbidden(const nc::Block& b) const {
  auto selected = [&](ErrorId id) {
    return block_error(id, b, fmt::format("{} while tool radius compensation is selected",
                                          nc::hash_command_name(*b.hash)));
  };
  if (!queue_.empty() && b.modal.plane != plane_)
    return block_error(ErrorId::KernelTrcPlaneChange, b,
                       fmt::format("G{} while tool radius compensation is active", static_cast<int>(b.modal.plane)));
  if (b.g_nonmodal.has(nc::GCode::g100))
    return block_error(ErrorId::KernelTrcMeasure, b, "measuring run G100 while tool radius compensation is selected");
  if (b.hash) {
    const nc::HashCommand& h = *b.hash;
    if (const auto* cs = std::get_if<nc::CoordSystem>(&h); cs && cs->op != nc::CsOp::def && cs->op != nc::CsOp::add)
      return selected(ErrorId::FrCsChangeWithTrc);
    if (std::holds_alternative<nc::Mcs>(h) || std::holds_alternative<nc::Ecs>(h))
      return selected(ErrorId::FrCsChangeWithTrc);
    if (const auto* t = std::get_if<nc::Tlc>(&h); t && t->on)
      return block_error(ErrorId::FrTlcWithTrc, b, "#TLC ON while tool radius compensation is selected");
    if (std::holds_alternative<nc::PSet>(h) || std::holds_alternative<nc::PReset>(h))
      return selected(ErrorId::KernelTrcPreset);
    if (std::holds_alternative<nc::CAxis>(h) || std::holds_alternative<nc::Face>(h) ||
        std::holds_alternative<nc::Cylinder>(h) || std::holds_alternative<nc::Rotation>(h) ||
        std::holds_alternative<nc::SuppressOffsets>(h) || std::holds_alternative<nc::GetManualOffsets>(h))
      return selected(ErrorId::KernelTrcNotAllowed);
  }
  const nc::Motion m = b.modal.motion;
  const bool thread = m == nc::Motion::thread || m == nc::Motion::tap || m == nc::Motion::tap_rigid ||
                      m == nc::Motion::tap_retract;
  if (b.manual_g || b.g_nonmodal.has_any(kNotWithTrc) || (thread && b.has_axis_words()))
    return block_error(ErrorId::KernelTrcNotAllowed, b,
                       "G74/G92/G101/G102, G201/G202 and thread or tapping motions are not possible while tool "
                       "radius compensation is selected");
  return {};
}

// Selection: the plane's axes, and where the tool stands in program coordinates.
PlanResult RadiusComp::select_plane(const nc::Block& b, const Planner& planner) {
  plane_ = b.modal.plane;
  const PlaneAxes pa = plane_axes(plane_);
  ia_ = static_cast<std::size_t>(pa.first);
  ib_ = static_cast<std::size_t>(pa.second);
  ax_a_ = ax_b_ = -1;
  for (std::size_t j = 0; j < axis_names_.size() && j < kMaxAxes; ++j) {
    if (axis_names_[j] == kMainAxisNames[ia_]) ax_a_ = static_cast<int>(j);
    if (axis_names_[j] == kMainAxisNames[ib_]) ax_b_ = static_cast<int>(j);
  }
  if (ax_a_ < 0 || ax_b_ < 0)
    return block_error(ErrorId::KernelAxisNotInPlane, b,
                       fmt::format("tool radius compensation in G{} needs axes {} and {}", static_cast<int>(plane_),
                                   kMainAxisNames[ia_], kMainAxisNames[ib_]));
  const motion::AxisVector& pcs = planner.planned_pcs();
  prog_ = {pcs[static_cast<std::size_t>(ax_a_)], pcs[static_cast<std::size_t>(ax_b_)]};
  return {};
}

// The tool radius of the D in force with the side: left (G41) positive.
double RadiusComp::offset_of(const nc::Block& b) const {
  if (b.modal.radius_comp == nc::RadiusComp::g40) return 0;
  const auto d = static_cast<std::size_t>(std::max<std::int64_t>(b.modal.d, 0));
  const double r = d > 0 && d < tools_.size() ? tools_[d].radius_mm : 0.0;
  return b.modal.radius_comp == nc::RadiusComp::g41 ? r : -r;
}

// The theoretical tip P of a turning tool relative to its nose centre, in
// the plane (G18: Z, X). Only G18 has the longitudinal axis first and the
// facing axis second, as the positions are defined; a position 1..8 in
// another plane is refused rather than applied the wrong way round.
std::expected<Vec2, Diagnostic> RadiusComp::tip_of(const nc::Block& b) const {
  if (b.modal.radius_comp == nc::RadiusComp::g40) return Vec2{};
  const auto d = static_cast<std::size_t>(std::max<std::int64_t>(b.modal.d, 0));
  if (d == 0 || d >= tools_.size()) return Vec2{};
  const config::ToolRecord& t = tools_[d];
  const Vec2 tip = trc::tip_from_centre(t.typ == 1 ? t.cutting_edge_pos : 0, t.radius_mm);
  if (trc::length(tip) < kTiny || plane_ == Plane::g18) return tip;
  return block_error(ErrorId::KernelTrcEdgePlane, b,
                     fmt::format("turning tool D{} has cutting-edge position {} (wz[{}].srk_lage), defined in the "
                                 "Z X plane (G18), with tool radius compensation in G{}",
                                 d, t.cutting_edge_pos, d, static_cast<int>(plane_)));
}

// The programmed element of b, from the programmed end of the last one.
std::expected<motion::trc::Element, Diagnostic> RadiusComp::element_of(const nc::Block& b,
                                                                      const Planner& planner) const {
  Element e;
  e.start = prog_;
  e.end = prog_;
  double* end[2] = {&e.end.a, &e.end.b};
  const int axes[2] = {ax_a_, ax_b_};
  for (int k = 0; k < 2; ++k) {
    const auto j = static_cast<std::size_t>(axes[k]);
    if (!b.axes[j]) continue;
    const double v = *b.axes[j] / (planner.word_is_diameter(b, j) ? 2.0 : 1.0);
    *end[k] = b.modal.absolute ? v : *end[k] + v;
  }
  if (!is_arc(b)) return e;
  e.arc = true;
  e.ccw = b.modal.motion == nc::Motion::ccw;
  const auto& ci = b.ijk[ia_];
  const auto& cj = b.ijk[ib_];
  if (ci || cj) {
    const Vec2 base = b.modal.circle_center_absolute ? Vec2{} : e.start;
    e.center = base + Vec2{ci.value_or(0), cj.value_or(0)};
    return e;
  }
  if (!b.r) return block_error(ErrorId::KernelArcNoCenter, b, "program I/J/K or R with G2/G3");
  // R: the centre on the chord's perpendicular; R > 0 the shorter arc.
  const Vec2 chord = e.end - e.start;
  const double half = trc::length(chord) / 2;
  const double h2 = *b.r * *b.r - half * half;
  if (half < kTiny || h2 < -1e-9)
    return half < kTiny ? block_error(ErrorId::KernelArcFullCircleWithR, b, "a full circle cannot be programmed with R")
                        : block_error(ErrorId::KernelArcRadiusTooSmall, b,
                                      fmt::format("circle: R is smaller than half the chord (R {:.4f} mm, half "
                                                  "the chord {:.4f} mm, difference {:.4f} mm)",
                                                  std::fabs(*b.r), half, half - std::fabs(*b.r)));
  const double side = (e.ccw ? 1.0 : -1.0) * (*b.r > 0 ? 1.0 : -1.0);
  e.center = e.start + 0.5 * chord + (side * std::sqrt(std::max(h2, 0.0)) / (2 * half)) * trc::left_of(chord);
  return e;
}

// An error in place of b. What is held does not run: its end would
// depend on the block refused, and ending it anyhow could cut into the part.
void RadiusComp::fail(const nc::Block& b, Diagnostic d, std::vector<TrcOut>& out) {
  queue_.clear();
  TrcOut e;
  e.block = b;
  e.error = std::move(d);
  out.push_back(std::move(e));
}

void RadiusComp::fail(const nc::Block& b, ErrorId id, std::string why, std::vector<TrcOut>& out) {
  fail(b, block_error(id, b, std::move(why)).error(), out);
}

// b waits behind the last element, whose end needs the next motion in the
// plane. A block that only repeats where the plane axes stand counts like one
// without plane axes (TF5200 90011: blocks without motion data for the
// compensation), so what waits is bounded whatever the program.
void RadiusComp::hold(const nc::Block& b, std::vector<TrcOut>& out) {
  if (queue_.back().held.size() >= kMaxHeld)
    return fail(b, ErrorId::KernelTrcTooManyHeld,
                fmt::format("more than {} blocks without motion in the plane follow each other under tool "
                            "radius compensation",
                            kMaxHeld),
                out);
  queue_.back().held.push_back(b);
}

void RadiusComp::push(const nc::Block& b, const Planner& planner, std::vector<TrcOut>& out) {
  planner_ = &planner;
  if (passes_through(b)) {
    out.push_back(TrcOut::of(b));
    return;
  }
  if (auto r = forbidden(b); !r) return fail(b, r.error(), out);
  if (b.program_end) {
    flush(out);
    out.push_back(TrcOut::of(b));
    return;
  }
  if (!relevant(b)) {
    if (queue_.empty()) {
      out.push_back(TrcOut::of(b));
      return;
    }
    return hold(b, out);
  }
  if (queue_.empty())
    if (auto r = select_plane(b, planner); !r) return fail(b, r.error(), out);
  auto el = element_of(b, planner);
  if (!el) return fail(b, el.error(), out);
  if (!el->arc && trc::length(el->end - el->start) < kTiny) {
    // No motion in the plane after all: the plane axes stay where the tool is.
    nc::Block still = b;
    still.axes[static_cast<std::size_t>(ax_a_)].reset();
    still.axes[static_cast<std::size_t>(ax_b_)].reset();
    if (queue_.empty()) return out.push_back(TrcOut::of(still));
    return hold(still, out);
  }
  Item item;
  item.block = b;
  item.prog = *el;
  item.o = offset_of(b);
  const auto tip = tip_of(b);
  if (!tip) return fail(b, tip.error(), out);
  item.tip = *tip;
  if (b.modal.radius_comp == nc::RadiusComp::g40) item.role = Role::departure;
  else if (queue_.empty() || item.o != queue_.back().o || trc::length(item.tip - queue_.back().tip) > kTiny)
    item.role = Role::link;
  if (item.role != Role::contour && el->arc) {
    if (queue_.empty()) return fail(b, ErrorId::KernelTrcSelectInArc, "tool radius compensation selected in a circle block", out);
    if (item.role == Role::departure)
      return fail(b, ErrorId::KernelTrcChangeInArc, "tool radius compensation deselected (G40) in a circle block", out);
    if ((item.o > 0) == (queue_.back().o > 0))
      return fail(b, ErrorId::KernelTrcRadiusChangeInArc, "the tool radius changes in a circle block", out);
    return fail(b, ErrorId::KernelTrcChangeInArc, "G41/G42 side change in a circle block", out);
  }
  if (item.role == Role::contour && el->arc && trc::offset_radius(*el, item.o) <= kTiny)
    return fail(b, ErrorId::KernelTrcArcTooSmall,
                fmt::format("the circle's radius {:.4f} mm is not larger than the tool radius {:.4f} mm on its "
                            "inner side",
                            trc::arc_radius(*el), std::abs(item.o)),
                out);
  if (queue_.empty()) {
    item.comp_start = prog_ - item.tip;  // selection: the tool (its tip P) stands on the programmed point
  } else if (!close_last(item, out)) {
    return;
  }
  prog_ = el->end;
  queue_.push_back(std::move(item));
  if (queue_.back().role == Role::departure) flush(out);  // it ends on the programmed point
}

}  // namespace nck::prep
