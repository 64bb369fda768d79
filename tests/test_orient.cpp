// Δ(p, q, r) and l ⋄ p against the exact rational oracle: random, near-degenerate (points a few
// ulps off a line), exactly degenerate and extreme-exponent input.
#include <gtest/gtest.h>

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
  auto& st = filter_stats();
  st.reset();
  const Point a(1, 0.1, 0.1), b(1, 0.2, 0.2), c(1, 0.3, 0.3);  // rounded: not exactly collinear
  (void)orient(a, b, c);
  (void)orient(Point(1, 0, 0), Point(1, 1, 0), Point(1, 0, 1));
  EXPECT_EQ(st.calls, 2u);
  EXPECT_EQ(st.exact, 1u);
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
  EXPECT_EQ(st.exact, 0u);
  // Beyond 2^52 the shortcut must not apply: these are collinear, and need GMP to prove it.
  const double b = 0x1p60;
  st.reset();
  EXPECT_EQ(orient(Point(1, b, b), Point(1, b + 1024, b + 1024), Point(1, b + 4096, b + 4096)), ZERO);
  EXPECT_EQ(orient(Point(1, b, b), Point(1, b + 1024, b + 1024), Point(1, b + 4096, b + 2048)), NEGATIVE);
}

}  // namespace
}  // namespace t2
