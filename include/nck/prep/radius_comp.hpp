#pragma once
// Tool radius compensation G40/G41/G42 as a buffering stage between the
// decoder and the planner (docs/decisions.md, "Tool radius compensation"). It
// works on decoded blocks in program coordinates of the working plane, before
// the offset chain: it rewrites the plane-axis words (and circle centres) of
// each motion block to the tool-centre path and inserts corner arcs, so the
// planner plans the compensated path like any programmed one.
//
// An element's end depends on the next motion in the plane, so the stage
// holds one such block (and the blocks without plane motion after it)
// until the next one is known. Setup side: may allocate, never in tick().
#include <cstddef>
#include <expected>
#include <optional>
#include <string>
#include <vector>

#include "nck/config/machine.hpp"
#include "nck/core/diagnostic.hpp"
#include "nck/motion/offset_contour.hpp"
#include "nck/nc/block.hpp"
#include "nck/prep/units/plan_context.hpp"

namespace nck::prep {

class Planner;

// A block for the planner, or an error to raise in its place.
struct TrcOut {
  nc::Block block;
  bool inserted = false;  // a corner arc of the compensation (no block event of its own)
  std::optional<Diagnostic> error;  // raised in place of the block

  // A block handed on to the planner as it is.
  static TrcOut of(nc::Block b) {
    TrcOut o;
    o.block = std::move(b);
    return o;
  }
};

class RadiusComp {
 public:
  // At most this many blocks without plane motion may follow a compensated
  // element before the next one (TF5200 90011 beyond).
  static constexpr std::size_t kMaxHeld = 8;
  // A compensated element leaves only when this many elements after it have
  // been checked against it for crossings (docs/decisions.md, "Tool radius
  // compensation", bottlenecks).
  static constexpr std::size_t kCheckDepth = 8;

  RadiusComp(const config::Machine& m, std::size_t channel);

  // Takes the next decoded block; appends what may be planned now, in order.
  // planner: its programmed position where compensation starts, and which
  // axis words are diameters.
  void push(const nc::Block& b, const Planner& planner, std::vector<TrcOut>& out);
  // Hands out what is held (the last element ends square to its end): before
  // an error or the end of the program.
  void flush(std::vector<TrcOut>& out);
  // Drops what is held (the channel stops with an error before it).
  void discard() { queue_.clear(); }
  bool holding() const { return !queue_.empty(); }
  // Block b goes to the planner as it is (compensation off, nothing held):
  // push() would only copy it.
  bool passes_through(const nc::Block& b) const {
    return queue_.empty() && b.modal.radius_comp == nc::RadiusComp::g40;
  }

  // The compensation state a block handed on carries (for the `trc` event):
  // the mode, the D in force and its tool radius.
  struct State {
    nc::RadiusComp mode = nc::RadiusComp::g40;
    std::int32_t d = 0;
    double radius_mm = 0;
  };
  // b's state when it differs from the one reported last (selection,
  // deselection, a side change, a new D while active); call it for the
  // blocks in the order they run.
  std::optional<State> report(const nc::Block& b);

 private:
  using Vec2 = motion::trc::Vec2;
  using Element = motion::trc::Element;
  // contour: an element of the compensated contour; link: a line that moves
  // the tool onto the contour (selection, side change G41<->G42, new
  // radius); departure: the G40 line off it.
  enum class Role : std::uint8_t { contour, link, departure };
  // One motion in the plane, held until its compensated end is known and the
  // element after it has been checked too.
  struct Item {
    nc::Block block;
    Element prog;
    double o = 0;  // signed offset (left positive)
    Vec2 tip;      // theoretical tip minus nose centre of a turning tool (cutting_edge.hpp)
    Role role = Role::contour;
    // Where the nose centre starts / ends (the block's words get these plus tip).
    Vec2 comp_start, comp_end;
    // The transition round the outside corner into this element (an arc, or
    // G25 lines) and its pieces in nose-centre space.
    std::vector<nc::Block> before;
    std::vector<Element> before_pieces;
    std::vector<nc::Block> held;          // blocks without plane motion after it
  };

  bool relevant(const nc::Block& b) const;
  PlanResult forbidden(const nc::Block& b) const;
  PlanResult select_plane(const nc::Block& b, const Planner& planner);
  std::expected<Element, Diagnostic> element_of(const nc::Block& b, const Planner& planner) const;
  double offset_of(const nc::Block& b) const;
  std::expected<Vec2, Diagnostic> tip_of(const nc::Block& b) const;
  void hold(const nc::Block& b, std::vector<TrcOut>& out);
  bool close_last(Item& next, std::vector<TrcOut>& out);
  bool check_last(std::vector<TrcOut>& out);
  bool check_crossings(std::vector<TrcOut>& out);
  void emit_front(std::vector<TrcOut>& out);
  nc::Block rewrite(const Item& p) const;
  void outside_corner(Item& last, Item& next, const motion::trc::Corner& k);
  nc::Block corner_line(const nc::Block& before, const nc::Block& after, Vec2 from, Vec2 to) const;
  nc::Block corner_arc(const nc::Block& before, const nc::Block& after, Vec2 center, Vec2 from, Vec2 to,
                       bool ccw) const;
  void set_plane_words(nc::Block& r, Vec2 from, Vec2 to) const;
  // An error in place of b (d, or id with why at b's line).
  void fail(const nc::Block& b, Diagnostic d, std::vector<TrcOut>& out);
  void fail(const nc::Block& b, ErrorId id, std::string why, std::vector<TrcOut>& out);

  std::vector<config::ToolRecord> tools_;
  std::vector<std::string> axis_names_;
  const Planner* planner_ = nullptr;  // the one of the last push (diameter words)
  // At most kCheckDepth + 1 items: the last one's end waits for the next
  // motion; the ones before it leave only once kCheckDepth later elements
  // are known to be sound, so a bottleneck stops the program before the
  // tool nears it.
  std::vector<Item> queue_;
  Plane plane_ = Plane::g17;
  int ax_a_ = -1, ax_b_ = -1;    // channel axes of the plane
  std::size_t ia_ = 0, ib_ = 1;  // their I/J/K indices
  Vec2 prog_;                    // programmed end of the last plane motion
  State reported_;               // the state of the last trc event (G40 at the start)
};

}  // namespace nck::prep
