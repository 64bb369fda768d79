// Δ(p, q, r) and l ⋄ p against the exact rational oracle: random, near-degenerate (points a few
// ulps off a line), exactly degenerate and extreme-exponent input.
// The counters of filter_stats() count in this program only (see filter.hpp).
#define T2_FILTER_STATS 1
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "testing.hpp"

namespace t2 {
namespace {

using testing::det3_oracle;
using testing::scale;
using testing::sign_oracle;

TEST(Orient, FrontPointsCounterClockwiseIsPositive) {
  const Point a(1, 0, 0), b(1, 1, 0), c(1, 0, 1);
  EXPECT_EQ(orient(a, b, c), POSITIVE);
  EXPECT_EQ(orient(a, c, b), NEGATIVE);
  EXPECT_EQ(orient(a, b, Point(1, 2, 0)), ZERO);
  EXPECT_EQ(static_cast<int>(orient(a, b, c)), 1);
}

TEST(Orient, AntipodeFlipsTheSign) {
  const Point a(1, 0, 0), b(1, 1, 0), c(1, 0, 1);
  EXPECT_EQ(orient(antipode(a), b, c), NEGATIVE);
  EXPECT_EQ(orient(antipode(a), antipode(b), c), POSITIVE);
  EXPECT_EQ(orient(a, antipode(a), c), ZERO);  // p, ¬p and anything are collinear
}

TEST(Orient, IsInvariantUnderPositiveScaling) {
  const Point a(1, 0, 0), b(2, 2, 0), c(0.5, 0, 0.5);
  EXPECT_EQ(orient(a, b, c), POSITIVE);
  EXPECT_EQ(orient(Point(3, 0, 0), b, Point(1e300, 0, 1e300)), POSITIVE);
}

TEST(Orient, RandomInputMatchesOracle) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 2000 * scale(); ++i) {
    Point p(u(rng), u(rng), u(rng)), q(u(rng), u(rng), u(rng)), r(u(rng), u(rng), u(rng));
    ASSERT_EQ(orient(p, q, r), sign_oracle(det3_oracle(p, q, r))) << to_string(p) << to_string(q) << to_string(r);
  }
}

TEST(Orient, NearlyCollinearFrontPointsMatchOracle) {
  // r is the rounded point of the segment pq, then nudged by a few ulps: the naive double
  // determinant gets many of these wrong, the filter must hand them to the exact stage.
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> u(-100, 100), t(0, 1);
  std::uniform_int_distribution<int> ulps(-3, 3);
  filter_stats().reset();
  for (int i = 0; i < 3000 * scale(); ++i) {
    const double px = u(rng), py = u(rng), qx = u(rng), qy = u(rng), s = t(rng);
    double rx = px + s * (qx - px), ry = py + s * (qy - py);
    for (int k = ulps(rng); k != 0; k += (k > 0 ? -1 : 1)) rx = std::nextafter(rx, k > 0 ? 1e9 : -1e9);
    const Point p(1, px, py), q(1, qx, qy), r(1, rx, ry);
    const Sign want = sign_oracle(det3_oracle(p, q, r));
    ASSERT_EQ(orient(p, q, r), want);
    ASSERT_EQ(orient(q, r, p), want);
    ASSERT_EQ(orient(r, q, p), -want);
  }
  // The generator does reach the hard cases: the filter had to defer to GMP for some.
  EXPECT_GT(filter_stats().exact, 0u);
}

TEST(Orient, ExactlyDegenerateInputIsZero) {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> small(-1000, 1000);
  for (int i = 0; i < 2000 * scale(); ++i) {
    // r = a p + b q with small integers: exactly representable, exactly collinear.
    const double pw = small(rng), px = small(rng), py = small(rng);
    const double qw = small(rng), qx = small(rng), qy = small(rng);
    const double a = small(rng), b = small(rng);
    if (pw == 0 && px == 0 && py == 0) continue;
    if (qw == 0 && qx == 0 && qy == 0) continue;
    const double rw = a * pw + b * qw, rx = a * px + b * qx, ry = a * py + b * qy;
    if (rw == 0 && rx == 0 && ry == 0) continue;
    ASSERT_EQ(orient(Point(pw, px, py), Point(qw, qx, qy), Point(rw, rx, ry)), ZERO);
  }
}

TEST(Orient, ExtremeExponentsMatchOracle) {
  // Products overflow or underflow in double: the filter must notice and defer to GMP.
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> m(-1, 1);
  std::uniform_int_distribution<int> e(-1070, 1020);
  auto coord = [&] { return std::ldexp(m(rng), e(rng)); };
  for (int i = 0; i < 1000 * scale(); ++i) {
    Point p(coord(), coord(), coord()), q(coord(), coord(), coord()), r(coord(), coord(), coord());
    ASSERT_EQ(orient(p, q, r), sign_oracle(det3_oracle(p, q, r)));
  }
  const double big = 0x1p1020, tiny = 0x1p-1074;
  const Point a(big, big, 0), b(big, 0, big), c(tiny, tiny, tiny);
  EXPECT_EQ(orient(a, b, c), sign_oracle(det3_oracle(a, b, c)));
}

/// Nearly collinear Cartesian triples at scale 2^e: r is the rounded point s of the way from p to
/// q, nudged by up to `ulps` units in the last place; scaled exactly by a power of two.
std::array<Point, 3> near_line(std::mt19937_64& rng, int e, int ulps) {
  std::uniform_real_distribution<double> u(-1, 1), t(0, 1);
  std::uniform_int_distribution<int> k(-ulps, ulps);
  const double px = u(rng), py = u(rng), qx = u(rng), qy = u(rng), s = t(rng);
  double rx = px + s * (qx - px), ry = py + s * (qy - py);
  for (int i = k(rng); i != 0; i += (i > 0 ? -1 : 1)) rx = std::nextafter(rx, i > 0 ? 2.0 : -2.0);
  auto c = [e](double x, double y) { return Point(1, std::ldexp(x, e), std::ldexp(y, e)); };
  return {c(px, py), c(qx, qy), c(rx, ry)};
}

TEST(Orient, CartesianStagesMatchOracleAtEveryScale) {
  // Every stage of orient_double.hpp: the fast path, unrounded differences, the first-order
  // filter, the full expansion, and the dyadic fallback outside the expansions' range.
  std::mt19937_64 rng(11);
  for (int e : {0, 60, -60, 400, -400, 480, -470, 499, 520, -520, 900, -900, -1020, 1010}) {
    for (int i = 0; i < 300 * scale(); ++i) {
      const auto [p, q, r] = near_line(rng, e, 2);
      const Sign want = sign_oracle(det3_oracle(p, q, r));
      ASSERT_EQ(orient(p, q, r), want) << e << " " << to_string(p) << to_string(q) << to_string(r);
      ASSERT_EQ(orient(r, p, q), want);
      ASSERT_EQ(orient(q, p, r), -want);
      // The same points with homogeneous weights (exact powers of two): the homogeneous formulas.
      const Point p2(4, 4 * p.x(), 4 * p.y()), r2(0.5, 0.5 * r.x(), 0.5 * r.y());
      if (std::isfinite(p2.x()) && std::isfinite(p2.y()) && r2.x() * 2 == r.x() && r2.y() * 2 == r.y()) {
        ASSERT_EQ(orient(p2, q, r2), want) << e;
      }
      // And as integers (to_exact scales by a power of two, keeping Δ's sign).
      if (std::abs(e) <= 400) {
        ASSERT_EQ(orient(to_exact(p), to_exact(q), to_exact(r)), want);
      }
    }
  }
}

TEST(Orient, ExactlyCollinearDyadicPointsAreZeroAtEveryScale) {
  // p, p + v, p + k v with short dyadic coordinates: exactly collinear, and the differences are
  // exact only sometimes (the coordinates have different exponents).
  std::mt19937_64 rng(12);
  std::uniform_int_distribution<int> m(-(1 << 20), 1 << 20), k(-8, 8);
  for (int e : {0, -30, 30, -480, 490, -1000, 1000}) {
    for (int i = 0; i < 300 * scale(); ++i) {
      const double px = std::ldexp(m(rng), e - 20), py = std::ldexp(m(rng), e - 20);
      const double vx = std::ldexp(m(rng), e - 24), vy = std::ldexp(m(rng), e - 24);
      const double kk = k(rng);
      const Point p(1, px, py), q(1, px + vx, py + vy), r(1, px + kk * vx, py + kk * vy);
      ASSERT_EQ(orient(p, q, r), ZERO) << e;
      ASSERT_EQ(orient(p, q, Point(1, r.x(), std::nextafter(r.y(), 1e300))), sign_oracle(det3_oracle(p, q, Point(1, r.x(), std::nextafter(r.y(), 1e300)))));
    }
  }
}

TEST(Orient, CartesianLimitsOfTheDoubleRange) {
  // Differences and products overflow; coordinates are subnormal.
  const double big = 0x1.fffffffffffffp1023, tiny = 0x1p-1074;
  const Point pts[] = {Point(1, big, big), Point(1, -big, big), Point(1, big, -big), Point(1, 0, 0), Point(1, tiny, 0),
                       Point(1, 0, tiny), Point(1, -tiny, tiny), Point(1, 3 * tiny, 5 * tiny), Point(1, 0x1p1000, 1),
                       Point(1, 1, 0x1p-1000), Point(1, -0x1p1023, 0x1p-1074)};
  for (const Point& p : pts)
    for (const Point& q : pts)
      for (const Point& r : pts) ASSERT_EQ(orient(p, q, r), sign_oracle(det3_oracle(p, q, r)));
}

TEST(Orient, IntegerPointsAreExactToo) {
  const ExactPoint a(1, 0, 0), b(1, 1, 0), c(1, 0, 1);
  EXPECT_EQ(orient(a, b, c), POSITIVE);
  const Integer huge("123456789012345678901234567890");
  EXPECT_EQ(orient(ExactPoint(1, huge, huge), ExactPoint(1, huge + 1, huge + 1), ExactPoint(1, huge + 2, huge + 2)), ZERO);
  EXPECT_EQ(orient(ExactPoint(1, huge, huge), ExactPoint(1, huge + 1, huge + 1), ExactPoint(1, huge + 2, huge + 3)), POSITIVE);
}

TEST(Side, AgreesWithOrientThroughJoin) {
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> small(-50, 50);
  for (int i = 0; i < 2000 * scale(); ++i) {
    const ExactPoint p(small(rng), small(rng), small(rng) | 1), q(small(rng), small(rng), small(rng) | 1);
    const int rw = small(rng), rx = small(rng), ry = small(rng);
    if (rw == 0 && rx == 0 && ry == 0) continue;  // [0, 0, 0] is not a point (about 1 in 10⁶ draws: the long run meets it)
    const ExactPoint r(rw, rx, ry);
    if (orient(p, q, ExactPoint(1, 0, 0)) == ZERO && orient(p, q, ExactPoint(0, 1, 0)) == ZERO &&
        orient(p, q, ExactPoint(0, 0, 1)) == ZERO)
      continue;  // p = ±q: join undefined
    ASSERT_EQ(side(join(p, q), r), orient(p, q, r));
    ASSERT_EQ(side(join(p, q), antipode(r)), -orient(p, q, r));
  }
}

TEST(Side, DoubleLineAndPointMatchOracle) {
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 2000 * scale(); ++i) {
    const Line l(u(rng), u(rng), u(rng));
    const Point p(u(rng), u(rng), u(rng));
    const Rational v = to_rational(l.W()) * to_rational(p.w()) + to_rational(l.X()) * to_rational(p.x()) +
                       to_rational(l.Y()) * to_rational(p.y());
    ASSERT_EQ(side(l, p), sign_oracle(v));
  }
}

TEST(Filter, CountsExactFallbacks) {
  static_assert(filter_stats_enabled);
  auto& st = filter_stats();
  st.reset();
  (void)orient(Point(1, 0, 0), Point(1, 1, 0), Point(1, 0, 1));  // far from degenerate: the fast path decides
  EXPECT_EQ(st.calls, 1u);
  EXPECT_EQ(st.exact, 0u);
  // Rounded, hence not exactly collinear: whether the fast path decides may improve with the
  // filter, but the count may only grow by one and the sign must be the oracle's.
  const Point a(1, 0.1, 0.1), b(1, 0.2, 0.2), c(1, 0.3, 0.3);
  EXPECT_EQ(orient(a, b, c), sign_oracle(det3_oracle(a, b, c)));
  EXPECT_EQ(st.calls, 2u);
  EXPECT_LE(st.exact, 1u);
}

TEST(Filter, IntegerGridNeverNeedsGmpButStaysExact) {
  // Small integer coordinates: the double evaluation does not round, so even exact zeros are
  // certified without GMP — and the signs still agree with the oracle.
  auto& st = filter_stats();
  st.reset();
  std::mt19937_64 rng(9);
  std::uniform_int_distribution<int> c(-20, 20);
  int zeros = 0;
  for (int i = 0; i < 3000 * scale(); ++i) {
    const Point p(1, c(rng), c(rng)), q(1, c(rng), c(rng)), r(1, c(rng), c(rng));
    const Sign s = orient(p, q, r);
    zeros += s == ZERO;
    ASSERT_EQ(s, sign_oracle(det3_oracle(p, q, r)));
  }
  EXPECT_GT(zeros, 0);
  // Only the exactly collinear triples, whose zero no error bound can certify, may need an
  // exact stage (for integers it is the cheapest one: differences and products are exact).
  EXPECT_LE(st.exact, static_cast<std::uint64_t>(zeros));
  // Beyond 2^52 the shortcut must not apply: these are collinear, and need GMP to prove it.
  const double b = 0x1p60;
  st.reset();
  EXPECT_EQ(orient(Point(1, b, b), Point(1, b + 1024, b + 1024), Point(1, b + 4096, b + 4096)), ZERO);
  EXPECT_EQ(orient(Point(1, b, b), Point(1, b + 1024, b + 1024), Point(1, b + 4096, b + 2048)), NEGATIVE);
}

}  // namespace
}  // namespace t2
