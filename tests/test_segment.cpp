// Segments, rays, vectors and directions of T², for double and Integer coordinates, against
// integer oracles: points built as αp + βq, null vectors of [a b −c −d], brute force.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <variant>

#include "t2/kernel/polygon.hpp"
#include "t2/kernel/ray.hpp"
#include "t2/kernel/segment.hpp"
#include "t2/kernel/vector.hpp"
#include "test_prim.hpp"

namespace t2 {
namespace {

using testing::combo;
using testing::coords;
using testing::det_oracle;
using testing::is_zero;
using testing::pt;
using testing::same_point;
using testing::scale;
using testing::Small;

template <class T>
class SegmentT : public ::testing::Test {};
TYPED_TEST_SUITE(SegmentT, testing::CoordinateTypes);

TYPED_TEST(SegmentT, AntipodalEndpointsAreUndefinedEqualOnesDegenerate) {
  using T = TypeParam;
  EXPECT_THROW(BasicSegment<T>(pt<T>(1, 2, 3), pt<T>(-2, -4, -6)), Undefined);
  try {
    BasicSegment<T>(pt<T>(0, 1, 0), pt<T>(0, -3, 0));
    ADD_FAILURE();
  } catch (const Undefined& e) {
    EXPECT_STREQ(e.what(), "segment(p, q) is undefined when q = antipode(p)");
  }
  const BasicSegment<T> s(pt<T>(1, 2, 3), pt<T>(2, 4, 6));
  EXPECT_TRUE(s.is_degenerate());
  EXPECT_TRUE(contains(s, pt<T>(3, 6, 9)));
  EXPECT_FALSE(contains(s, pt<T>(-1, -2, -3)));
  EXPECT_FALSE(contains(s, pt<T>(1, 2, 4)));
  EXPECT_THROW(on_segment(pt<T>(1, 0, 0), pt<T>(-1, 0, 0), pt<T>(1, 0, 0)), Undefined);
}

TYPED_TEST(SegmentT, PositiveCombinationsAreOnNegativeOnesAreNot) {
  using T = TypeParam;
  Small g(11, 30);
  std::uniform_int_distribution<long> co(-6, 6);
  int on = 0, off = 0;
  for (int i = 0; i < 3000 * scale(); ++i) {
    const auto pa = g.triple(), qa = g.triple();
    const BasicPoint<T> p = pt<T>(pa), q = pt<T>(qa);
    const auto P = coords(p), Q = coords(q);
    // Oracle for p = ±q: all 2×2 minors zero.
    const bool dependent = P[0] * Q[1] == P[1] * Q[0] && P[0] * Q[2] == P[2] * Q[0] && P[1] * Q[2] == P[2] * Q[1];
    if (dependent) continue;
    const long al = co(g.rng), be = co(g.rng);
    if (al == 0 && be == 0) continue;
    const auto R = combo(al, P, be, Q);
    const bool want = al >= 0 && be >= 0;
    ASSERT_EQ(on_segment(p, q, pt<T>(R)), want) << al << " " << be;
    ASSERT_EQ(on_segment(q, p, pt<T>(R)), want);
    ASSERT_EQ(contains(BasicSegment<T>(p, q), pt<T>(R)), want);
    (want ? on : off)++;
    // A point off the line is never on the segment.
    const auto r = g.triple();
    if (det_oracle(P, Q, coords(pt<T>(r))) != 0) {
      ASSERT_FALSE(on_segment(p, q, pt<T>(r)));
    }
  }
  EXPECT_GT(on, 100);
  EXPECT_GT(off, 100);
}

TEST(Segment, DoubleOnSegmentIsExactNearTheEnds) {
  // r = p + tiny·(q − p) rounds; only exact tests tell whether it is on the line at all.
  const Point p(1, 0.1, 0.2), q(1, 0.7, 0.3);
  const Point r(1, 0.1 + 1e-18, 0.2);  // 0.1 + 1e-18 rounds to 0.1: r = p exactly
  EXPECT_TRUE(on_segment(p, q, r));
  const Point s(1, std::nextafter(0.1, 1.0), 0.2);  // one ulp off the line
  EXPECT_FALSE(on_segment(p, q, s));
}

TEST(Segment, KindsInThePlanarModel) {
  EXPECT_EQ(kind(Segment(Point(1, 0, 0), Point(2, 1, 1))), SegmentKind::front);
  EXPECT_EQ(kind(Segment(Point(-1, 0, 0), Point(-2, 1, 1))), SegmentKind::back);
  EXPECT_EQ(kind(Segment(Point(1, 0, 0), Point(-2, 1, 1))), SegmentKind::crossing);
  EXPECT_EQ(kind(Segment(Point(-1, 0, 0), Point(2, 1, 1))), SegmentKind::crossing);
  EXPECT_EQ(kind(Segment(Point(1, 0, 0), Point(0, 1, 1))), SegmentKind::front_ray);
  EXPECT_EQ(kind(Segment(Point(0, 1, 1), Point(-1, 0, 0))), SegmentKind::back_ray);
  EXPECT_EQ(kind(Segment(Point(0, 1, 0), Point(0, 1, 1))), SegmentKind::on_infinity);
  EXPECT_STREQ(to_string(SegmentKind::crossing), "crossing");
  EXPECT_STREQ(to_string(SegmentKind::on_infinity), "on_infinity");
  EXPECT_TRUE(crosses_infinity(ExactSegment(ExactPoint(1, 0, 0), ExactPoint(-2, 1, 1))));
  EXPECT_FALSE(crosses_infinity(ExactSegment(ExactPoint(1, 0, 0), ExactPoint(2, 1, 1))));
  EXPECT_THROW(point_at_infinity(Segment(Point(1, 0, 0), Point(2, 1, 1))), Undefined);
  EXPECT_THROW(point_at_infinity(Segment(Point(0, 1, 0), Point(0, 1, 1))), Undefined);
}

TYPED_TEST(SegmentT, CrossingSegmentsMeetOmegaOnTheSegment) {
  using T = TypeParam;
  Small g(12, 40);
  for (int i = 0; i < 2000 * scale(); ++i) {
    auto pa = g.triple(), qa = g.triple();
    if (pa[0] == 0 || qa[0] == 0) continue;
    if ((pa[0] > 0) == (qa[0] > 0)) qa = {-qa[0], -qa[1], -qa[2]};  // make the sides differ
    const auto P = coords(pt<T>(pa)), Q = coords(pt<T>(qa));
    if (same_point(P, combo(-1, Q, 0, Q))) continue;  // antipodes
    const BasicSegment<T> s(pt<T>(pa), pt<T>(qa));
    ASSERT_TRUE(crosses_infinity(s));
    const auto c = coords(point_at_infinity(s));
    ASSERT_EQ(c[0], 0);
    ASSERT_EQ(det_oracle(P, Q, c), 0);
    // c = |w_q| p + |w_p| q up to a positive factor.
    ASSERT_TRUE(same_point(c, combo(abs(Q[0]), P, abs(P[0]), Q)));
    // c is on the segment; the two planar pieces are half-rays of one side each, inside s.
    ASSERT_TRUE(contains(s, point_at_infinity(s)));
    const auto pieces = planar_pieces(s);
    ASSERT_EQ(pieces.size(), 2u);
    ASSERT_EQ(kind(pieces[0]), pa[0] > 0 ? SegmentKind::front_ray : SegmentKind::back_ray);
    ASSERT_EQ(kind(pieces[1]), pa[0] > 0 ? SegmentKind::back_ray : SegmentKind::front_ray);
    for (const auto& piece : pieces) {
      ASSERT_TRUE(contains(s, piece.source()) && contains(s, piece.target()));
      // A point inside the piece (a positive combination of its ends) is inside s.
      const auto m = coords(piece.source()), n = coords(piece.target());
      ASSERT_TRUE(contains(s, pt<T>(combo(1, m, 1, n))));
    }
  }
}

// Oracle of segment intersection: the null vector k of the 3×4 matrix [a b −c −d]; the
// closed arcs meet iff k (or −k) has no negative component. Used when that null space is a
// line (the two great circles are distinct and neither segment is degenerate).
struct NullVector {
  Integer k[4];
  bool unique = false;
};
NullVector null_vector(const std::array<Integer, 3>& a, const std::array<Integer, 3>& b,
                       const std::array<Integer, 3>& c, const std::array<Integer, 3>& d) {
  const std::array<Integer, 3> nc{-c[0], -c[1], -c[2]}, nd{-d[0], -d[1], -d[2]};
  NullVector n;
  n.k[0] = det_oracle(b, nc, nd);
  n.k[1] = -det_oracle(a, nc, nd);
  n.k[2] = det_oracle(a, b, nd);
  n.k[3] = -det_oracle(a, b, nc);
  n.unique = n.k[0] != 0 || n.k[1] != 0 || n.k[2] != 0 || n.k[3] != 0;
  return n;
}

TYPED_TEST(SegmentT, IntersectionMatchesNullVectorOracle) {
  using T = TypeParam;
  Small g(13, 8);
  int meet = 0, miss = 0;
  for (int i = 0; i < 4000 * scale(); ++i) {
    const auto A = coords(pt<T>(g.triple())), B = coords(pt<T>(g.triple())), C = coords(pt<T>(g.triple())),
               D = coords(pt<T>(g.triple()));
    if (same_point(A, combo(-1, B, 0, B)) || same_point(C, combo(-1, D, 0, D))) continue;
    if (same_point(A, B) || same_point(C, D)) continue;
    // Distinct great circles: a×b and c×d not parallel, i.e. some of c, d off the line ab.
    if (det_oracle(A, B, C) == 0 && det_oracle(A, B, D) == 0) continue;
    const NullVector n = null_vector(A, B, C, D);
    if (!n.unique) continue;
    bool nonneg = true, nonpos = true;
    for (const auto& k : n.k) {
      nonneg = nonneg && k >= 0;
      nonpos = nonpos && k <= 0;
    }
    const bool want = nonneg || nonpos;
    const BasicSegment<T> s(pt<T>(A), pt<T>(B)), t(pt<T>(C), pt<T>(D));
    ASSERT_EQ(intersects(s, t), want);
    ASSERT_EQ(intersects(t, s), want);
    ASSERT_EQ(intersects(opposite(s), t), want);
    // s meets t iff ¬s meets ¬t; and s and ¬t never both meet t's partner at the same point.
    ASSERT_EQ(intersects(antipode(s), antipode(t)), want);
    const auto x = intersection(s, t);
    if (!want) {
      ASSERT_TRUE(std::holds_alternative<std::monostate>(x));
      ++miss;
      continue;
    }
    ++meet;
    ASSERT_TRUE(std::holds_alternative<BasicPoint<T>>(x));
    const Integer sg = nonneg ? 1 : -1;
    const auto want_point = combo(sg * n.k[0], A, sg * n.k[1], B);  // = k2 c + k3 d
    ASSERT_TRUE(same_point(coords(std::get<BasicPoint<T>>(x)), want_point));
  }
  EXPECT_GT(meet, 200);
  EXPECT_GT(miss, 200);
}

TEST(Segment, DoublesWithExtremeExponentsAgreeWithTheirExactImages) {
  // Every double is an exact dyadic rational, so the double predicates must agree with the
  // Integer ones on to_exact of the same points, even when products overflow or underflow.
  std::mt19937_64 rng(16);
  std::uniform_real_distribution<double> m(-1, 1);
  std::uniform_int_distribution<int> e(-300, 300), pick(0, 3);
  auto coord = [&] { return pick(rng) == 0 ? 0.0 : std::ldexp(m(rng), e(rng)); };
  auto point = [&] {
    for (;;) {
      const double w = coord(), x = coord(), y = coord();
      if (w != 0 || x != 0 || y != 0) return Point(w, x, y);
    }
  };
  int met = 0;
  for (int i = 0; i < 1500 * scale(); ++i) {
    const Point a = point(), b = point(), c = point(), d = point();
    if (a == antipode(b) || c == antipode(d)) continue;
    const Segment s(a, b), t(c, d);
    const ExactSegment es(to_exact(a), to_exact(b)), et(to_exact(c), to_exact(d));
    ASSERT_EQ(intersects(s, t), intersects(es, et));
    ASSERT_EQ(on_segment(a, b, c), on_segment(to_exact(a), to_exact(b), to_exact(c)));
    ASSERT_EQ(kind(s), kind(es));
    const auto x = intersection(s, t);
    const auto ex = intersection(es, et);
    ASSERT_EQ(x.index(), ex.index());
    if (const auto* p = std::get_if<ExactPoint>(&ex)) {
      ++met;
      ASSERT_EQ(std::get<Point>(x), to_double(*p));  // computed exactly, rounded once
    }
    if (crosses_infinity(s)) {
      ASSERT_EQ(point_at_infinity(s), to_double(point_at_infinity(es)));
    }
  }
  EXPECT_GT(met, 100);
}

TYPED_TEST(SegmentT, AgreesWithPolygonSegmentsIntersect) {
  // polygon.hpp (chapter 05) has its own segment test, written independently: a cross-check.
  using T = TypeParam;
  Small g(17, 4);
  for (int i = 0; i < 3000 * scale(); ++i) {
    const auto a = pt<T>(g.triple()), b = pt<T>(g.triple()), c = pt<T>(g.triple()), d = pt<T>(g.triple());
    if (a == antipode(b) || c == antipode(d)) continue;
    ASSERT_EQ(intersects(BasicSegment<T>(a, b), BasicSegment<T>(c, d)), segments_intersect(a, b, c, d));
  }
  EXPECT_EQ(planar_pieces(BasicSegment<T>(pt<T>(1, 0, 0), pt<T>(1, 1, 0))).size(), 1u);
}

TEST(Segment, AntipodalCrossingIsNotAnIntersection) {
  // In R² these two straddle each other; in T² the front segment meets ¬t, not t.
  const Segment s(Point(1, -1, 0), Point(1, 1, 0));
  const Segment t(Point(-1, 0, 1), Point(-1, 0, -1));  // the back copy of the vertical segment
  EXPECT_EQ(orient(s.source(), s.target(), t.source()) * orient(s.source(), s.target(), t.target()), NEGATIVE);
  EXPECT_EQ(orient(t.source(), t.target(), s.source()) * orient(t.source(), t.target(), s.target()), NEGATIVE);
  EXPECT_FALSE(intersects(s, t));
  EXPECT_TRUE(intersects(s, antipode(t)));
  EXPECT_EQ(std::get<Point>(intersection(s, antipode(t))), Point(1, 0, 0));
}

TYPED_TEST(SegmentT, CollinearAndDegenerateIntersections) {
  using T = TypeParam;
  // On the line y = 0 of the front side, points [1, x, 0].
  auto P = [](long x) { return pt<T>(1, x, 0); };
  const BasicSegment<T> s(P(0), P(4));
  auto check_piece = [&](const BasicSegment<T>& t, long lo, long hi) {
    const auto x = intersection(s, t);
    if (lo == hi) {
      ASSERT_TRUE(std::holds_alternative<BasicPoint<T>>(x));
      EXPECT_EQ(std::get<BasicPoint<T>>(x), P(lo));
    } else {
      ASSERT_TRUE(std::holds_alternative<BasicSegment<T>>(x));
      EXPECT_EQ(std::get<BasicSegment<T>>(x), BasicSegment<T>(P(lo), P(hi)));
    }
  };
  check_piece(BasicSegment<T>(P(2), P(6)), 2, 4);
  check_piece(BasicSegment<T>(P(6), P(2)), 2, 4);  // oriented like s
  check_piece(BasicSegment<T>(P(-3), P(9)), 0, 4);
  check_piece(BasicSegment<T>(P(1), P(3)), 1, 3);
  check_piece(BasicSegment<T>(P(4), P(7)), 4, 4);
  check_piece(BasicSegment<T>(P(2), P(2)), 2, 2);
  EXPECT_FALSE(intersects(s, BasicSegment<T>(P(5), P(7))));
  EXPECT_FALSE(intersects(s, BasicSegment<T>(P(5), P(5))));
  // The same line through Ω: the back copy of [0, 4] does not meet s. The segment from the
  // front point x = 2 to the back point ¬(x = 6) leaves 2 away from 6 (§3.4: "in the direction
  // opposite to ¬p1"): the front half-line x ≤ 2, then a back half-line. It meets s in [0, 2].
  EXPECT_FALSE(intersects(s, antipode(s)));
  check_piece(BasicSegment<T>(P(2), antipode(P(6))), 0, 2);
  // From front x = 6 to the back point ¬(x = 2): its front part is x ≥ 6.
  EXPECT_FALSE(intersects(s, BasicSegment<T>(P(6), antipode(P(2)))));
  // Along Ω.
  const BasicSegment<T> o(pt<T>(0, 1, 0), pt<T>(0, 0, 1)), o2(pt<T>(0, 1, 1), pt<T>(0, -1, 1));
  ASSERT_TRUE(std::holds_alternative<BasicSegment<T>>(intersection(o, o2)));
  EXPECT_EQ(std::get<BasicSegment<T>>(intersection(o, o2)), BasicSegment<T>(pt<T>(0, 1, 1), pt<T>(0, 0, 1)));
}

TYPED_TEST(SegmentT, CollinearIntersectionsMatchParameterOracle) {
  using T = TypeParam;
  // Points αu + βv of one great circle, parametrised by the 2-D vector (α, β); on a circle
  // the arcs are intervals of angle, and an integer oracle compares them through the 2-D
  // cross product.
  Small g(14, 5);
  int overlaps = 0;
  for (int i = 0; i < 1500 * scale(); ++i) {
    const auto U = coords(pt<T>(g.triple())), V = coords(pt<T>(g.triple()));
    if (is_zero({U[1] * V[2] - U[2] * V[1], U[2] * V[0] - U[0] * V[2], U[0] * V[1] - U[1] * V[0]})) continue;
    std::array<long, 2> e[4];
    for (auto& x : e)
      do x = {g(), g()};
      while (x[0] == 0 && x[1] == 0);
    auto cross2 = [](const std::array<long, 2>& a, const std::array<long, 2>& b) { return a[0] * b[1] - a[1] * b[0]; };
    auto dot2 = [](const std::array<long, 2>& a, const std::array<long, 2>& b) { return a[0] * b[0] + a[1] * b[1]; };
    auto antipodal = [&](const auto& a, const auto& b) { return cross2(a, b) == 0 && dot2(a, b) < 0; };
    if (antipodal(e[0], e[1]) || antipodal(e[2], e[3])) continue;
    // x on the 2-D arc ab (shorter than half a turn): x = αa + βb, α, β ≥ 0.
    auto on_arc = [&](const auto& a, const auto& b, const auto& x) {
      if (cross2(a, b) == 0) return cross2(a, x) == 0 && dot2(a, x) > 0;  // a = b
      const long al = cross2(x, b) * cross2(a, b), be = cross2(a, x) * cross2(a, b);
      return al >= 0 && be >= 0;
    };
    const bool want = on_arc(e[0], e[1], e[2]) || on_arc(e[0], e[1], e[3]) || on_arc(e[2], e[3], e[0]) ||
                      on_arc(e[2], e[3], e[1]);
    auto lift = [&](const std::array<long, 2>& a) { return pt<T>(combo(a[0], U, a[1], V)); };
    const BasicSegment<T> s(lift(e[0]), lift(e[1])), t(lift(e[2]), lift(e[3]));
    ASSERT_EQ(intersects(s, t), want);
    const auto x = intersection(s, t);
    ASSERT_EQ(std::holds_alternative<std::monostate>(x), !want);
    if (auto* seg = std::get_if<BasicSegment<T>>(&x)) {
      ++overlaps;
      // The piece lies in both, and its ends come from the four endpoints.
      ASSERT_TRUE(contains(s, seg->source()) && contains(t, seg->source()));
      ASSERT_TRUE(contains(s, seg->target()) && contains(t, seg->target()));
      ASSERT_FALSE(seg->is_degenerate());
      // Oriented like s: source before target when walking from s.source().
      ASSERT_TRUE(on_segment(s.source(), seg->target(), seg->source()));
    }
    if (auto* p = std::get_if<BasicPoint<T>>(&x)) {
      ASSERT_TRUE(contains(s, *p) && contains(t, *p));
    }
  }
  EXPECT_GT(overlaps, 50);
}

// ------------------------------------------------------------------ rays, vectors, directions

TYPED_TEST(SegmentT, DirectionFromTwoPoints) {
  using T = TypeParam;
  using D = BasicDirection<T>;
  EXPECT_EQ(direction(pt<T>(1, 0, 0), pt<T>(1, 3, 4)), D(T(3), T(4)));
  EXPECT_EQ(direction(pt<T>(2, 2, 2), pt<T>(1, 3, 4)), D(T(2), T(3)));
  // Two back points: walking from p to q in the back plane goes the same Cartesian way.
  EXPECT_EQ(direction(pt<T>(-1, 0, 0), pt<T>(-1, -3, -4)), D(T(-3), T(-4)));
  // Front to back: where the segment crosses Ω.
  const auto p = pt<T>(1, 1, 0), q = pt<T>(-1, 0, -2);
  EXPECT_EQ(direction(p, q).point(), point_at_infinity(BasicSegment<T>(p, q)));
  // From a point at infinity one comes in: the opposite direction.
  EXPECT_EQ(direction(pt<T>(0, 1, 0), pt<T>(1, 5, 5)), D(T(-1), T(0)));
  EXPECT_EQ(direction(pt<T>(1, 5, 5), pt<T>(0, 1, 0)), D(T(1), T(0)));
  EXPECT_THROW(direction(pt<T>(0, 1, 0), pt<T>(0, 0, 1)), Undefined);
  EXPECT_THROW(direction(pt<T>(1, 1, 1), pt<T>(-1, -1, -1)), Undefined);
  EXPECT_THROW(direction(pt<T>(1, 1, 1), pt<T>(2, 2, 2)), Undefined);
  EXPECT_THROW(D(T(0), T(0)), Undefined);
  try {
    D d(pt<T>(1, 0, 0));
    ADD_FAILURE();
  } catch (const Undefined& e) {
    EXPECT_STREQ(e.what(), "a direction is a point at infinity (w = 0)");
  }
  EXPECT_EQ(opposite(D(T(1), T(2))), D(T(-2), T(-4)));
  // Direction of a line: its positive side on the left.
  const auto l = join(pt<T>(1, 0, 0), pt<T>(1, 1, 0));
  EXPECT_EQ(direction(l), D(T(1), T(0)));
  EXPECT_THROW(direction(omega<T>()), Undefined);
}

TYPED_TEST(SegmentT, DirectionIsWhereTheHalfCircleFromPThroughQMeetsOmega) {
  using T = TypeParam;
  Small g(15, 20);
  for (int i = 0; i < 2000 * scale(); ++i) {
    const auto P = coords(pt<T>(g.triple())), Q = coords(pt<T>(g.triple()));
    if (P[0] == 0) continue;
    if (same_point(P, Q) || same_point(P, combo(-1, Q, 0, Q))) continue;
    const auto d = coords(direction(pt<T>(P), pt<T>(Q)).point());
    // Oracle: d = αp + βq with w = 0 and β > 0 (the first point of Ω after p towards q):
    // α w_p + β w_q = 0 gives (α, β) = s(−w_q, w_p) with s = sign w_p.
    const Integer s = P[0] > 0 ? 1 : -1;
    ASSERT_TRUE(same_point(d, combo(-s * Q[0], P, s * P[0], Q)));
    ASSERT_EQ(d[0], 0);
    // The ray from p through q contains q iff q is on p's side of T² (or on Ω).
    const BasicRay<T> r = BasicRay<T>::through(pt<T>(P), pt<T>(Q));
    const bool want = Q[0] == 0 || (Q[0] > 0) == (P[0] > 0);
    ASSERT_EQ(contains(r, pt<T>(Q)), want);
    ASSERT_TRUE(contains(r, pt<T>(P)));
    ASSERT_TRUE(contains(r, r.target()));
  }
}

TYPED_TEST(SegmentT, RaysAreSegmentsToInfinity) {
  using T = TypeParam;
  const BasicRay<T> r(pt<T>(1, 1, 1), BasicDirection<T>(T(1), T(0)));
  EXPECT_TRUE(contains(r, pt<T>(1, 100, 1)));
  EXPECT_FALSE(contains(r, pt<T>(1, 0, 1)));
  EXPECT_FALSE(contains(r, pt<T>(-1, -100, -1)));  // the back copy is not on the ray
  EXPECT_TRUE(contains(r, pt<T>(0, 5, 0)));
  EXPECT_EQ(kind(r.segment()), SegmentKind::front_ray);
  EXPECT_THROW(BasicRay<T>(pt<T>(0, 1, 1), BasicDirection<T>(T(1), T(0))), Undefined);
  EXPECT_EQ(BasicRay<T>(pt<T>(1, 1, 1), pt<T>(0, 3, 0)), r);
  EXPECT_THROW(BasicRay<T>(pt<T>(1, 1, 1), pt<T>(1, 3, 0)), Undefined);
  EXPECT_THROW(BasicRay<T>::through(pt<T>(1, 1, 1), pt<T>(2, 2, 2)), Undefined);
  EXPECT_EQ(BasicRay<T>::through(pt<T>(1, 1, 1), pt<T>(1, 4, 1)), r);
  // From a back point: the ray through another back point stays on the back side.
  const auto br = BasicRay<T>::through(pt<T>(-1, 0, 0), pt<T>(-1, -2, 0));
  EXPECT_EQ(kind(br.segment()), SegmentKind::back_ray);
  EXPECT_TRUE(contains(br, pt<T>(-1, -1, 0)));
}

TYPED_TEST(SegmentT, VectorsAreDifferences) {
  using T = TypeParam;
  using V = BasicVector<T>;
  EXPECT_EQ(vector(pt<T>(1, 1, 1), pt<T>(1, 4, 5)), V::cartesian(T(3), T(4)));
  EXPECT_EQ(vector(pt<T>(2, 2, 2), pt<T>(1, 4, 5)), V::cartesian(T(3), T(4)));
  // Front to back: beyond infinity (w < 0).
  EXPECT_LT(vector(pt<T>(1, 0, 0), pt<T>(-1, 1, 1)).w(), 0);
  // To a point at infinity: an infinite vector, pointing there.
  const auto vi = vector(pt<T>(-1, 0, 0), pt<T>(0, 1, 2));
  EXPECT_EQ(vi.w(), 0);
  EXPECT_EQ(direction(vi), BasicDirection<T>(T(-1), T(-2)));
  EXPECT_THROW(vector(pt<T>(0, 1, 0), pt<T>(1, 0, 0)), Undefined);
  EXPECT_THROW(vector(pt<T>(1, 2, 3), pt<T>(-1, -2, -3)), Undefined);
  EXPECT_THROW(V(T(-2), T(0), T(0)), Undefined);  // tip ¬O
  EXPECT_NO_THROW(V(T(2), T(0), T(0)));           // the null vector
  EXPECT_THROW(direction(V(T(2), T(0), T(0))), Undefined);
  EXPECT_EQ(direction(V(T(-1), T(3), T(0))), BasicDirection<T>(T(1), T(0)));
}

TYPED_TEST(SegmentT, ToStringOfEveryPrimitive) {
  using T = TypeParam;
  EXPECT_EQ(to_string(BasicSegment<T>(pt<T>(1, 0, 0), pt<T>(-1, 1, 0))), "segment([1, 0, 0] -> [-1, 1, 0])");
  EXPECT_EQ(to_string(BasicRay<T>(pt<T>(2, 0, 0), BasicDirection<T>(T(0), T(-1)))), "ray([2, 0, 0] -> [0, 0, -1])");
  EXPECT_EQ(to_string(BasicDirection<T>(T(3), T(-4))), "direction(3, -4)");
  EXPECT_EQ(to_string(BasicVector<T>(T(-1), T(2), T(5))), "vector[-1, 2, 5]");
}

TEST(Segment, ToString) {
  EXPECT_EQ(to_string(Segment(Point(1, 0, 0), Point(1, 1, 0))), "segment([1, 0, 0] -> [1, 1, 0])");
  EXPECT_EQ(to_string(Direction(1, 2)), "direction(1, 2)");
  EXPECT_EQ(to_string(ExactVector(1, 2, 3)), "vector[1, 2, 3]");
  EXPECT_EQ(to_string(Ray(Point(1, 0, 0), Direction(0, 1))), "ray([1, 0, 0] -> [0, 0, 1])");
}

}  // namespace
}  // namespace t2
