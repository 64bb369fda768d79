// orientation(P) in linear time for homogeneous input: the double filter, for any weights
// (detail::orientation_filter), must decide ordinary polygons, and the exact fallback
// adds its fractions in pairs (detail::rational_sum). Before both, gen's convex polygons (exact
// points of the unit circle, w ≠ 1) fell to a left-to-right rational sum whose denominator grows
// with every term: Θ(n²), and polygon_kernel, which asks orientation(P) first, took 256 s at
// n = 10⁶. Here the filter's decision is checked against the exact sum, and the exact path
// against an independent oracle (cross products of the Cartesian rationals).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "t2/gen/generate.hpp"
#include "t2/kernel/polygon.hpp"

namespace t2 {
namespace {

// Twice the signed area from the Cartesian rationals, one term at a time (the oracle).
Rational area2(const Polygon& P) {
  Rational s = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const Point& p = P[i];
    const Point& q = P[(i + 1) % P.size()];
    const Rational px = to_rational(p.x()) / to_rational(p.w()), py = to_rational(p.y()) / to_rational(p.w());
    const Rational qx = to_rational(q.x()) / to_rational(q.w()), qy = to_rational(q.y()) / to_rational(q.w());
    s += px * qy - py * qx;
  }
  return s;
}

TEST(PolygonOrientation, TheFilterDecidesConvexCirclePolygons) {
  gen::Options o;
  o.n = 2000;
  o.seed = 5;
  Polygon P = gen::polygon(gen::Kind::convex_polygon, o);
  ASSERT_TRUE(std::any_of(P.begin(), P.end(), [](const Point& p) { return p.w() != 1; }));
  EXPECT_EQ(detail::orientation_filter(P), POSITIVE);
  EXPECT_EQ(sign_of(area2(P)), POSITIVE);
  std::reverse(P.begin(), P.end());
  EXPECT_EQ(detail::orientation_filter(P), NEGATIVE);
  EXPECT_EQ(orientation(P), NEGATIVE);
}

TEST(PolygonOrientation, FilterAndExactSumAgreeWithTheOracleOnWeightedPolygons) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> c(-40, 40), w(1, 9), nn(3, 9);
  int decided = 0;
  for (int i = 0; i < 400; ++i) {
    Polygon P;
    const int n = nn(rng);
    for (int k = 0; k < n; ++k) {
      const double wk = w(rng);
      P.emplace_back(wk, wk * c(rng), wk * c(rng));
    }
    const Sign want = sign_of(area2(P));
    const Sign f = detail::orientation_filter(P);
    if (f != ZERO) {
      ++decided;
      ASSERT_EQ(f, want);
    }
    ASSERT_EQ(orientation(P), want);
    for (Point& p : P) p = antipode(p);  // the back side: the sign flips
    ASSERT_EQ(orientation(P), -want);
  }
  EXPECT_GT(decided, 300);
}

TEST(PolygonOrientation, NearlyFlatWeightedPolygonsGoToTheExactSum) {
  // (0, 0), (2⁴⁹, 1), (2⁵⁰ + δ, 2) with weight 3 (exact doubles): twice the area is -δ, under
  // the filter's bound (about 6 for terms near 2⁵¹), so the pairwise exact sum decides.
  for (double d : {-1.0, 0.0, 1.0}) {
    const Polygon P{Point(3, 0, 0), Point(3, 3 * 0x1p49, 3), Point(3, 3 * (0x1p50 + d), 6)};
    EXPECT_EQ(detail::orientation_filter(P), ZERO);
    EXPECT_EQ(area2(P), Rational(-d));
    EXPECT_EQ(orientation(P), sign_of(Rational(-d)));
  }
}

TEST(PolygonOrientation, PairwiseSumEqualsTheLeftToRightSum) {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> num(-1000, 1000), den(1, 997);
  for (std::size_t n : {0, 1, 2, 3, 5, 8, 13, 100}) {
    std::vector<Rational> t;
    Rational want = 0;
    for (std::size_t k = 0; k < n; ++k) {
      t.emplace_back(num(rng), den(rng));
      t.back().canonicalize();
      want += t.back();
    }
    EXPECT_EQ(detail::rational_sum(t), want) << n;
  }
}

}  // namespace
}  // namespace t2
