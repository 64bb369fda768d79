// Chapter 03, predicates: orientation, sides, join/meet and duality, point on segment, the
// wxy order, distances in T¹ and infinite distances, the midpoint, angles and Algorithm 1.
//
// Prints every number the chapter quotes and writes its figures, in the planar and the
// spherical model, into --figures DIR. Deterministic. Where a seed formula is shown, the
// program implements it literally (so that its failures can be printed) next to the
// corrected version, and checks both against an independent oracle.
#include <t2/t2.hpp>
#include <t2/kernel/angle.hpp>
#include <t2/kernel/distance.hpp>
#include <t2/kernel/lexicographic.hpp>
#include <t2/kernel/midpoint.hpp>
#include <t2/kernel/segment.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace chapter03 {
void circles();                                                   // circles.cpp
void circle_figures(const std::filesystem::path& dir, int& written);  // circles.cpp
/// The naive midpoint that the midpoint figure draws next to t2::midpoint.
using Midpoint = t2::ExactPoint (*)(const t2::ExactPoint&, const t2::ExactPoint&);
void figures(const std::filesystem::path& dir, Midpoint naive_midpoint);  // figures.cpp
}  // namespace chapter03

namespace {

using t2::ExactPoint;
using t2::Integer;
using t2::Point;
using t2::Sign;
namespace dr = t2::draw;
namespace pal = t2::draw::palette;

std::string str(const Point& p) { return t2::to_string(p); }
std::string str(const ExactPoint& p) { return t2::to_string(p); }
const char* sym(Sign s) { return t2::to_symbol(s); }

// ---------------------------------------------------------------------------------------------
// 1. Orientation and the side of a line.

void orientation() {
  std::cout << "== 1. Orientation and sides\n";
  //> orient-demo
  const Point p(1, 0, 0), q(1, 2, 0), r(1, 1, 1);  // three front points, counter-clockwise
  const Point s(-1, -1, -1);                        // a back point: the antipode of r
  const t2::Line l = t2::join(p, q);                // the oriented line p ∨ q
  //< orient-demo
  std::cout << "orient(p, q, r) = " << sym(t2::orient(p, q, r)) << "   orient(q, p, r) = " << sym(t2::orient(q, p, r))
            << "   orient(p, q, s) = " << sym(t2::orient(p, q, s)) << "   (s = antipode(r))\n";
  std::cout << "orient(p, q, [7, 7, 7]) = " << sym(t2::orient(p, q, Point(7, 7, 7)))
            << " (a positive multiple of r: the same point)\n";
  std::cout << "p v q = " << t2::to_string(l) << ";  side(p v q, r) = " << sym(t2::side(l, r))
            << ", side(p v q, s) = " << sym(t2::side(l, s)) << ", side(Omega, s) = " << sym(t2::side(t2::omega(), s))
            << "\n";
  // Δ(p, q, r) = (p ∨ q) ⋄ r, checked on every triple of a small integer grid of both sides.
  int triples = 0, agree = 0;
  for (int a = -1; a <= 1; a += 2)
    for (int x = -1; x <= 1; ++x)
      for (int y = -1; y <= 1; ++y) {
        const ExactPoint u(a, x, y), v(1, y, -x), w(a * 2, x + y, 1);
        if (t2::orient(u, v, ExactPoint(1, 0, 0)) == t2::ZERO && t2::orient(u, v, ExactPoint(0, 1, 0)) == t2::ZERO &&
            t2::orient(u, v, ExactPoint(0, 0, 1)) == t2::ZERO)
          continue;  // u = ±v: no line
        ++triples;
        agree += t2::side(t2::join(u, v), w) == t2::orient(u, v, w);
      }
  std::cout << "side(join(u, v), w) == orient(u, v, w) on " << agree << " of " << triples << " test triples\n\n";
}

// ---------------------------------------------------------------------------------------------
// 2. Join, meet, duality.

void join_meet_duality() {
  std::cout << "== 2. Join, meet and duality\n";
  //> meet-demo
  const ExactPoint a = ExactPoint::cartesian(0, 0), b = ExactPoint::cartesian(4, 2);
  const ExactPoint c = ExactPoint::cartesian(0, 1), d = ExactPoint::cartesian(4, 3);
  const t2::ExactLine ab = t2::join(a, b), cd = t2::join(c, d);  // two parallel lines
  const ExactPoint m = t2::meet(ab, cd);                          // they meet on Omega
  const ExactPoint n = t2::meet(cd, ab);                          // swapped: the antipode
  //< meet-demo
  std::cout << "ab = " << t2::to_string(ab) << ", cd = " << t2::to_string(cd) << "\nmeet(ab, cd) = " << str(m)
            << ", meet(cd, ab) = " << str(n) << ", n == antipode(m): " << (n == t2::antipode(m)) << "\n";
  // The meet rule: z = meet(l, m) is where m, walked in its direction (tangent t = m × z at
  // z), crosses l from its negative to its positive side. Checked on the pairs of a grid.
  int line_pairs = 0, rule_ok = 0;
  for (int i = -9; i <= 9; ++i)
    for (int j = -9; j <= 9; ++j) {
      const t2::ExactLine l(i % 3, i / 3, 1), mm(j / 3, 1, j % 3);
      if (l == mm || l == t2::opposite(mm)) continue;  // one line: no meet
      const ExactPoint z = t2::meet(l, mm);
      const ExactPoint t(mm.X() * z.y() - mm.Y() * z.x(), mm.Y() * z.w() - mm.W() * z.y(),
                         mm.W() * z.x() - mm.X() * z.w());  // t = m × z, along m at z
      const ExactPoint before(z.w() - t.w(), z.x() - t.x(), z.y() - t.y());
      const ExactPoint after(z.w() + t.w(), z.x() + t.x(), z.y() + t.y());
      ++line_pairs;
      rule_ok += t2::side(l, before) == t2::NEGATIVE && t2::side(l, after) == t2::POSITIVE;
    }
  std::cout << "meet(l, m): m crosses l from - to + there, on " << rule_ok << " of " << line_pairs
            << " pairs of lines\n";
  try {
    (void)t2::meet(ab, t2::opposite(ab));
  } catch (const t2::Undefined& e) {
    std::cout << "meet(ab, opposite(ab)) throws t2::Undefined: " << e.what() << "\n";
  }
  // Duality: the point with the line's coordinates, and back. side(l, p) = side(dual(p), dual(l)).
  int checked = 0, agree = 0;
  for (int w = -2; w <= 2; ++w)
    for (int x = -2; x <= 2; ++x)
      for (int y = -2; y <= 2; ++y) {
        if (w == 0 && x == 0 && y == 0) continue;
        const ExactPoint p(w, x, y);
        for (const t2::ExactLine& l : {ab, cd, t2::omega<Integer>()}) {
          ++checked;
          agree += t2::side(l, p) == t2::side(t2::dual(p), t2::dual(l));
        }
      }
  std::cout << "side(l, p) == side(dual(p), dual(l)) on " << agree << " of " << checked << " pairs\n\n";
}

// ---------------------------------------------------------------------------------------------
// 3. Point on segment.

void point_on_segment() {
  std::cout << "== 3. Point on segment\n";
  // The oracle: solve r = αp + βq in exact rationals from two independent coordinates.
  auto oracle = [](const ExactPoint& p, const ExactPoint& q, const ExactPoint& r) {
    const Integer c[3][3] = {{p.w(), p.x(), p.y()}, {q.w(), q.x(), q.y()}, {r.w(), r.x(), r.y()}};
    for (int i = 0; i < 3; ++i)
      for (int j = i + 1; j < 3; ++j) {
        const Integer det = c[0][i] * c[1][j] - c[0][j] * c[1][i];
        if (det == 0) continue;
        t2::Rational alpha(c[2][i] * c[1][j] - c[2][j] * c[1][i], det);
        t2::Rational beta(c[0][i] * c[2][j] - c[0][j] * c[2][i], det);
        alpha.canonicalize();  // mpq_class(n, d) does not normalize signs and common factors
        beta.canonicalize();
        for (int k = 0; k < 3; ++k)  // r must really be αp + βq
          if (alpha * c[0][k] + beta * c[1][k] != c[2][k]) return false;
        return alpha >= 0 && beta >= 0;
      }
    return false;
  };
  //> on-segment-demo
  const ExactPoint p(1, 0, 0),
      q(-1, -2, 0);  // p front, q back: the segment runs through Omega
  const bool at_omega =
      t2::on_segment(p, q, ExactPoint(0, -1, 0));  // where it crosses Omega
  const bool other_omega =
      t2::on_segment(p, q, ExactPoint(0, 1, 0));  // the antipode of that
  const bool front_ray =
      t2::on_segment(p, q, ExactPoint(1, -1, 0));  // (-1, 0), front side
  const bool between = t2::on_segment(p, q, ExactPoint(1, 1, 0));      // (1, 0): NOT on it
  //< on-segment-demo
  std::cout << "p = " << str(p) << ", q = " << str(q) << ": [0,-1,0] " << at_omega << ", [0,1,0] " << other_omega
            << ", [1,-1,0] " << front_ray << ", [1,1,0] " << between << "\n";
  int cases = 0, library_ok = 0, inside = 0;
  for (int pw = -1; pw <= 1; ++pw)
    for (int px = -2; px <= 2; ++px)
      for (int qw = -1; qw <= 1; ++qw)
        for (int qx = -2; qx <= 2; ++qx)
          for (int rw = -2; rw <= 2; ++rw)
            for (int rx = -3; rx <= 3; ++rx) {
              const int py = 1, qy = -1;  // p and q are never equal
              if (rw == 0 && rx == 0) continue;
              const ExactPoint pp(pw, px, py), qq(qw, qx, qy);
              if (pp == t2::antipode(qq)) continue;  // no segment between antipodes
              for (int ry = -2; ry <= 2; ++ry) {
                const ExactPoint rr(rw, rx, ry);
                ++cases;
                const bool o = oracle(pp, qq, rr);
                inside += o;
                library_ok += t2::on_segment(pp, qq, rr) == o;
              }
            }
  std::cout << "against the rational oracle, " << cases << " cases (" << inside
            << " on the segment): t2::on_segment right on " << library_ok << "\n";
  std::cout << "one-point segment: on_segment(p, p, p) = " << t2::on_segment(p, p, p)
            << ", on_segment(p, p, [2, 0, 0]) = " << t2::on_segment(p, p, ExactPoint(2, 0, 0))
            << ", on_segment(p, p, [1, 1, 0]) = " << t2::on_segment(p, p, ExactPoint(1, 1, 0)) << "\n\n";
}

// ---------------------------------------------------------------------------------------------
// 4. The lexicographic wxy order.

namespace sketch {
//> lex-order
// Compare normalized coordinates [w/|w|, x/|w|, y/|w|] without dividing: first the side
// of T² (back < Omega < front), then x/|w| against x'/|w'| as x·|w'| against x'·|w|, then
// y likewise. For two points of Omega the seed gives no normalization; here they are
// ordered by x then y after scaling by max(|x|, |y|), compared the same way by
// cross-multiplication.
Sign compare_wxy(const ExactPoint& a, const ExactPoint& b) {
  if (t2::sign_of(a.w()) != t2::sign_of(b.w()))
    return t2::sign_of(Integer(t2::sign_of(a.w()) - t2::sign_of(b.w())));
  Integer sa = abs(a.w()), sb = abs(b.w());
  if (sa == 0) {
    sa = std::max(abs(a.x()), abs(a.y()));
    sb = std::max(abs(b.x()), abs(b.y()));
  }
  if (const Sign s = t2::sign_of(Integer(a.x() * sb - b.x() * sa)); s != t2::ZERO)
    return s;
  return t2::sign_of(Integer(a.y() * sb - b.y() * sa));
}
//< lex-order
}  // namespace sketch

void lexicographic() {
  std::cout << "== 4. Lexicographic wxy order\n";
  //> lex-demo
  std::vector<ExactPoint> pts = {ExactPoint(2, 2, 0),   ExactPoint(1, 1, 5),
                                 ExactPoint(-1, 3, 0),  ExactPoint(0, 1, 1),
                                 ExactPoint(-3, -3, 3), ExactPoint(0, -2, 0),
                                 ExactPoint(4, 4, -4),  ExactPoint(1, 1, 1)};
  std::stable_sort(pts.begin(), pts.end(),
                   [](const auto& a, const auto& b) { return t2::less_wxy(a, b); });
  //< lex-demo
  std::cout << "sorted:";
  for (const auto& p : pts) std::cout << ' ' << str(p);
  std::cout << "\nnormalized:";
  for (const auto& p : pts) std::cout << ' ' << str(t2::normalized(t2::to_double(p)));
  int pairs = 0, agree = 0;
  for (int a = -2; a <= 2; ++a)
    for (int b = -2; b <= 2; ++b)
      for (int c = -2; c <= 2; ++c)
        for (int d = -2; d <= 2; ++d)
          for (int e = -2; e <= 2; ++e)
            for (int f = -2; f <= 2; ++f) {
              if ((a == 0 && b == 0 && c == 0) || (d == 0 && e == 0 && f == 0)) continue;
              const ExactPoint u(a, b, c), v(d, e, f);
              ++pairs;
              agree += sketch::compare_wxy(u, v) == t2::compare_lexicographic(u, v);
            }
  std::cout << "\nsketch::compare_wxy == t2::compare_lexicographic on " << agree << " of " << pairs << " pairs\n\n";
}

// ---------------------------------------------------------------------------------------------
// 5. Squared distance in T¹ and infinite distances.

namespace sketch {
//> squared-distance
// Seed 000, §4.3.1: the squared distance of two proper points as a point of T¹,
// [sign(aw bw)(aw bw)², (ax bw - bx aw)² + (ay bw - by aw)²]. Front-back pairs get a
// negative weight: a distance "beyond infinity".
t2::ExactT1 squared_distance(const ExactPoint& a, const ExactPoint& b) {
  if (a.w() == 0 || b.w() == 0)
    throw t2::Undefined("squared_distance(a, b) needs two proper points (w != 0)");
  const Integer ww = a.w() * b.w(), dx = a.x() * b.w() - b.x() * a.w(),
                dy = a.y() * b.w() - b.y() * a.w();
  return t2::ExactT1(ww > 0 ? Integer(ww * ww) : Integer(-ww * ww), dx * dx + dy * dy);
}
//< squared-distance
}  // namespace sketch

namespace sketch {
//> sweep-test
// Which of the proper points a, b (same side of T²) is nearer to the point at infinity c?
// Seed 000, §4.3.1: r = a ∨ c, n = the direction normal to r entering its positive side,
// r⊥ = a ∨ n; then r⊥ ⋄ b > 0 means a is nearer. Returns NEGATIVE when a is nearer.
Sign compare_to_infinite(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c) {
  const t2::ExactLine r = t2::join(a, c);
  const ExactPoint n(0, r.X(),
                     r.Y());  // the normal direction of r, towards its positive side
  const t2::ExactLine r_perp = t2::join(a, n);
  return -t2::side(r_perp, b);
}
//< sweep-test
}  // namespace sketch

namespace sketch {
//> angle-test
// Which of the points at infinity b, c is nearer to the proper point a? Compare the
// angles a·o·b and a·o·c at the origin o of space: cos(aob) = (a·b)/(|a||b|). Squared
// with signs, (a·b)|c| > (a·c)|b| becomes a polynomial test. Returns NEGATIVE when b is
// nearer.
Sign compare_infinite_to(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c) {
  const Integer ab = a.w() * b.w() + a.x() * b.x() + a.y() * b.y();
  const Integer ac = a.w() * c.w() + a.x() * c.x() + a.y() * c.y();
  const Integer bb = b.w() * b.w() + b.x() * b.x() + b.y() * b.y();
  const Integer cc = c.w() * c.w() + c.x() * c.x() + c.y() * c.y();
  // sign(ab)·ab²·cc versus sign(ac)·ac²·bb: the larger cosine is the smaller angle.
  const Integer lhs = sgn(ab) * ab * ab * cc, rhs = sgn(ac) * ac * ac * bb;
  return t2::sign_of(Integer(rhs - lhs));
}
//< angle-test
}  // namespace sketch

void distances() {
  std::cout << "== 5. Distances\n";
  //> distance-demo
  const ExactPoint a = ExactPoint::cartesian(0, 0), b = ExactPoint::cartesian(3, 4);
  const ExactPoint back(-1, -3, -4);  // drawn at (3, 4) too, but on the back side
  const t2::ExactT1 near = t2::squared_distance(a, b), far = t2::squared_distance(a, back);
  const t2::ExactT1 to_omega = t2::squared_distance(a, ExactPoint(0, 3, 4));
  //< distance-demo
  std::cout << "d2(a, b) = " << t2::to_string(near) << ", d2(a, back) = " << t2::to_string(far)
            << ", d2(a, [0,3,4]) = " << t2::to_string(to_omega) << "; sketch gives " << t2::to_string(sketch::squared_distance(a, b))
            << " and " << t2::to_string(sketch::squared_distance(a, back)) << "\n";
  std::cout << "compare_distance_values: d2(a,b) vs d2(a,[0,3,4]) " << sym(t2::compare_distance_values(near, to_omega))
            << ", d2(a,[0,3,4]) vs d2(a,back) " << sym(t2::compare_distance_values(to_omega, far)) << "\n";
  // Oracle for the sweep test: a is nearer to the direction c iff (a - b)·c > 0 (the limit of
  // |b - T c| - |a - T c| as T grows). Checked over a grid of front pairs and directions.
  int cases = 0, sketch_ok = 0, library_ok = 0;
  for (int ax = -2; ax <= 2; ++ax)
    for (int ay = -2; ay <= 2; ++ay)
      for (int bx = -2; bx <= 2; ++bx)
        for (int by = -2; by <= 2; ++by)
          for (int cx = -2; cx <= 2; ++cx)
            for (int cy = -2; cy <= 2; ++cy) {
              if (cx == 0 && cy == 0) continue;
              const ExactPoint pa = ExactPoint::cartesian(ax, ay), pb = ExactPoint::cartesian(bx, by), pc(0, cx, cy);
              if (pa == pb) continue;
              const Sign want = -t2::sign_of((ax - bx) * cx + (ay - by) * cy);
              ++cases;
              sketch_ok += sketch::compare_to_infinite(pa, pb, pc) == want;
              library_ok += t2::compare_distance(pa, pb, pc) == want;
            }
  std::cout << "sweep rule against the limit (a - b)·c, " << cases << " front cases: sketch right on " << sketch_ok
            << ", t2::compare_distance right on " << library_ok << "\n";
  // Oracle for the angle rule: the limit of |a - T b/|b|| - |a - T c/|c||, i.e. a·ĉ - a·b̂, in
  // long double (on this small grid the values are either equal or far apart).
  cases = sketch_ok = library_ok = 0;
  for (int ax = -2; ax <= 2; ++ax)
    for (int ay = -2; ay <= 2; ++ay)
      for (int bx = -2; bx <= 2; ++bx)
        for (int by = -2; by <= 2; ++by)
          for (int cx = -2; cx <= 2; ++cx)
            for (int cy = -2; cy <= 2; ++cy) {
              if ((bx == 0 && by == 0) || (cx == 0 && cy == 0)) continue;
              const long double lb = std::sqrt(static_cast<long double>(bx * bx + by * by)),
                                lc = std::sqrt(static_cast<long double>(cx * cx + cy * cy));
              const long double diff = (ax * cx + ay * cy) / lc - (ax * bx + ay * by) / lb;
              const Sign want = std::fabs(diff) < 1e-12L ? t2::ZERO : (diff > 0 ? t2::POSITIVE : t2::NEGATIVE);
              const ExactPoint pa = ExactPoint::cartesian(ax, ay), pb(0, bx, by), pc(0, cx, cy);
              ++cases;
              sketch_ok += sketch::compare_infinite_to(pa, pb, pc) == want;
              library_ok += t2::compare_distance(pb, pc, pa) == want;
            }
  std::cout << "angle rule against the limit a·c^ - a·b^, " << cases << " cases: sketch right on " << sketch_ok
            << ", t2::compare_distance right on " << library_ok << "\n";
  //> two-notions
  const ExactPoint u = ExactPoint::cartesian(10, 0), v = ExactPoint::cartesian(21, 200),
                   dir(0, 1, 0);
  const Sign sweep =
      t2::compare_distance(u, v, dir);  // the sweep rule: the Euclidean limit
  const Sign angle = sketch::compare_infinite_to(dir, u, v);  // the angle rule, misapplied
  //< two-notions
  std::cout << "u = (10, 0), v = (21, 200), c = [0,1,0]: the sweep rule says " << (sweep < 0 ? "u" : "v")
            << " is nearer to c; the angle rule would say " << (angle < 0 ? "u" : "v") << "\n\n";
}

// ---------------------------------------------------------------------------------------------
// 6. The midpoint.

namespace sketch {
//> midpoints
// The naive homogeneous midpoint, straight from the Cartesian formula.
ExactPoint naive_midpoint(const ExactPoint& p, const ExactPoint& q) {
  return ExactPoint(2 * p.w() * q.w(), p.x() * q.w() + q.x() * p.w(),
                    p.y() * q.w() + q.y() * p.w());
}
// Seed 000, §4.3.2 (after de Rezende & Stolfi): weight each point by the other's |w|.
ExactPoint seed_midpoint(const ExactPoint& p, const ExactPoint& q) {
  const Integer ap = abs(p.w()), aq = abs(q.w());
  return ExactPoint(aq * p.w() + ap * q.w(), aq * p.x() + ap * q.x(),
                    aq * p.y() + ap * q.y());
}
//< midpoints
}  // namespace sketch

void midpoints() {
  std::cout << "== 6. The midpoint\n";
  const ExactPoint f1 = ExactPoint::cartesian(0, 0), f2(2, 4, 2), b1(-1, -2, 2), b2(-2, 0, -4);
  struct Case {
    const char* name;
    ExactPoint p, q;
  };
  auto where = [](const ExactPoint& m) { return m.w() > 0 ? "front" : m.w() < 0 ? "back" : "Omega"; };
  for (const Case& c : {Case{"front-front", f1, f2}, Case{"back-back  ", b1, b2}, Case{"front-back ", f1, b1}}) {
    //> midpoint-demo
    const ExactPoint n = sketch::naive_midpoint(c.p, c.q), m = t2::midpoint(c.p, c.q);
    //< midpoint-demo
    std::cout << c.name << "  p = " << str(c.p) << " q = " << str(c.q) << "  naive " << str(n) << " (" << where(n)
              << ", on segment: " << t2::on_segment(c.p, c.q, n) << ")  midpoint " << str(m) << " (" << where(m)
              << ", on segment: " << t2::on_segment(c.p, c.q, m) << ", same as sketch: "
              << (m == sketch::seed_midpoint(c.p, c.q)) << ")\n";
  }
  try {
    (void)sketch::seed_midpoint(ExactPoint(0, 1, 0), ExactPoint(0, 0, 1));
  } catch (const t2::Undefined& e) {
    std::cout << "seed formula on [0,1,0] and [0,0,1] (both on Omega): " << e.what() << "\n";
  }
  try {
    (void)t2::midpoint(ExactPoint(0, 1, 0), ExactPoint(0, 0, 1));
  } catch (const t2::Undefined& e) {
    std::cout << "t2::midpoint on the same pair: " << e.what() << "\n";
  }
  std::cout << '\n';
}

// ---------------------------------------------------------------------------------------------
// 7. Angles: Algorithm 1 of seed 000 and its correction.

namespace sketch {
//> algorithm-1
// Algorithm 1 of seed 000, literally: p, q are directions (points of Omega); o = [1,0,0],
// d = [0,1,0]. Returns POSITIVE for "angle p > angle q".
Sign algorithm_1(const ExactPoint& p, const ExactPoint& q) {
  const ExactPoint o(1, 0, 0), d(0, 1, 0);
  if (t2::orient(p, o, q) * t2::orient(p, o, d) == t2::POSITIVE) return t2::POSITIVE;
  if (t2::orient(p, o, q) == t2::ZERO) return t2::ZERO;
  return t2::NEGATIVE;
}
//< algorithm-1
}  // namespace sketch

namespace sketch {
//> compare-angle
// Corrected: the angle of a direction in [0, 2π) counter-clockwise from d = [0,1,0].
// First the half it lies in (upper: y > 0, or y = 0 and x > 0), then the orientation
// inside a half.
Sign compare_angle(const ExactPoint& p, const ExactPoint& q) {
  auto half = [](const ExactPoint& v) {
    return (v.y() > 0 || (v.y() == 0 && v.x() > 0)) ? 0 : 1;
  };
  if (half(p) != half(q)) return half(p) < half(q) ? t2::NEGATIVE : t2::POSITIVE;
  return t2::orient(p, ExactPoint(1, 0, 0), q);  // = sign of sin(angle p - angle q)
}
//< compare-angle
}  // namespace sketch

void angles() {
  std::cout << "== 7. Angles\n";
  // Sixteen directions, at known angles, in counter-clockwise order from [0,1,0].
  const int dirs[16][2] = {{1, 0},  {2, 1},   {1, 1},   {1, 2},   {0, 1},  {-1, 2}, {-1, 1}, {-2, 1},
                           {-1, 0}, {-2, -1}, {-1, -1}, {-1, -2}, {0, -1}, {1, -2}, {1, -1}, {2, -1}};
  int total = 0, bad1 = 0, bad1_upper = 0, bad1_domain = 0, bad_sketch = 0, bad_lib = 0;
  std::vector<std::string> failures;
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 16; ++j) {
      const ExactPoint p(0, dirs[i][0], dirs[i][1]), q(0, dirs[j][0], dirs[j][1]);
      const Sign want = t2::sign_of(i - j);  // the oracle: the index order is the angle order
      ++total;
      const Sign a1 = sketch::algorithm_1(p, q);
      if (a1 != want) {
        ++bad1;
        if (i <= 8 && j <= 8) {  // both in the closed upper half [0, π], the seed's domain
          ++bad1_upper;
          bad1_domain += i != 8 && j != 8;  // ... and neither angle is π
          failures.push_back(str(p) + " vs " + str(q) + ": says " + sym(a1) + ", truth " + sym(want));
        }
      }
      bad_sketch += sketch::compare_angle(p, q) != want;
      bad_lib += t2::compare_angle(p, q) != want;
    }
  std::cout << "Algorithm 1 is wrong on " << bad1 << " of " << total << " ordered pairs of 16 directions; "
            << bad1_upper << " wrong pairs have both angles in [0, pi], " << bad1_domain
            << " of them without an angle pi:\n";
  for (const auto& f : failures) std::cout << "  " << f << "\n";
  std::cout << "corrected: the sketch is wrong on " << bad_sketch << ", t2::compare_angle on " << bad_lib << " of "
            << total << "\n\n";
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = dr::figures_dir(argc, argv, T2_FIGURES_DIR);
  std::cout << std::boolalpha;
  orientation();
  join_meet_duality();
  point_on_segment();
  lexicographic();
  distances();
  midpoints();
  angles();
  chapter03::circles();
  chapter03::figures(dir, sketch::naive_midpoint);
}
