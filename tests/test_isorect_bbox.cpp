// Iso-rectangles and bounding boxes of T² (seed 000 §4.1.7–4.1.8), for double and Integer
// coordinates, against rational Cartesian oracles and membership oracles.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <variant>
#include <vector>

#include "t2/kernel/bbox.hpp"
#include "t2/kernel/isorect.hpp"
#include "test_prim.hpp"

namespace t2 {
namespace {

using testing::combo;
using testing::coords;
using testing::pt;
using testing::scale;
using testing::Small;

template <class T>
class RectT : public ::testing::Test {};
TYPED_TEST_SUITE(RectT, testing::CoordinateTypes);

using testing::value;
using testing::pos;

template <class T>
BasicT1<T> random_extent(Small& g, bool allow_infinite) {
  std::uniform_int_distribution<int> kind(0, allow_infinite ? 5 : 3);
  const int k = kind(g.rng);
  if (k == 4) return BasicT1<T>::plus_infinity();
  if (k == 5) return BasicT1<T>::minus_infinity();
  long w = 0;
  while (w <= 0) w = g();
  return BasicT1<T>(T(w), T(g()));
}

TYPED_TEST(RectT, VerticesMatchCartesianOracle) {
  using T = TypeParam;
  Small g(31, 9);
  for (int i = 0; i < 2000 * scale(); ++i) {
    auto at = g.triple();
    if (at[0] == 0) continue;
    const auto a = pt<T>(at);
    const auto dx = random_extent<T>(g, false), dy = random_extent<T>(g, false);
    const Sign o = (i % 2) ? POSITIVE : NEGATIVE;
    const BasicIsoRect<T> r(a, dx, dy, o);
    const auto A = pos(coords(a));
    const Rational DX = value(dx), DY = value(dy);
    const std::array<Rational, 2> want[4] = {A, {A[0] + DX, A[1]}, {A[0] + DX, A[1] + DY}, {A[0], A[1] + DY}};
    for (int k = 0; k < 4; ++k) {
      const auto v = coords(r.corner(k));
      ASSERT_EQ(sign_of(v[0]), sign_of(Integer(at[0])));  // every vertex on a's side
      ASSERT_EQ(pos(v)[0], want[k][0]);
      ASSERT_EQ(pos(v)[1], want[k][1]);
    }
    // The boundary traversed with the stored orientation.
    const Sign turn = orient(r.vertex(0), r.vertex(1), r.vertex(3));
    if (DX != 0 && DY != 0) {
      ASSERT_EQ(turn, o);
      ASSERT_EQ(orient(r.vertex(1), r.vertex(2), r.vertex(3)), o);
    } else {
      ASSERT_EQ(turn, ZERO);
    }
    // As a set the rectangle is its box: corners in, and points in by the Cartesian oracle.
    for (int k = 0; k < 4; ++k) ASSERT_TRUE(contains(r, r.corner(k)));
    const auto inner = pt<T>(combo(1, combo(1, coords(r.corner(0)), 1, coords(r.corner(2))), 0, coords(a)));
    ASSERT_TRUE(contains(r, inner));  // the midpoint of the diagonal (same-side corners)
    ASSERT_FALSE(contains(r, antipode(inner)));
    // Opposite corners give back the same rectangle.
    const auto r2 = iso_rect(a, r.corner(2), o);
    for (int k = 0; k < 4; ++k) ASSERT_EQ(r2.vertex(k), r.vertex(k));
  }
}

TYPED_TEST(RectT, InfiniteExtentsAndTheCorrectedCornerC) {
  using T = TypeParam;
  using T1v = BasicT1<T>;
  // a front, Δx = +∞: b is the direction +x; Δy finite: c = b.
  const BasicIsoRect<T> r1(pt<T>(1, 2, 3), T1v::plus_infinity(), T1v(T(1), T(4)));
  EXPECT_EQ(r1.corner(1), pt<T>(0, 1, 0));
  EXPECT_EQ(r1.corner(2), pt<T>(0, 1, 0));
  EXPECT_EQ(r1.corner(3), pt<T>(1, 2, 7));
  // On the back side the same extent reaches the opposite point of Ω (Cartesian x grows
  // towards [0, −1, 0] there, since a back point with Cartesian x is [−1, −x, ...]).
  const BasicIsoRect<T> r2(pt<T>(-1, 2, 3), T1v::plus_infinity(), T1v(T(1), T(4)));
  EXPECT_EQ(r2.corner(1), pt<T>(0, -1, 0));
  // Both infinite: c = [0, w_a x_Δx, w_a y_Δy], on the arc bd of Ω, also for a at the
  // origin (where the seed's [0, x_a, y_a] would be the non-point [0, 0, 0]).
  Small g(32, 9);
  for (int i = 0; i < 500 * scale(); ++i) {
    const auto at = g.triple();
    if (at[0] == 0) continue;
    const T sx(g() < 0 ? -1 : 1), sy(g() < 0 ? -1 : 1);
    const BasicIsoRect<T> r(pt<T>(at), T1v(T(0), sx), T1v(T(0), sy));
    const auto b = r.corner(1), c = r.corner(2), d = r.corner(3);
    ASSERT_TRUE(is_at_infinity(c));
    ASSERT_TRUE(on_segment(b, d, c));
    ASSERT_FALSE(c == b || c == d);
    // The limit oracle: far along the diagonal the finite corner c_R = a + (R sx, R sy)
    // turns towards c: Δ(c_R, a, c) = 0 — c is the point at infinity of the ray a → c_R.
    const Integer R("1000000000000000000000");
    const ExactIsoRect far(testing::exact(pt<T>(at)), ExactT1(Integer(1), Integer(R * Integer(sx))),
                           ExactT1(Integer(1), Integer(R * Integer(sy))));
    ASSERT_EQ(orient(testing::exact(pt<T>(at)), far.corner(2), testing::exact(c)), ZERO);
    ASSERT_TRUE(on_segment(testing::exact(pt<T>(at)), testing::exact(c), far.corner(2)));
    // iso_rect(a, c) with c at infinity gives back the same corner.
    ASSERT_EQ(iso_rect(pt<T>(at), c).corner(2), c);
    // The seed's corner [0, x_a, y_a] is off the arc bd in general.
    if ((at[0] * at[1] * sx < 0 || at[0] * at[2] * sy < 0) && (at[1] != 0 || at[2] != 0)) {
      ASSERT_FALSE(on_segment(b, d, pt<T>(0, at[1], at[2])));
    }
  }
}

TYPED_TEST(RectT, UndefinedRectangles) {
  using T = TypeParam;
  using T1v = BasicT1<T>;
  EXPECT_THROW(BasicIsoRect<T>(pt<T>(0, 1, 1), T1v(T(1), T(1)), T1v(T(1), T(1))), Undefined);
  EXPECT_THROW(BasicIsoRect<T>(pt<T>(1, 1, 1), T1v(T(-1), T(1)), T1v(T(1), T(1))), Undefined);
  EXPECT_THROW(BasicIsoRect<T>(pt<T>(1, 1, 1), T1v(T(1), T(1)), T1v(T(-1), T(-1))), Undefined);
  EXPECT_THROW(BasicIsoRect<T>(pt<T>(1, 1, 1), T1v(T(1), T(1)), T1v(T(1), T(1)), ZERO), BadInput);
  EXPECT_THROW(iso_rect(pt<T>(1, 1, 1), pt<T>(-1, 3, 3)), Undefined);
  EXPECT_THROW(iso_rect(pt<T>(1, 1, 1), pt<T>(0, 1, 0)), Undefined);
  EXPECT_THROW(BasicBBox<T>(pt<T>(1, 1, 1), T1v(T(-1), T(1)), T1v(T(1), T(1))), Undefined);
  const BasicIsoRect<T> r(pt<T>(1, 0, 0), T1v(T(1), T(2)), T1v(T(1), T(3)));
  EXPECT_EQ(opposite(r).orientation(), NEGATIVE);
  EXPECT_EQ(opposite(r).vertex(1), r.vertex(3));
}

// ------------------------------------------------------------------------------------ boxes

// Oracle membership of a proper point in a box given by rational bounds (nullopt = infinite).
struct Bounds {
  int side;
  std::optional<Rational> lo[2], hi[2];
};
template <class T>
Bounds bounds_of(const BasicBBox<T>& b) {
  Bounds r;
  r.side = b.side() == Side::front ? 1 : -1;
  const BasicT1<T> l[2] = {b.xmin(), b.ymin()}, h[2] = {b.xmax(), b.ymax()};
  for (int k = 0; k < 2; ++k) {
    if (!is_infinite(l[k])) r.lo[k] = value(l[k]);
    if (!is_infinite(h[k])) r.hi[k] = value(h[k]);
  }
  return r;
}

template <class T>
BasicBBox<T> random_box(Small& g, int side) {
  for (;;) {
    auto at = g.triple();
    if (at[0] == 0) continue;
    if ((at[0] > 0 ? 1 : -1) != side) at = {-at[0], -at[1], -at[2]};
    return BasicBBox<T>(pt<T>(at), random_extent<T>(g, true), random_extent<T>(g, true));
  }
}

TYPED_TEST(RectT, BoxBoundsAndContainsMatchOracle) {
  using T = TypeParam;
  Small g(33, 7);
  for (int i = 0; i < 1000 * scale(); ++i) {
    const auto b = random_box<T>(g, (i % 2) ? 1 : -1);
    const auto A = pos(coords(b.a()));
    const Bounds bd = bounds_of(b);
    // Oracle bounds straight from a and Δ.
    const BasicT1<T> D[2] = {b.dx(), b.dy()};
    for (int k = 0; k < 2; ++k) {
      if (is_infinite(D[k])) {
        const bool up = D[k].x() > 0;
        ASSERT_EQ(up ? bd.lo[k] : bd.hi[k], A[k]);
        ASSERT_FALSE(up ? bd.hi[k].has_value() : bd.lo[k].has_value());
      } else {
        const Rational e = A[k] + value(D[k]);
        ASSERT_EQ(*bd.lo[k], std::min(A[k], e));
        ASSERT_EQ(*bd.hi[k], std::max(A[k], e));
      }
    }
    for (int j = 0; j < 20; ++j) {
      const auto p = g.triple();
      const auto P = coords(pt<T>(p));
      bool want = false;
      if (p[0] != 0 && (p[0] > 0 ? 1 : -1) == bd.side) {
        const auto C = pos(P);
        want = true;
        for (int k = 0; k < 2; ++k) {
          if (bd.lo[k] && C[k] < *bd.lo[k]) want = false;
          if (bd.hi[k] && C[k] > *bd.hi[k]) want = false;
        }
      } else if (p[0] == 0) {
        // On Ω: every non-zero component must point a way the box runs off to (mirrored on
        // the back side, where Cartesian +x leads to [0, −1, 0]).
        const long comp[2] = {p[1], p[2]};
        want = true;
        for (int k = 0; k < 2; ++k) {
          const int dir = bd.side * (comp[k] > 0 ? 1 : comp[k] < 0 ? -1 : 0);
          if (dir > 0 && bd.hi[k].has_value()) want = false;
          if (dir < 0 && bd.lo[k].has_value()) want = false;
        }
      }
      ASSERT_EQ(contains(b, pt<T>(p)), want) << to_string(b) << " " << to_string(pt<T>(p));
    }
  }
}

TYPED_TEST(RectT, BBoxOfPointsIsTheSmallestBox) {
  using T = TypeParam;
  Small g(34, 9);
  int undefined = 0;
  for (int i = 0; i < 1000 * scale(); ++i) {
    std::vector<BasicPoint<T>> pts;
    const int side = (i % 2) ? 1 : -1;
    const int n = 1 + (i % 5);
    for (int k = 0; k < n; ++k) {
      auto p = g.triple();
      if (k > 0 && g() % 3 == 0) p[0] = 0;  // many points at infinity
      if (p[0] == 0 && p[1] == 0 && p[2] == 0) p[1] = 1;
      if (p[0] != 0 && (p[0] > 0 ? 1 : -1) != side) p = {-p[0], -p[1], -p[2]};
      if (k == 0 && p[0] == 0) p[0] = side;
      pts.push_back(pt<T>(p));
    }
    std::optional<BasicBBox<T>> made;
    try {
      made = bbox(std::span<const BasicPoint<T>>(pts));
    } catch (const Undefined&) {
    }
    // Oracle: an axis is unbounded both ways iff points at infinity pull it both ways.
    bool both = false;
    for (int k = 1; k <= 2; ++k) {
      bool up = false, down = false;
      for (const auto& p : pts) {
        const auto P = coords(p);
        if (P[0] != 0) continue;
        if (side * sgn(P[k]) > 0) up = true;
        if (side * sgn(P[k]) < 0) down = true;
      }
      both = both || (up && down);
    }
    if (both) {
      ASSERT_FALSE(made.has_value());
      ++undefined;
      continue;
    }
    ASSERT_TRUE(made.has_value());
    const BasicBBox<T>& b = *made;
    ASSERT_EQ(static_cast<int>(b.side()), side);
    for (const auto& p : pts) ASSERT_TRUE(contains(b, p)) << to_string(b) << to_string(p);
    // Smallest: each finite bound is attained by a proper point.
    const Bounds bd = bounds_of(b);
    for (int k = 0; k < 2; ++k) {
      for (const auto* bound : {&bd.lo[k], &bd.hi[k]}) {
        if (!bound->has_value()) continue;
        bool hit = false;
        for (const auto& p : pts)
          if (is_proper(p) && pos(coords(p))[k] == **bound) hit = true;
        ASSERT_TRUE(hit);
      }
    }
  }
  EXPECT_GT(undefined, 10);
  EXPECT_THROW(bbox({pt<T>(1, 0, 0), pt<T>(-1, 1, 1)}), Undefined);
  EXPECT_THROW(bbox({pt<T>(0, 1, 0)}), Undefined);
  EXPECT_THROW(bbox(std::span<const BasicPoint<T>>()), BadInput);
}

TYPED_TEST(RectT, UnionFollowsTheSeedsRuleLiterally) {
  using T = TypeParam;
  Small g(35, 7);
  int defined = 0, undefined = 0;
  for (int i = 0; i < 2000 * scale(); ++i) {
    const auto b1 = random_box<T>(g, (i % 3) ? 1 : -1), b2 = random_box<T>(g, (i % 5) ? 1 : -1);
    // §4.1.8: different sides → undefined; an infinite extent on an axis → defined only if
    // b1.Δ ≠ −b2.Δ (as points of T¹).
    bool want = b1.side() == b2.side();
    const BasicT1<T> d1[2] = {b1.dx(), b1.dy()}, d2[2] = {b2.dx(), b2.dy()};
    for (int k = 0; k < 2; ++k)
      if ((is_infinite(d1[k]) || is_infinite(d2[k])) && d1[k] == antipode(d2[k])) want = false;
    try {
      const auto u = b1 + b2;
      ASSERT_TRUE(want);
      ++defined;
      // It holds both boxes: every corner, and Ω parts.
      for (int k = 0; k < 4; ++k) {
        ASSERT_TRUE(contains(u, b1.vertex(k)));
        ASSERT_TRUE(contains(u, b2.vertex(k)));
      }
      // And its bounds are the min and max of theirs.
      const Bounds U = bounds_of(u), B1 = bounds_of(b1), B2 = bounds_of(b2);
      for (int k = 0; k < 2; ++k) {
        if (!B1.lo[k] || !B2.lo[k]) {
          ASSERT_FALSE(U.lo[k]);
        } else {
          ASSERT_EQ(*U.lo[k], std::min(*B1.lo[k], *B2.lo[k]));
        }
        if (!B1.hi[k] || !B2.hi[k]) {
          ASSERT_FALSE(U.hi[k]);
        } else {
          ASSERT_EQ(*U.hi[k], std::max(*B1.hi[k], *B2.hi[k]));
        }
      }
    } catch (const Undefined&) {
      ASSERT_FALSE(want);
      ++undefined;
    }
  }
  EXPECT_GT(defined, 300);
  EXPECT_GT(undefined, 300);
}

TYPED_TEST(RectT, IntersectionIsAlwaysDefinedAndMatchesMembership) {
  using T = TypeParam;
  Small g(36, 6);
  int boxes = 0, omega = 0, empty = 0;
  for (int i = 0; i < 1500 * scale(); ++i) {
    const auto b1 = random_box<T>(g, (i % 3) ? 1 : -1), b2 = random_box<T>(g, (i % 5) ? 1 : -1);
    const auto x = intersection(b1, b2);
    auto in_x = [&](const BasicPoint<T>& p) {
      if (const auto* b = std::get_if<BasicBBox<T>>(&x)) return contains(*b, p);
      if (const auto* s = std::get_if<BasicSegment<T>>(&x)) return contains(*s, p);
      return false;
    };
    if (std::holds_alternative<BasicBBox<T>>(x)) ++boxes;
    if (std::holds_alternative<BasicSegment<T>>(x)) {
      ++omega;
      const auto& s = std::get<BasicSegment<T>>(x);
      ASSERT_EQ(kind(s), SegmentKind::on_infinity);
    }
    if (std::holds_alternative<std::monostate>(x)) ++empty;
    for (int j = 0; j < 30; ++j) {
      auto p = g.triple();
      if (j % 3 == 0) p[0] = 0;  // many points at infinity
      if (p[1] == 0 && p[2] == 0) continue;
      ASSERT_EQ(in_x(pt<T>(p)), contains(b1, pt<T>(p)) && contains(b2, pt<T>(p)));
    }
    // Corners of both boxes: in the intersection iff in both.
    for (int k = 0; k < 4; ++k) {
      ASSERT_EQ(in_x(b1.vertex(k)), contains(b2, b1.vertex(k)));
      ASSERT_EQ(in_x(b2.vertex(k)), contains(b1, b2.vertex(k)));
    }
  }
  EXPECT_GT(boxes, 100);
  EXPECT_GT(omega, 30);
  EXPECT_GT(empty, 100);
}

TYPED_TEST(RectT, ToString) {
  using T = TypeParam;
  using T1v = BasicT1<T>;
  EXPECT_EQ(to_string(BasicIsoRect<T>(pt<T>(1, 0, 0), T1v(T(1), T(2)), T1v(T(1), T(3)), NEGATIVE)),
            "iso_rect([1, 0, 0], [1, 0, 3], [1, 2, 3], [1, 2, 0], -)");
  EXPECT_EQ(to_string(BasicBBox<T>(pt<T>(-1, 0, 0), T1v::minus_infinity(), T1v(T(1), T(3)))),
            "bbox(x in [0, -1]..[1, 0], y in [1, 0]..[1, 3], back)");
}

TEST(BBox, Figure46FrontAndBackBoxesMeetAtInfinity) {
  // A front box unbounded towards −x and a back box whose Cartesian x grows to +∞ (which on
  // the back side is the point [0, −1, 0]): they share exactly that point of Ω.
  const ExactBBox f(ExactPoint(1, 0, 0), ExactT1::minus_infinity(), ExactT1(1, 2));
  const ExactBBox b(ExactPoint(-1, -3, 1), ExactT1::plus_infinity(), ExactT1(1, 5));
  const auto x = intersection(f, b);
  ASSERT_TRUE(std::holds_alternative<ExactSegment>(x));
  EXPECT_EQ(std::get<ExactSegment>(x), ExactSegment(ExactPoint(0, -1, 0), ExactPoint(0, -1, 0)));
  EXPECT_THROW(f + b, Undefined);
  // Unbounded the same way in the Cartesian sense of each side: different points of Ω.
  const ExactBBox b2(ExactPoint(-1, -3, 1), ExactT1::minus_infinity(), ExactT1(1, 5));
  EXPECT_TRUE(std::holds_alternative<std::monostate>(intersection(f, b2)));
  // Same side, disjoint proper parts, a common point at infinity.
  const BBox s1(Point(1, 0, 0), T1::plus_infinity(), T1(1, 1)), s2(Point(1, 0, 5), T1::plus_infinity(), T1(1, 1));
  const auto y = intersection(s1, s2);
  ASSERT_TRUE(std::holds_alternative<Segment>(y));
  EXPECT_EQ(std::get<Segment>(y).source(), Point(0, 1, 0));
  // Overlapping quadrants: a box.
  const BBox q1(Point(1, 0, 0), T1::plus_infinity(), T1::plus_infinity()), q2(Point(1, 3, -2), T1(1, 4), T1::plus_infinity());
  const auto z = intersection(q1, q2);
  ASSERT_TRUE(std::holds_alternative<BBox>(z));
  EXPECT_EQ(to_string(std::get<BBox>(z)), "bbox(x in [1, 3]..[1, 7], y in [1, 0]..[0, 1], front)");
}

// Containment in a box of doubles is a predicate, so it is exact although the box's far end
// a + Δ is a sum that doubles round. Oracle: the Cartesian interval [a, a + Δ] in rationals, for
// the doubles next to the rounded end (one of which is just outside the exact interval whenever
// the sum rounds). The rectangle of exercise 15b's large test that found it comes first.
TEST(BBox, ContainsIsExactWhereTheFarEndRoundsInDoubles) {
  std::mt19937_64 rng(20261128);
  std::uniform_int_distribution<int> num(1, 30000), den(2, 9);
  int rounded = 0, outside = 0;
  for (int t = 0; t < 2000; ++t) {
    const double ax = t == 0 ? 10799 : num(rng), ay = t == 0 ? 14347.0 / 7 : num(rng) / 7.0;
    const double dx = t == 0 ? 3169.0 / 3 : num(rng) / double(den(rng)), dy = t == 0 ? 20343.0 / 3 : num(rng) / 3.0;
    for (const double s : {1.0, -1.0}) {  // the front box and its back twin (a = [−1, −ax, −ay])
      const BBox b(Point(s, s * ax, s * ay), T1(1, dx), T1(1, dy));
      const Rational lo(ax), hi = Rational(ax) + Rational(dx), ylo(ay), yhi = Rational(ay) + Rational(dy);
      const double end = ax + dx;  // what a + Δ gives in doubles
      if (Rational(end) != hi) ++rounded;
      for (const double x : {std::nextafter(end, -1e300), end, std::nextafter(end, 1e300)}) {
        const bool in = lo <= Rational(x) && Rational(x) <= hi;
        outside += !in;
        const double y = ay;  // inside in y: the corner
        ASSERT_LE(ylo, Rational(y));
        ASSERT_LE(Rational(y), yhi);
        ASSERT_EQ(contains(b, Point(s, s * x, s * y)), in) << "x = " << x << ", box " << to_string(b);
        ASSERT_EQ(contains(b, Point(2 * s, 2 * s * x, 2 * s * y)), in) << "w = 2";
      }
    }
  }
  EXPECT_GT(rounded, 500);  // the case occurs: the sum rounds in most boxes
  EXPECT_GT(outside, 500);
}

}  // namespace
}  // namespace t2
