// Points, lines, join, meet, duality and equality up to a positive factor.
#include <gtest/gtest.h>

#include <random>

#include "testing.hpp"

namespace t2 {
namespace {

TEST(Point, ZeroTripleIsNotAPoint) {
  EXPECT_THROW(Point(0, 0, 0), Undefined);
  EXPECT_THROW(ExactPoint(0, 0, 0), Undefined);
  EXPECT_THROW(Point(1, std::nan(""), 0), BadInput);
  EXPECT_THROW(Point(1, 0, HUGE_VAL), BadInput);
}

TEST(Point, EqualityIsUpToAPositiveFactor) {
  EXPECT_EQ(Point(1, 2, 3), Point(2, 4, 6));
  EXPECT_NE(Point(1, 2, 3), Point(-1, -2, -3));  // p != ¬p
  EXPECT_EQ(antipode(Point(1, 2, 3)), Point(-2, -4, -6));
  EXPECT_NE(Point(1, 2, 3), Point(1, 2, 3.0000000000000004));
  EXPECT_EQ(Point(0, 1, 0), Point(0, 5, 0));
  EXPECT_NE(Point(0, 1, 0), Point(0, -1, 0));
  EXPECT_EQ(ExactPoint(3, 6, 9), ExactPoint(1, 2, 3));
}

TEST(Point, SidesAndInfinity) {
  EXPECT_EQ(side_of(Point(1, 5, 5)), Side::front);
  EXPECT_EQ(side_of(Point(-1, 5, 5)), Side::back);
  EXPECT_EQ(side_of(Point::at_infinity(1, 1)), Side::infinity);
  EXPECT_TRUE(is_at_infinity(Point(0, 1, 2)));
  EXPECT_TRUE(is_proper(Point(-3, 1, 2)));
  auto c = to_cartesian(Point(-2, 4, 6));
  ASSERT_TRUE(c.has_value());
  EXPECT_EQ(c->first, -2.0);
  EXPECT_EQ(c->second, -3.0);
  EXPECT_FALSE(to_cartesian(Point(0, 1, 0)).has_value());
  EXPECT_EQ(to_string(normalized(Point(-2, 4, 6))), "[-1, 2, 3]");
  EXPECT_EQ(to_string(normalized(Point(0, 4, -8))), "[0, 0.5, -1]");
}

TEST(Point, ToExactIsExact) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> m(-1, 1);
  std::uniform_int_distribution<int> e(-1074, 1023);
  for (int i = 0; i < 500; ++i) {
    const Point p(std::ldexp(m(rng), e(rng)), std::ldexp(m(rng), e(rng)), std::ldexp(m(rng), e(rng)));
    const ExactPoint q = to_exact(p);
    // Same point: the ratios of coordinates agree exactly.
    const Rational pw = to_rational(p.w()), px = to_rational(p.x()), py = to_rational(p.y());
    ASSERT_EQ(pw * Rational(q.x()), px * Rational(q.w()));
    ASSERT_EQ(px * Rational(q.y()), py * Rational(q.x()));
    ASSERT_EQ(sgn(pw), sgn(q.w()));
    ASSERT_EQ(sgn(px), sgn(q.x()));
  }
}

TEST(Line, JoinPassesThroughBothPointsAndIsOriented) {
  const ExactPoint p(1, 0, 0), q(1, 1, 0);
  const ExactLine l = join(p, q);
  EXPECT_EQ(side(l, p), ZERO);
  EXPECT_EQ(side(l, q), ZERO);
  EXPECT_EQ(side(l, ExactPoint(1, 0, 1)), POSITIVE);  // left of p→q
  EXPECT_EQ(join(q, p), opposite(l));
}

TEST(Line, JoinOfEqualOrAntipodalPointsIsUndefined) {
  EXPECT_THROW(join(Point(1, 2, 3), Point(2, 4, 6)), Undefined);
  EXPECT_THROW(join(Point(1, 2, 3), Point(-1, -2, -3)), Undefined);
  try {
    join(ExactPoint(1, 2, 3), ExactPoint(-1, -2, -3));
    FAIL();
  } catch (const Undefined& e) {
    EXPECT_NE(std::string(e.what()).find("antipode"), std::string::npos);
  }
}

TEST(Line, MeetOfParallelLinesIsOnOmega) {
  const ExactLine a = join(ExactPoint(1, 0, 0), ExactPoint(1, 1, 0));
  const ExactLine b = join(ExactPoint(1, 0, 1), ExactPoint(1, 1, 1));
  const ExactPoint m = meet(a, b);
  EXPECT_TRUE(is_at_infinity(m));
  EXPECT_EQ(side(a, m), ZERO);
  EXPECT_EQ(side(b, m), ZERO);
  EXPECT_THROW(meet(a, a), Undefined);
  EXPECT_THROW(meet(a, opposite(a)), Undefined);
  EXPECT_EQ(side(omega<Integer>(), m), ZERO);
  EXPECT_EQ(side(omega(), Point(1, 5, 5)), POSITIVE);
  EXPECT_EQ(side(omega(), Point(-1, 5, 5)), NEGATIVE);
}

TEST(Line, DoubleJoinOfNearlyEqualPointsStillPassesThroughThem) {
  // The rounded cross product would be zero; the exact fallback keeps a valid line.
  const Point p(1, 1, 1), q(1, 1, std::nextafter(1.0, 2.0));
  const Line l = join(p, q);
  EXPECT_EQ(side(l, p), ZERO);
  EXPECT_EQ(side(l, q), ZERO);
  const Point big(1e300, 1e300, 0), big2(1e300, 0, 1e300);
  const Line m = join(big, big2);  // overflows in double
  EXPECT_EQ(side(m, big), ZERO);
}

TEST(Line, DualityPreservesIncidenceAndSide) {
  std::mt19937_64 rng(8);
  std::uniform_int_distribution<int> small(-20, 20);
  for (int i = 0; i < 500; ++i) {
    const ExactPoint p(small(rng), small(rng), small(rng) | 1);
    const ExactLine l(small(rng) | 1, small(rng), small(rng));
    ASSERT_EQ(side(l, p), side(dual(p), dual(l)));
  }
}

}  // namespace
}  // namespace t2

namespace t2 {
namespace {
TEST(Point, ToExactKeepsSmallIntegersSmall) {
  EXPECT_EQ(to_string(to_exact(Point(1, 5, 7))), "[1, 5, 7]");
  EXPECT_EQ(to_string(to_exact(Point(0.5, -0.25, 0))), "[2, -1, 0]");
  EXPECT_EQ(to_string(to_exact(Point(0, 0x1p100, 0x1p99))), "[0, 2, 1]");
}
}  // namespace
}  // namespace t2
