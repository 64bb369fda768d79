// Gallery, part 2: the figures 4.1-4.11 of seed 000 (section 4.1 of the thesis: triangles,
// iso-rectangles, bounding boxes and circles of T2). Every fact a label states (a membership,
// an equality of vertices, a crossing point, an undefined construction) is computed here by
// the library; undefined constructions are caught as t2::Undefined and reported as such.
#include <optional>
#include <string>
#include <variant>

#include "gallery.hpp"

namespace gallery {
namespace {

using t2::T1;

/// "inside", "on the boundary" or "outside", from the exact predicate.
const char* where(t2::BoundedSide s) {
  return s == t2::BoundedSide::inside ? "inside" : s == t2::BoundedSide::boundary ? "on the boundary" : "outside";
}

// ---- 4.1 triangle ------------------------------------------------------------------------

void fig_4_1() {
  dr::Figure f;
  const Point a(1, -1.4, -1), b(1, 1.6, -0.6), c(1, 0.2, 1.5);
  const t2::Triangle t(a, b, c);
  f.add(t, st(pal::blue).width(2).fill(pal::blue));
  f.add(a, lab(pal::blue, "a", -135));
  f.add(b, lab(pal::blue, "b", -45));
  f.add(c, lab(pal::blue, "c", 90));
  // A point and its antipode: the triangle of T² holds at most one of the two.
  const Point s(1, 0.1, 0);
  f.add(s, lab(pal::green, std::string("s: ") + where(t2::bounded_side(t, s)), 135).size(3));
  const Point ns = t2::antipode(s);
  f.add(ns, lab(pal::red, std::string("¬s: ") + where(t2::bounded_side(t, ns)), -45).size(3));
  dr::save_both(f, plane(2.2), sphere(55, -60), out_dir() / "fig-4-1-triangle.svg");
}

// ---- 4.2-4.4 iso-rectangles --------------------------------------------------------------

/// Labels the corners a, b, c, d of r (by name, whatever the orientation); corners that
/// coincide share one label, e.g. "b = c", found by comparing the points.
void label_corners(dr::Figure& f, const Point (&v)[4], const double (&angle)[4], const char* colour) {
  static const char* const names[4] = {"a", "b", "c", "d"};
  for (int i = 0; i < 4; ++i) {
    bool seen = false;
    for (int j = 0; j < i; ++j) seen = seen || v[j] == v[i];
    if (seen) continue;
    std::string text = names[i];
    for (int j = i + 1; j < 4; ++j)
      if (v[j] == v[i]) text += std::string(" = ") + names[j];
    f.add(v[i], lab(colour, text, angle[i]));
  }
}

void fig_4_2() {
  dr::Figure f;
  const t2::IsoRect r(Point(1, -1.2, -0.8), T1(1, 2.4), T1(1, 1.6));
  f.add(r, st(pal::blue).width(2).fill(pal::blue));
  const Point v[4] = {r.corner(0), r.corner(1), r.corner(2), r.corner(3)};
  label_corners(f, v, {-135, -45, 45, 135}, pal::blue);
  f.arrow(v[0], v[1], st(pal::light_grey).width(1).label("Δx").label_angle(-90));
  f.arrow(v[0], v[3], st(pal::light_grey).width(1).label("Δy").label_angle(180));
  dr::save_both(f, plane(2.2), sphere(55, -60), out_dir() / "fig-4-2-isorect.svg");
}

void fig_4_3() {
  dr::Figure f;
  const t2::IsoRect r(Point(1, -1.2, -0.8), T1::plus_infinity(), T1(1, 1.6));
  f.add(r, st(pal::blue).width(2).fill(pal::blue));
  const Point v[4] = {r.corner(0), r.corner(1), r.corner(2), r.corner(3)};
  label_corners(f, v, {-135, 180, 45, 135}, pal::blue);
  dr::save_both(f, plane(2.2), sphere(55, -60), out_dir() / "fig-4-3-isorect-degenerate.svg");
}

void fig_4_4() {
  dr::Figure f;
  const Point a(1, -1, -1);
  const T1 dx(-1, 1), dy(1, 2.5);  // Δx "beyond infinity": w < 0
  std::string verdict;
  try {
    (void)t2::IsoRect(a, dx, dy);
    verdict = "iso_rect(a, Δx, Δy) is defined";
  } catch (const t2::Undefined&) {
    verdict = "iso_rect(a, Δx, Δy): undefined";
  }
  // The corners the formulas of §4.1.7 would give, to show why: ab and dc cross on Ω.
  Point v[4] = {a, a, a, a};
  for (int i = 0; i < 4; ++i) v[i] = t2::detail::rect_vertex(a, dx, dy, i);
  for (int i = 0; i < 4; ++i) f.segment(v[i], v[(i + 1) % 4], st(pal::red).width(2));
  label_corners(f, v, {-135, -45, 45, 135}, pal::red);
  const auto x = t2::intersection(t2::Segment(v[0], v[1]), t2::Segment(v[3], v[2]));
  if (const auto* p = std::get_if<Point>(&x)) f.add(*p, lab(pal::black, "ab ∩ dc", -150).marker(dr::Marker::cross).size(5));
  f.title(verdict);
  dr::save_both(f, plane(3), sphere(35, -55), out_dir() / "fig-4-4-isorect-undefined.svg");
}

// ---- 4.5-4.6 bounding boxes ------------------------------------------------------------

void fig_4_5() {
  dr::Figure f;
  const t2::BBox b1(Point(1, -1, 0), T1::plus_infinity(), T1(1, 1.8));   // x in [-1, +inf)
  const t2::BBox b2(Point(1, 1, -1.5), T1::minus_infinity(), T1(1, 2.5));  // x in (-inf, 1]
  f.add(b1, st(pal::blue).width(2).fill(pal::blue));
  f.add(b2, st(pal::orange).width(2).fill(pal::orange));
  f.label(Point(1, 1.8, 1.2), "b₁", st(pal::blue));
  f.label(Point(1, -1.2, -0.9), "b₂", st(pal::orange));
  std::string verdict;
  try {
    (void)(b1 + b2);
    verdict = "b₁ + b₂ is defined";
  } catch (const t2::Undefined&) {
    verdict = "b₁ + b₂: undefined";
  }
  // Where each box reaches Ω: antipodal points, which no box (no convex set) can hold both of.
  const auto o1 = t2::omega_part(b1), o2 = t2::omega_part(b2);
  if (o1 && o2) {
    const bool anti = o1->source() == t2::antipode(o2->source());
    f.add(o1->source(), lab(pal::blue, "u", 90));
    f.add(o2->source(), lab(pal::orange, anti ? "¬u" : "v", 90));
  }
  f.title(verdict);
  dr::save_both(f, plane(4), sphere(60, -90), out_dir() / "fig-4-5-bbox-union-undefined.svg");
}

void fig_4_6() {
  dr::Figure f;
  const t2::BBox b1(Point(1, 1, -2.2), T1::minus_infinity(), T1(1, 1.6));   // front, x in (-inf, 1]
  const t2::BBox b2(Point(-1, 1, -0.6), T1::plus_infinity(), T1(1, 1.6));   // back, x in [-1, +inf)
  f.add(b1, st(pal::blue).width(2).fill(pal::blue));
  f.add(b2, st(pal::orange).width(2).fill(pal::orange));
  f.label(Point(1, -2, -1.4), "b₁ (front)", st(pal::blue));
  f.label(Point(-1, -2.5, -1.4), "b₂ (back)", st(pal::orange));
  const auto x = t2::intersection(b1, b2);
  if (const auto* s = std::get_if<t2::Segment>(&x); s && s->is_degenerate()) {
    f.add(s->source(), lab(pal::black, "b₁ ∩ b₂ = " + t2::to_string(s->source()), 0).marker(dr::Marker::square).size(4));
  } else if (s) {
    f.add(*s, lab(pal::black, "b₁ ∩ b₂", 0).width(3));
  } else if (std::holds_alternative<std::monostate>(x)) {
    f.title("b₁ ∩ b₂ is empty");
  } else {
    f.title("b₁ ∩ b₂ is a box");
  }
  dr::save_both(f, plane(4), sphere(15, -140), out_dir() / "fig-4-6-bbox-intersection.svg");
}

// ---- 4.7-4.11 circles -------------------------------------------------------------------

/// The radius kind of every circle, if they agree ("finite", ...), for a title.
std::string kinds(std::initializer_list<t2::Circle> cs) {
  const t2::RadiusKind k = radius_kind(*cs.begin());
  for (const auto& c : cs)
    if (radius_kind(c) != k) return "radius kinds differ";
  return std::string("radius_kind: ") + t2::to_string(k);
}

/// A circle given by its centre and boundary point, with both marked and its orientation arrow.
void circle_cp(dr::Figure& f, const t2::Circle& c, const char* colour, const std::string& cname,
               const std::string& pname, double cangle, double pangle) {
  f.add(c, st(colour).width(2).fill(colour).arrow());
  f.add(c.center(), lab(colour, cname, cangle).marker(dr::Marker::cross).size(4));
  f.add(c.boundary_point(), lab(colour, pname, pangle));
}

void fig_4_7() {  // finite radius, front side
  dr::Figure f;
  const t2::Circle c1(Point(1, -1, 0.5), Point(1, -0.1, 0.5), t2::POSITIVE);
  circle_cp(f, c1, pal::blue, "c₁", "p₁", -90, 0);
  // The circle through three points: its centre is computed, its orientation is Δ(p, q, r).
  const Point p(1, 0.4, -0.6), q(1, 1.5, -1.3), r(1, 1.4, 0.1);
  const t2::Circle c2 = t2::circle_through(p, q, r);
  f.add(c2, st(pal::orange).width(2).fill(pal::orange).arrow());
  f.add(c2.center(), lab(pal::orange, "c₂", -90).marker(dr::Marker::cross).size(4));
  f.add(p, lab(pal::orange, "p", 180));
  f.add(q, lab(pal::orange, "q", -90));
  f.add(r, lab(pal::orange, "r", 45));
  f.title(kinds({c1, c2}));
  dr::save_both(f, plane(2.5), sphere(80, -60), out_dir() / "fig-4-7-circles-finite-front.svg");
}

void fig_4_8() {  // finite radius, back side
  dr::Figure f;
  const t2::Circle c1(Point(-1, 1, -0.5), Point(-1, 0.1, -0.5), t2::POSITIVE);
  circle_cp(f, c1, pal::blue, "c₁", "p₁", -90, 180);
  // The circle with diameter pq: its centre is the midpoint of p and q.
  const Point p(-1, -0.3, 0.5), q(-1, -1.7, 1.1);
  const t2::Circle c2 = t2::circle_from_diameter(p, q, t2::NEGATIVE);
  f.add(c2, st(pal::orange).width(2).fill(pal::orange).arrow());
  f.add(c2.center(), lab(pal::orange, "c₂", -90).marker(dr::Marker::cross).size(4));
  f.segment(p, q, st(pal::orange).width(1));
  f.add(p, lab(pal::orange, "p", 0));
  f.add(q, lab(pal::orange, "q", 180));
  f.title(kinds({c1, c2}));
  dr::save_both(f, plane(2.5), sphere(-80, -60), out_dir() / "fig-4-8-circles-finite-back.svg");
}

/// Figures 4.9 and 4.10: a circle of radius "beyond infinity" drawn on side s (+1 front, −1
/// back), its centre c on the other side, and a point x inside the drawn disk whose distance
/// to c is compared with p's by the exact predicate.
void beyond(double s, const std::string& out, double lat) {
  dr::Figure f;
  const t2::Circle c1(Point(-s, 0.3 * s, -0.1 * s), Point(s, 1.1 * s, 0.1 * s), t2::POSITIVE);
  f.add(c1, st(pal::blue).width(2).fill(pal::blue).arrow());
  const Point c = c1.center(), p = c1.boundary_point();
  f.add(c, lab(pal::red, s > 0 ? "c (back)" : "c (front)", -45).marker(dr::Marker::cross).size(4));
  f.add(t2::antipode(c), lab(pal::blue, "¬c", 135).size(3));
  f.add(p, lab(pal::blue, "p", 0));
  const Point x(s, 0.1 * s, -0.6 * s);
  const t2::Sign cmp = t2::compare_distance(x, p, c);
  f.add(x, lab(pal::green, std::string("x: d(x, c) ") + (cmp > 0 ? ">" : cmp < 0 ? "<" : "=") + " d(p, c)", 90).size(3));
  f.title(kinds({c1}));
  dr::save_both(f, plane(2.5), sphere(lat, -60), out_dir() / out);
}
void fig_4_9() { beyond(1, "fig-4-9-circles-beyond-front.svg", 70); }
void fig_4_10() { beyond(-1, "fig-4-10-circles-beyond-back.svg", -70); }

void fig_4_11() {  // infinite radius
  dr::Figure f;
  // Two circles with the same centre at infinity and the same (infinite) radius: two lines.
  const Point c(0, 1, 0);
  const t2::Circle l1(c, Point(1, 1.2, 0.8)), l2(c, Point(1, -1.5, -0.8));
  f.add(l1, st(pal::blue).width(2).arrow());
  f.add(l2, st(pal::orange).width(2).arrow());
  f.add(c, lab(pal::black, "c", 180).marker(dr::Marker::cross).size(4));
  f.add(l1.boundary_point(), lab(pal::blue, "p₁", 0));
  f.add(l2.boundary_point(), lab(pal::orange, "p₂", 180));
  // A proper centre with its boundary point on Ω: the circle is Ω itself.
  const t2::Circle o(Point(1, 0.2, -0.9), Point(0, 1, 1));
  f.add(o, st(pal::green).width(2).arrow());
  f.add(o.center(), lab(pal::green, "c₃", -90).marker(dr::Marker::cross).size(4));
  f.add(o.boundary_point(), lab(pal::green, "p₃", 45));
  f.title(kinds({l1, l2, o}));
  dr::save_both(f, plane(2.5), sphere(30, -60), out_dir() / "fig-4-11-circles-infinite.svg");
}

}  // namespace

std::vector<Entry> thesis4_primitives() {
  return {
      {"4.1", "fig-4-1-triangle.svg",
       "A triangle of T² in the planar model (left) and on the sphere (right). s is inside and its antipode ¬s "
       "outside (exact bounded_side): a triangle never holds two antipodal points.",
       fig_4_1},
      {"4.2", "fig-4-2-isorect.svg",
       "An iso-rectangle on the front side, stored as a proper corner a and two extents Δx, Δy (values of T¹ with "
       "w ≥ 0); b, c, d follow from them. The seed's Cartesian formulas for Y_c and Y_d have typos (x for y); the "
       "library uses the corrected ones.",
       fig_4_2},
      {"4.3", "fig-4-3-isorect-degenerate.svg",
       "Δx = +∞: b and c both become the point at infinity of the x axis (the equality is computed), so the "
       "rectangle degenerates to a half-strip with three distinct vertices, a triangle on the sphere.",
       fig_4_3},
      {"4.4", "fig-4-4-isorect-undefined.svg",
       "Δx \"beyond infinity\" (w < 0) puts b and c on the back side: the sides ab and dc then cross on Ω (the "
       "crossing is computed), the boundary is not simple, and the library refuses the rectangle (t2::Undefined).",
       fig_4_4},
      {"4.5", "fig-4-5-bbox-union-undefined.svg",
       "Two front boxes, b₁ unbounded towards +x and b₂ towards −x. Their union would reach both u and its antipode "
       "¬u on Ω (checked), and no box does: operator+ throws t2::Undefined.",
       fig_4_5},
      {"4.6", "fig-4-6-bbox-intersection.svg",
       "A front box b₁ and a back box b₂, both unbounded towards the point [0, −1, 0] of Ω: on the back, Cartesian "
       "+x leads there, which is why b₂ runs to the right in the planar model. Their intersection, computed, is "
       "that one point of Ω.",
       fig_4_6},
      {"4.7", "fig-4-7-circles-finite-front.svg",
       "Circles of finite radius on the front: c₁ given by its centre and a boundary point p₁, and the circle "
       "through p, q, r, whose centre c₂ the library computes. Arrows show the orientation (the second one is "
       "Δ(p, q, r)).",
       fig_4_7},
      {"4.8", "fig-4-8-circles-finite-back.svg",
       "Circles of finite radius on the back (dashed, hatched): the second has diameter pq and its centre c₂ is "
       "their midpoint. A positive circle on the back (c₁) runs clockwise as drawn, since the drawing of the back "
       "side is mirrored.",
       fig_4_8},
      {"4.9", "fig-4-9-circles-beyond-front.svg",
       "Radius \"beyond infinity\": centre c on the back, circle on the front (we read the thesis's \"no aquém\" as "
       "the side of the circle). It is drawn like the finite circle around ¬c, but the shaded disk holds the points "
       "farther from c than the circle: d(x, c) > d(p, c) by the exact compare_distance.",
       fig_4_9},
      {"4.10", "fig-4-10-circles-beyond-back.svg",
       "The same with the sides exchanged: centre c on the front, the circle on the back; again x in the shaded "
       "disk around ¬c is farther from c than p is.",
       fig_4_10},
      {"4.11", "fig-4-11-circles-infinite.svg",
       "Infinite radius. With its centre c on Ω a circle is a line: through p₁ and through p₂ two different circles "
       "with the same centre and the same radius, which is why a circle is stored by a boundary point, not a "
       "radius. A proper centre c₃ with its boundary point p₃ on Ω gives Ω itself (green).",
       fig_4_11},
  };
}

}  // namespace gallery
