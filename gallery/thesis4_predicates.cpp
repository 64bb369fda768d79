// Gallery, part 3: the figures 4.12-4.20 of seed 000 (chapter 4 of the thesis, §4.3: relative
// distances to points at infinity, midpoints, membership in a segment, angles). Every fact a
// figure states (which point is nearer, which side, on the segment or not, which angle is
// larger) is the answer of the library's exact predicates, turned into text here.
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "gallery.hpp"

namespace gallery {
namespace {

using t2::Sign;

// The seed's formulas that the figures show failing (§4.3.2 and Algorithm 1, §4.3.7). They
// are not part of the library: chapter 03's program teaches them.
Point naive_midpoint(const Point& p, const Point& q) {  // [2 w0 w1, x0 w1 + x1 w0, y0 w1 + y1 w0]
  return Point(2 * p.w() * q.w(), p.x() * q.w() + q.x() * p.w(), p.y() * q.w() + q.y() * p.w());
}
Sign algorithm_1(const Point& p, const Point& q) {  // "p > q" iff Δ(p,o,q)·Δ(p,o,d) = +1
  const Point o(1, 0, 0), d(0, 1, 0);
  if (t2::orient(p, o, q) * t2::orient(p, o, d) == t2::POSITIVE) return t2::POSITIVE;
  return t2::orient(p, o, q) == t2::ZERO ? t2::ZERO : t2::NEGATIVE;
}

/// "nearer", "farther", "as near": how compare_distance(a, b, c) places a against b.
std::string nearer_text(Sign s) { return s < 0 ? "nearer" : (s > 0 ? "farther" : "as near"); }
/// "nearer to x", "farther from x", "as near to x".
std::string near_to(Sign s, const std::string& x) { return s > 0 ? "farther from " + x : nearer_text(s) + " to " + x; }
/// The sign as "> 0", "< 0" or "= 0".
std::string sign_text(Sign s) { return s > 0 ? "> 0" : (s < 0 ? "< 0" : "= 0"); }

/// The claims of a caption are checked by the program; a failed check is a bug in the gallery.
void require(bool ok, const char* what) {
  if (!ok) throw std::logic_error(std::string("gallery figure 4.x: ") + what);
}

/// A polyline of `n` proper points on the circle of radius `rad` around the Cartesian point
/// (cx, cy), from angle a0 to angle a1 (radians, counter-clockwise): an angle mark.
std::vector<Point> arc(double cx, double cy, double rad, double a0, double a1, int n = 24) {
  std::vector<Point> v;
  for (int i = 0; i <= n; ++i) {
    const double t = a0 + (a1 - a0) * i / n;
    v.push_back(Point(1, cx + rad * std::cos(t), cy + rad * std::sin(t)));
  }
  return v;
}

/// The angle of a point at infinity [0, x, y] (drawing only: never used to decide anything).
double theta(const Point& d) { return std::atan2(d.y(), d.x()); }

// ---------------------------------------------------------------------------------------------
// 4.12: two proper points and one point at infinity: the sweep rule.

struct SweepCase {
  Point a{1, -1.5, -1}, c{0, 2, 1};
  Point b1{1, -3.25, 0.5}, b2{1, 1.5, -1.5};
};

void fig_4_12() {
  const SweepCase k;
  const t2::Line r = t2::join(k.a, k.c);
  const Point n(0, r.X(), r.Y());  // norm(r): the direction across r into its positive side
  require(t2::side(r, t2::Point(1, k.a.x() / k.a.w() + n.x(), k.a.y() / k.a.w() + n.y())) > 0,
          "norm(r) points into the positive side of r");
  const t2::Line rp = t2::join(k.a, n);
  dr::Figure f;
  f.add(rp, st(pal::green).width(1.5).shade().fill(pal::green));
  f.label(Point(1, -0.45, -2.8), "r⊥", st(pal::green).label_angle(0));
  f.add(r, st(pal::blue).width(2).arrow().label("r = a ∨ c").label_angle(-60));
  f.add(k.c, lab(pal::blue, "c", 30).size(4.5));
  f.add(n, lab(pal::green, "norm(r)", 110).marker(dr::Marker::square));
  const Point bs[] = {k.b1, k.b2};
  const char* names[] = {"b₁", "b₂"};
  std::string title;
  for (int i = 0; i < 2; ++i) {
    const Point& b = bs[i];
    const Sign s = t2::side(rp, b);
    const Sign d = t2::compare_distance(k.a, b, k.c);  // a against b, distances to c
    require(s == -d, "r⊥ ⋄ b > 0 exactly when a is nearer to c than b (seed §4.3.1)");
    // The sweep line through b: perpendicular to the way towards c.
    f.add(t2::join(b, n), st(pal::light_grey).width(1));
    f.add(b, lab(s > 0 ? pal::green : pal::red, names[i], i == 0 ? 180 : 0).size(4));
    const std::string da = "d(a, c)", db = std::string("d(") + names[i] + ", c)";
    title += std::string(i ? "     " : "") + "r⊥ ⋄ " + names[i] + " " + sign_text(s) + ": " +
             (d < 0 ? da + " < " + db : (d > 0 ? db + " < " + da : da + " = " + db));
  }
  require(t2::side(rp, k.b1) > 0 && t2::side(rp, k.b2) < 0, "caption 4.12: b1 positive, b2 negative");
  f.title(title);
  f.add(k.a, lab(pal::black, "a", -120).size(4.5));
  dr::PlaneView v = plane(4);
  v.size = 440;
  dr::save(f, v, out_dir() / "fig-4-12-sweep-rule.svg");
}

// ---------------------------------------------------------------------------------------------
// 4.13: points running off towards a point at infinity: the angle at the origin of R³ shrinks.
// Drawn as the vertical section of R³ through the origin o and the direction b: horizontal axis
// x, vertical axis w; the front of T² is the line w = 1 of this section.

void fig_4_13() {
  const Point b(0, 1, 0);
  const double ts[] = {0.5, 1.5, 4};
  const char* names[] = {"a₁", "a₂", "a₃"};
  const char* colours[] = {pal::red, pal::orange, pal::green};
  // The order of the distances, from the exact predicate on the points of T² [1, t, 0].
  std::string order;
  for (int i = 2; i >= 0; --i) {
    if (i < 2) {
      const Sign c = t2::compare_distance(Point(1, ts[i + 1], 0), Point(1, ts[i], 0), b);
      require(c < 0, "the farther along the ray towards b, the nearer to b");
      order += " < ";
    }
    order += std::string("d(") + names[i] + ", b)";
  }
  dr::Figure f;
  // The section: o at (0, 0); a point (X, W) of the section is drawn at the front point [1, X, W].
  auto at = [](double X, double W) { return Point(1, X, W); };
  f.segment(at(-0.4, 1), at(4.8, 1), st(pal::dark_grey).width(1.2));
  f.label(at(-0.4, 1), "w = 1", st(pal::dark_grey).label_angle(90));
  f.arrow(at(0, 0), at(4.8, 0), st(pal::blue).width(2));
  f.label(at(4.6, 0), "towards b = [0, 1, 0]", st(pal::blue).label_angle(-90));
  for (int i = 0; i < 3; ++i) {
    const double ang = std::atan2(1.0, ts[i]);  // a_i = [1, t_i, 0] is the point (t_i, 1) of the section
    const double len = std::min(4.8 / std::cos(ang), 2.6 / std::sin(ang));
    f.segment(at(0, 0), at(len * std::cos(ang), len * std::sin(ang)), st(colours[i]).width(1));
    f.polyline(arc(0, 0, 0.4 + 0.22 * i, 0, ang, 24), st(colours[i]).width(2.2));
    f.add(at(ts[i], 1), lab(colours[i], names[i], i == 0 ? 140 : 100).size(4));
  }
  f.add(at(0, 0), lab(pal::black, "o", 180).marker(dr::Marker::square));
  f.label(at(2.2, -1.1), order, st(pal::black).label_angle(0));
  dr::PlaneView v = plane(2.8);
  v.cx = 2.2;
  v.cy = 0.6;
  v.omega = false;
  dr::save(f, v, out_dir() / "fig-4-13-angle-at-origin.svg");
}

// ---------------------------------------------------------------------------------------------
// 4.14: one proper point, two points at infinity.

void fig_4_14() {
  const Point a(1, 1.5, 0.5), b(0, 1, 0), c(0, -1, 2), o(1, 0, 0);
  const Sign s = t2::compare_distance(b, c, a);  // b against c, distances to a
  require(s < 0, "caption 4.14: b is the nearer");
  dr::Figure f;
  f.segment(o, a, st(pal::light_grey).width(1));
  f.segment(a, b, st(pal::green).width(2.2));
  f.segment(a, c, st(pal::orange).width(2.2));
  f.add(o, lab(pal::dark_grey, "o", -120).marker(dr::Marker::square));
  f.add(a, lab(pal::black, "a", -60).size(4.5));
  f.add(b, lab(pal::green, "b: " + near_to(s, "a"), -60).size(4.5));
  f.add(c, lab(pal::orange, "c: " + near_to(t2::compare_distance(c, b, a), "a"), -80).size(4.5));
  dr::save_both(f, plane(3), sphere(35, 58), out_dir() / "fig-4-14-proper-to-two-infinite.svg");
}

// ---------------------------------------------------------------------------------------------
// 4.15: three points at infinity: the angle between directions.

void fig_4_15() {
  const Point a(0, 1, 0), b(0, 1, 1.2), c(0, -1, 1.6), o(1, 0, 0);
  const Sign s = t2::compare_distance(b, c, a);
  require(s < 0, "caption 4.15: b is the nearer");
  dr::Figure f;
  for (const Point& p : {a, b, c}) f.segment(o, p, st(pal::light_grey).width(1));
  f.polyline(arc(0, 0, 0.9, 0, theta(b), 24), st(pal::green).width(2.2));
  f.polyline(arc(0, 0, 1.6, 0, theta(c), 40), st(pal::orange).width(2.2));
  f.segment(a, c, st(pal::orange).width(3).layer(-1));  // along Ω: the arc of the angle aôc
  f.segment(a, b, st(pal::green).width(3));
  f.add(o, lab(pal::dark_grey, "o", -120).marker(dr::Marker::square));
  f.add(a, lab(pal::black, "a", -30).size(4.5));
  f.add(b, lab(pal::green, "b: " + near_to(s, "a"), 180).size(4.5));
  f.add(c, lab(pal::orange, "c: " + near_to(t2::compare_distance(c, b, a), "a"), -100).size(4.5));
  dr::save_both(f, plane(3), sphere(35, 60), out_dir() / "fig-4-15-three-infinite.svg");
}

// ---------------------------------------------------------------------------------------------
// 4.16: two points at infinity and a proper one, the reference point at infinity.

void fig_4_16() {
  const Point a(0, 1, 0), b(0, 1, -0.75), c(1, -1.5, -0.5), o(1, 0, 0);
  // The seed's rule (the angle at the origin), which the figure shows; the library's 90° rule
  // (chapter 03, section 5) gives the same answer here.
  const Sign s = t2::detail::compare_angles_at_origin(b, c, a);
  require(s < 0 && t2::compare_distance(b, c, a) < 0, "caption 4.16: b is the nearer");
  dr::Figure f;
  f.segment(o, a, st(pal::light_grey).width(1));
  f.segment(o, b, st(pal::light_grey).width(1));
  f.segment(o, c, st(pal::light_grey).width(1));
  f.polyline(arc(0, 0, 0.7, theta(b), 0, 24), st(pal::green).width(2.2));
  f.segment(c, a, st(pal::orange).width(2.2));
  f.segment(a, b, st(pal::green).width(3));  // along Ω: the arc of the angle aôb
  f.add(o, lab(pal::dark_grey, "o", -100).marker(dr::Marker::square));
  f.add(a, lab(pal::black, "a", -30).size(4.5));
  f.add(b, lab(pal::green, "b: " + near_to(s, "a"), -120).size(4.5));
  f.add(c, lab(pal::orange, "c: " + near_to(t2::detail::compare_angles_at_origin(c, b, a), "a"), 125).size(4.5));
  dr::save_both(f, plane(3), sphere(35, -60), out_dir() / "fig-4-16-two-infinite-one-proper.svg");
}

// ---------------------------------------------------------------------------------------------
// 4.17: midpoints: two front points, a front and a back point, two back points.

void fig_4_17() {
  struct Case {
    Point p0, p1;
    const char* colour;
    double a0, a1, am, an;  // label directions of p0, p1, the midpoint and the naive one
  } cases[] = {
      {Point(1, -3, 0.5), Point(1, -1, 2.5), pal::blue, 200, 0, -20, 0},
      // drawn at (-0.75, -0.5) (front) and (1, 0.5) (back)
      {Point(1, -0.75, -0.5), Point(-1, -1, -0.5), pal::purple, -90, -90, 20, 90},
      // drawn at (1.25, -3.25) and (3.25, -1.25), both back
      {Point(-1, -1.25, 3.25), Point(-1, -3.25, 1.25), pal::red, 180, 0, -10, 170},
  };
  dr::Figure f;
  int i = 0;
  for (const Case& k : cases) {
    ++i;
    const Point m = t2::midpoint(k.p0, k.p1);
    const Point n = naive_midpoint(k.p0, k.p1);
    require(t2::on_segment(k.p0, k.p1, m), "the midpoint lies on the segment");
    f.segment(k.p0, k.p1, st(k.colour).width(2));
    const std::string s = std::to_string(i);
    f.add(k.p0, lab(k.colour, "p" + s + "₀", k.a0).size(4));
    f.add(k.p1, lab(k.colour, "p" + s + "₁", k.a1).size(4));
    auto where = [](const Point& x) { return x.w() > 0 ? "front" : (x.w() < 0 ? "back" : "on Ω"); };
    f.add(m, lab(pal::black, "m" + s + " (" + where(m) + ")", k.am).marker(dr::Marker::diamond).size(5).layer(1));
    if (n != m) {
      require(!t2::on_segment(k.p0, k.p1, n), "a wrong naive midpoint is off the segment");
      f.add(n, lab(pal::orange, "n" + s + " (" + where(n) + ")", k.an).marker(dr::Marker::cross).size(5).layer(1));
    }
  }
  dr::save_both(f, plane(4), sphere(35, -150), out_dir() / "fig-4-17-midpoints.svg");
}

// ---------------------------------------------------------------------------------------------
// 4.18: is r on the segment pq? p on the front, q on the back.

void fig_4_18() {
  const Point p(1, -1, 0), q(-1, -1, -1);  // drawn at (-1, 0) and (1, 1)
  const Point r1 = Point(3 * p.w() + q.w(), 3 * p.x() + q.x(), 3 * p.y() + q.y());  // 3p + q
  const Point r2 = t2::antipode(r1);
  const Point r3(2, 0, 1), r4(2, 1, -4);
  const t2::Line l = t2::join(p, q);
  require(t2::on_segment(p, q, r1) && !t2::on_segment(p, q, r2) && !t2::on_segment(p, q, r3) &&
              t2::side(l, r3) == t2::ZERO && t2::side(l, r4) != t2::ZERO,
          "caption 4.18: r1 on the segment, r2 and r3 on the line only, r4 off the line");
  dr::Figure f;
  f.add(l, st(pal::pale_grey).width(1));
  f.segment(p, q, st(pal::blue).width(2.5));
  f.add(p, lab(pal::blue, "p", 120).size(4.5));
  f.add(q, lab(pal::blue, "q", -60).size(4.5));
  f.add(t2::antipode(p), lab(pal::light_grey, "d = ¬p", -80).marker(dr::Marker::square));
  const Point rs[] = {r1, r2, r3, r4};
  const double angles[] = {160, -60, 120, -90};
  for (int i = 0; i < 4; ++i) {
    const bool on = t2::on_segment(p, q, rs[i]);
    const Sign s = t2::side(l, rs[i]);
    std::string text = "r" + std::to_string(i + 1) + (on ? " ∈ pq" : " ∉ pq");
    if (!on) text += s == 0 ? " (on the line)" : " (off the line)";
    f.add(rs[i], lab(on ? pal::green : pal::red, text, angles[i]).size(4));
  }
  dr::PlaneView v = plane(3.5);
  v.size = 420;
  dr::save_both(f, v, sphere(45, -110), out_dir() / "fig-4-18-point-on-segment.svg");
}

// ---------------------------------------------------------------------------------------------
// 4.19: the angle p̂qr with q on Ω is zero; a proper line meets Ω.

void fig_4_19() {
  const Point q(0, 2, 1), p(1, -1, 1.5), r(1, -0.5, -1.5);
  const Point ang = t2::angle(p, q, r);
  const Point zero(0, 1, 0);
  require(ang.w() == 0 && t2::compare_angle(ang, zero) == t2::ZERO, "angle(p, q, r) with q on Omega is zero");
  dr::Figure f;
  f.segment(p, q, st(pal::blue).width(2.2));
  f.segment(r, q, st(pal::green).width(2.2));
  f.add(p, lab(pal::blue, "p", 200).size(4.5));
  f.add(r, lab(pal::green, "r", 200).size(4.5));
  f.add(q, lab(pal::black, "q on Ω", -120).size(4.5));
  f.title("angle(p, q, r) = [0, " + std::string(ang.x() > 0 ? "+" : "−") + ", 0]: the angle zero");
  dr::save_both(f, plane(3.5), sphere(35, 0), out_dir() / "fig-4-19-angle-at-omega.svg");
}

// ---------------------------------------------------------------------------------------------
// 4.20: comparison of angles: Algorithm 1 as printed and corrected.

void fig_4_20() {
  const Point o(1, 0, 0), d(0, 1, 0);
  const Point p(0, 1, 1.75), q1(0, -1, 1), q2(0, 1, -0.75);
  const t2::Line po = t2::join(p, o);
  require(algorithm_1(p, q1) == t2::compare_angle(p, q1) && t2::compare_angle(p, q1) != t2::ZERO &&
              algorithm_1(p, q2) > 0 && t2::compare_angle(p, q2) < 0,
          "caption 4.20: Algorithm 1 right for q1, wrong for q2");
  dr::Figure f;
  f.add(po, st(pal::blue).width(1.5).arrow().shade().label("p ∨ o").label_angle(180));
  f.polyline(arc(0, 0, 0.6, 0, theta(p), 24), st(pal::blue).width(2.2));
  f.add(o, lab(pal::dark_grey, "o", -135).marker(dr::Marker::square));
  f.add(d, lab(pal::black, "d: angle 0", 120).marker(dr::Marker::square));
  f.add(p, lab(pal::blue, "p", 150).size(4.5));
  const Point qs[] = {q1, q2};
  std::string title = "Algorithm 1:";
  const char* colours[] = {pal::green, pal::red};
  for (int i = 0; i < 2; ++i) {
    const Sign alg = algorithm_1(p, qs[i]);
    const Sign ok = t2::compare_angle(p, qs[i]);
    const char* rel = alg < 0 ? "<" : (alg > 0 ? ">" : "=");
    const std::string name = "q" + std::to_string(i + 1);
    const double th = theta(qs[i]) < 0 ? theta(qs[i]) + 2 * std::numbers::pi : theta(qs[i]);
    f.polyline(arc(0, 0, 1.1 + 0.6 * i, 0, th, 64), st(colours[i]).width(1.6));
    f.add(qs[i], lab(colours[i], name, i == 0 ? 150 : -70).size(4.5));
    title += std::string(i ? "," : "") + " ∠p " + rel + " ∠" + name + (alg == ok ? " (right)" : " (wrong)");
  }
  f.title(title);
  dr::PlaneView v = plane(3);
  v.size = 420;
  dr::save(f, v, out_dir() / "fig-4-20-compare-angles.svg");
}

/// The facts the captions state beyond what the figures show, checked by the exact predicates
/// (a failed check throws: the caption would be wrong).
void check_caption_facts() {
  const Point o(1, 0, 0), o1(1, 1, 0), e(0, 1, 0), n(0, 0, 1);
  // 4.14: translating o to [1, 1, 0] fixes every point of Ω but changes the answer.
  require(t2::compare_distance(e, n, o) == t2::ZERO, "from o, [0,1,0] and [0,0,1] are equally far");
  require(t2::compare_distance(e, n, o1) < 0, "from [1,1,0], [0,1,0] is nearer than [0,0,1]");
  // 4.12: the sweep rule is not changed by the same translation.
  const SweepCase k;
  for (const Point& b : {k.b1, k.b2}) {
    auto tr = [](const Point& p) { return Point(p.w(), p.x() + p.w(), p.y()); };  // translation by (1, 0)
    require(t2::compare_distance(tr(k.a), tr(b), k.c) == t2::compare_distance(k.a, b, k.c),
            "the sweep rule is invariant under translation");
  }
  // 4.16: translating c (which fixes a and b) flips the seed's answer, not the library's.
  const Point a(0, 1, 0), b(0, 1, -0.75), c(1, -1.5, -0.5), c2(1, 8, 0);
  require(t2::detail::compare_angles_at_origin(b, c, a) < 0 && t2::detail::compare_angles_at_origin(b, c2, a) > 0,
          "by the seed's rule, moving c to [1, 8, 0] makes it nearer to a than b");
  require(t2::compare_distance(b, c, a) < 0 && t2::compare_distance(b, c2, a) < 0,
          "by the 90 degree rule, b stays the nearer wherever c is");
  // 4.17: the naive formula gives a proper point for front/back, the antipode for back/back.
  {
    const Point p0(1, -0.75, -0.5), p1(-1, -1, -0.5);
    require(t2::midpoint(p0, p1).w() == 0 && naive_midpoint(p0, p1).w() != 0, "front/back naive midpoint");
    const Point q0(-1, -1.25, 3.25), q1(-1, -3.25, 1.25);
    require(naive_midpoint(q0, q1) == t2::antipode(t2::midpoint(q0, q1)), "back/back naive midpoint");
  }
  // 4.19: Ω has no direction; the line q ∨ p misses the origin, so on the sphere its great circle
  // crosses the equator obliquely.
  bool undefined = false;
  try {
    (void)t2::direction(t2::Line(1, 0, 0));
  } catch (const t2::Undefined&) {
    undefined = true;
  }
  require(undefined, "Omega has no direction");
  require(t2::join(Point(0, 2, 1), Point(1, -1, 1.5)).W() != 0, "q v p misses the origin");
}

}  // namespace

std::vector<Entry> thesis4_predicates() {
  check_caption_facts();
  return {
      {"4.12", "fig-4-12-sweep-rule.svg",
       "Which of two proper points a, b is nearer to the point at infinity c (the sweep rule of §4.3.1): "
       "r = a ∨ c, norm(r) the direction across r into its positive side, r⊥ = a ∨ norm(r) (its positive "
       "side shaded). b₁ lies on the positive side of r⊥, so a is nearer to c; b₂ on the negative side, so "
       "b₂ is nearer: sweeping towards c with lines perpendicular to r (grey), the point met later is the "
       "nearer. The verdicts above are compare_distance's, checked against the sign r⊥ ⋄ b. The rule is "
       "translation-invariant (the program checks it); with a and b on opposite sides of Ω the library "
       "calls the comparison undefined, a case the seed leaves out.",
       fig_4_12},
      {"4.13", "fig-4-13-angle-at-origin.svg",
       "Why angles measure infinite distances: a vertical section of R³ through its origin o and the "
       "direction b = [0, 1, 0], with the front of T² the line w = 1. The points aᵢ = [1, tᵢ, 0] run off "
       "towards b, and the angle aᵢôb shrinks; compare_distance orders them the same way "
       "(the inequality below).",
       fig_4_13},
      {"4.14", "fig-4-14-proper-to-two-infinite.svg",
       "A proper point a and two points at infinity b, c: the seed compares the angles aôb and aôc at "
       "the origin of R³, which on the sphere (right) are the great-circle arcs from a to b and to c; "
       "compare_distance says b is the nearer. This is the limit for points running off along rays "
       "from o = [1, 0, 0], and so depends on the origin: a translation fixes every point of Ω, yet "
       "[0, 1, 0] and [0, 0, 1] are equally far from o and not from [1, 1, 0] (checked by the program).",
       fig_4_14},
      {"4.15", "fig-4-15-three-infinite.svg",
       "Three points at infinity: the distance from a to b or c is the angle between the directions, "
       "the arc of Ω between them (thick) or the angle at o (the marks inside); b is the nearer to a.",
       fig_4_15},
      {"4.16", "fig-4-16-two-infinite-one-proper.svg",
       "Two points at infinity a, b and a proper point c, distances from a: the angle aôb (along Ω) "
       "against aôc (the arc from a to c on the sphere); b is the nearer. Unlike figures 4.12 and 4.15 "
       "this is a convention of the seed, not a limit of finite distances, and it depends on the "
       "origin: moving c to [1, 8, 0] (a translation, which fixes a and b) makes c the nearer. The "
       "library does not follow it: by chapter 03's convention every proper point is 90° from a, so b "
       "(less than 90° from a) is the nearer wherever c is.",
       fig_4_16},
      {"4.17", "fig-4-17-midpoints.svg",
       "The midpoint formula of T², m = [|w₁|w₀ + |w₀|w₁, …] (diamonds), for two front points (1), a front "
       "and a back point (2) and two back points (3), drawn in one picture. The naive formula "
       "[2w₀w₁, x₀w₁ + x₁w₀, y₀w₁ + y₁w₀] (crosses nᵢ) agrees in case 1; in case 2 it gives a proper "
       "point off the segment instead of the crossing of Ω, in case 3 the front antipode of the "
       "midpoint (same spot in the planar model, filled instead of hollow). The thesis draws three panels.",
       fig_4_17},
      {"4.18", "fig-4-18-point-on-segment.svg",
       "Is r on the segment pq (p front, q back)? The library's exact test: r = αp + βq with α, β ≥ 0. "
       "r₁ and r₂ = ¬r₁ are drawn at the same spot of the planar model, but only r₁ is on the segment; "
       "r₃ is on the line pq but not on the segment, r₄ off the line. The seed's test (\"if b and c "
       "are on the same side of the line ad …\") is muddled: a, d = ¬p and the origin of R³ are "
       "collinear, and the other case is left unsaid; d = ¬p is marked for reference.",
       fig_4_18},
      {"4.19", "fig-4-19-angle-at-omega.svg",
       "The angle p̂qr with q on Ω and p, r proper is zero: angle(p, q, r) is [0, +, 0] (title, "
       "computed): both lines leave q in the same direction, parallel in the planar model. On the "
       "sphere the two arcs meet at q at a visible angle: the angle of T² is between directions, not "
       "the angle the sphere shows. The seed's remark that a proper line meets Ω at a right angle is "
       "loose: Ω has no direction (the library throws Undefined), and on the sphere a great circle "
       "crosses Ω at a right angle only when its line passes through the origin, which q ∨ p does not.",
       fig_4_19},
      {"4.20", "fig-4-20-compare-angles.svg",
       "Comparing the angles of directions p, q (points of Ω; d = [0, 1, 0] is the angle zero) with the "
       "seed's Algorithm 1: the sign of Δ(p, o, q) against that of Δ(p, o, d), i.e. on which side of "
       "p ∨ o (positive side shaded) q lies. With both angles in [0, π) it is right (q₁); for q₂, whose "
       "angle is larger than p's, it answers ∠p > ∠q₂. The text says to reflect the angles into the "
       "first two quadrants first, but the algorithm does not; the library's compare_angle compares the "
       "half turns first and is right for every pair.",
       fig_4_20},
  };
}

}  // namespace gallery
