#pragma once
// Plane geometry of tool radius compensation (G41/G42): the path of the
// tool centre at a signed distance from a programmed contour of lines and
// arcs, the corner between two offset elements and the bottleneck tests.
// Pure functions of two plane coordinates (a = first plane axis, b =
// second; G17 X Y, G18 Z X, G19 Y Z), so "left" is the same rule in every
// plane. Setup side only.
//
// Signed offset o: the tool radius with the side, positive to the LEFT of
// the direction of travel (G41), negative to the right (G42). A negative
// tool radius flips the side on its own.
#include <cstdint>

namespace nck::motion::trc {

struct Vec2 {
  double a = 0, b = 0;
};
constexpr Vec2 operator+(Vec2 p, Vec2 q) { return {p.a + q.a, p.b + q.b}; }
constexpr Vec2 operator-(Vec2 p, Vec2 q) { return {p.a - q.a, p.b - q.b}; }
constexpr Vec2 operator*(double k, Vec2 p) { return {k * p.a, k * p.b}; }
constexpr double dot(Vec2 p, Vec2 q) { return p.a * q.a + p.b * q.b; }
constexpr double cross(Vec2 p, Vec2 q) { return p.a * q.b - p.b * q.a; }
// The unit normal to the left of direction t.
constexpr Vec2 left_of(Vec2 t) { return {-t.b, t.a}; }
double length(Vec2 p);

// One programmed element in the plane: a line, or an arc about `center`
// (start == end is a full circle).
struct Element {
  bool arc = false;
  bool ccw = false;
  Vec2 start, end, center;
};

double arc_radius(const Element& e);
// Unit direction of travel where the element starts / ends (a line of zero
// length has none: {0, 0}).
Vec2 tangent_start(const Element& e);
Vec2 tangent_end(const Element& e);
// Radius of the tool-centre arc: smaller on the side of the centre (a left
// offset of a counter-clockwise arc), larger on the other. <= 0 means the
// tool does not fit into the arc (bottleneck).
double offset_radius(const Element& e, double o);
// The element's points moved by o along its normal.
Vec2 offset_start(const Element& e, double o);
Vec2 offset_end(const Element& e, double o);

enum class CornerKind : std::uint8_t {
  smooth,   // tangent transition: both offset elements meet without help
  inside,   // the offset elements overlap: they end / start at their intersection
  outside,  // they leave a gap: closed by an arc of the tool radius about the corner
};

enum class CornerError : std::uint8_t { none, no_intersection };

struct Corner {
  CornerKind kind = CornerKind::smooth;
  CornerError error = CornerError::none;
  Vec2 end_a;          // where the tool centre leaves element a
  Vec2 start_b;        // where it enters element b
  Vec2 center;         // outside: the centre of the corner arc (the programmed corner)
  bool arc_ccw = false;  // outside: direction of the corner arc
};

// The corner at the point where a ends and b starts.
Corner corner(const Element& a, const Element& b, double o);

// G25: the straight transition round an outside corner. The tangents of
// the two offset elements, ta at end_a and tb at start_b, are extended: up
// to a 90 deg turn to the point where they meet (one point); beyond it each
// by the tool radius r, joined by a line (two points). The path runs
// end_a -> p[0] (-> p[1]) -> start_b.
struct LinearCorner {
  int n = 0;
  Vec2 p[2];
};
LinearCorner linear_corner(Vec2 end_a, Vec2 ta, Vec2 start_b, Vec2 tb, double r);

// Angle swept from s to e about c in the element's direction, in (0, 2*pi];
// s == e gives a full turn.
double sweep_rad(Vec2 c, Vec2 s, Vec2 e, bool ccw);
// Whether the compensated element from s to e still runs the way the
// programmed one does. False is a bottleneck: the tool would have to travel
// backwards along the contour, cutting into it (a slot narrower than the
// tool, a step smaller than the tool radius between two inside corners).
bool keeps_direction(const Element& programmed, Vec2 s, Vec2 e);

// Whether two pieces of a tool-centre path (a line from start to end, or an
// arc about center) cross at a point inside both, more than 1e-6 mm from
// their ends: the offset contour runs over itself, so the tool would cut
// into the part there (a bottleneck between blocks that are not
// neighbours). Pieces on one line or one circle never count; a piece of
// zero length neither.
bool pieces_cross(const Element& p, const Element& q);

}  // namespace nck::motion::trc
