// midpoint(p, q) of §4.3.2 against independent checks: the midpoint is a positive combination
// αp + βq (so it lies on the segment pq), it is the Euclidean midpoint of the drawn positions on
// one side, it is equidistant from p and q, and it is on Ω for a front/back pair. The naive
// formulas are shown to fail where the chapter says they do.
#include <gtest/gtest.h>

#include <array>
#include <random>

#include "t2/kernel/distance.hpp"
#include "t2/kernel/midpoint.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

using testing::scale;

using testing::make;
using testing::q;

ExactPoint to_exact_point(const ExactPoint& p) { return p; }
ExactPoint to_exact_point(const Point& p) { return to_exact(p); }

template <class P>
std::array<Rational, 3> vec(const P& p) {
  return {q(p.w()), q(p.x()), q(p.y())};
}
/// True when m = αp + βq with α ≥ 0, β ≥ 0 (p, q independent): m is on the segment pq of T².
/// From m × q = α (p × q) and p × m = β (p × q), and m in the plane of p and q.
template <class P>
::testing::AssertionResult on_segment_oracle(const P& p, const P& qq, const P& m) {
  using V = std::array<Rational, 3>;
  auto vcross = [](const V& x, const V& y) -> V {
    return {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
  };
  auto vdot = [](const V& x, const V& y) -> Rational { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
  const auto a = vec(p), b = vec(qq), c = vec(m);
  const auto n = vcross(a, b);
  if (vdot(n, c) != 0) return ::testing::AssertionFailure() << "not collinear";
  const int alpha = sgn(vdot(vcross(c, b), n)), beta = sgn(vdot(vcross(a, c), n));
  if (alpha < 0 || beta < 0 || (alpha == 0 && beta == 0))
    return ::testing::AssertionFailure() << "alpha " << alpha << " beta " << beta;
  return ::testing::AssertionSuccess();
}

template <class P>
void same_side(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<long> u(-50, 50), w(1, 9), s(0, 1);
  for (int i = 0; i < 3000 * scale(); ++i) {
    const int sd = s(rng) ? 1 : -1;
    const P p = make<P>(sd * w(rng), u(rng), u(rng)), qq = make<P>(sd * w(rng), u(rng), u(rng));
    const P m = midpoint(p, qq);
    ASSERT_EQ(sign_of(m.w()), sd);
    if (!(p == qq)) {
      ASSERT_TRUE(on_segment_oracle(p, qq, m));
      ASSERT_FALSE(on_segment_oracle(p, qq, antipode(m)));  // the oracle can say no
    }
    // The drawn position is the Euclidean midpoint.
    ASSERT_EQ(q(m.x()) / q(m.w()), (q(p.x()) / q(p.w()) + q(qq.x()) / q(qq.w())) / 2);
    ASSERT_EQ(q(m.y()) / q(m.w()), (q(p.y()) / q(p.w()) + q(qq.y()) / q(qq.w())) / 2);
    // Equidistant, as a predicate and as T1 values.
    ASSERT_EQ(compare_distance(p, qq, m), ZERO);
    ASSERT_TRUE(squared_distance(p, m) == squared_distance(m, qq));
    // A function of the points, not of their representatives.
    using T = typename P::Coordinate;
    ASSERT_TRUE(midpoint(P(T(3) * p.w(), T(3) * p.x(), T(3) * p.y()), qq) == m);
    ASSERT_TRUE(midpoint(qq, p) == m);
    // The same point whichever coordinate type computes it.
    ASSERT_TRUE(to_exact(to_double(to_exact_point(m))) == to_exact_point(m));
  }
}

TEST(Midpoint, SameSideIsTheEuclideanMidpointOnThatSide) {
  same_side<Point>(1);
  same_side<ExactPoint>(2);
}

template <class P>
void opposite_sides(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<long> u(-50, 50), w(1, 9);
  for (int i = 0; i < 3000 * scale(); ++i) {
    const P p = make<P>(w(rng), u(rng), u(rng)), qq = make<P>(-w(rng), u(rng), u(rng));
    if (p == antipode(qq)) {
      ASSERT_THROW(midpoint(p, qq), Undefined);
      continue;
    }
    const P m = midpoint(p, qq);
    ASSERT_TRUE(is_at_infinity(m));
    ASSERT_TRUE(on_segment_oracle(p, qq, m));
    // Neither side is nearer: m is as far from p (+inf) as from q (+inf).
    ASSERT_TRUE(squared_distance(p, m) == squared_distance(qq, m));
    ASSERT_TRUE(midpoint(qq, p) == m);
  }
}

TEST(Midpoint, FrontAndBackMeetOnOmega) {
  opposite_sides<Point>(3);
  opposite_sides<ExactPoint>(4);
}

template <class P>
void infinity_and_undefined() {
  const P p = make<P>(2, 1, 5), d = make<P>(0, 3, -4);
  EXPECT_TRUE(midpoint(p, d) == d);  // halfway to infinity is infinity
  EXPECT_TRUE(midpoint(d, p) == d);
  EXPECT_TRUE(midpoint(antipode(p), d) == d);
  EXPECT_TRUE(on_segment_oracle(p, d, midpoint(p, d)));
  EXPECT_TRUE(midpoint(d, d) == d);
  EXPECT_TRUE(midpoint(p, p) == p);
  EXPECT_THROW(midpoint(p, antipode(p)), Undefined);
  EXPECT_THROW(midpoint(d, antipode(d)), Undefined);
  EXPECT_THROW(midpoint(d, make<P>(0, 1, 1)), Undefined);
}

TEST(Midpoint, PointsOfOmegaAndUndefinedCases) {
  infinity_and_undefined<Point>();
  infinity_and_undefined<ExactPoint>();
}

TEST(Midpoint, DoubleOverflowFallsBackToExact) {
  const Point p(1e300, 1e300, 0), qq(1e300, 0, 1e300);  // products overflow
  EXPECT_TRUE(midpoint(p, qq) == Point(2, 1, 1));
  const Point a(-1e300, 1e300, 0), b(1e300, 0, 1e300);
  EXPECT_TRUE(midpoint(a, b) == Point(0, 1, 1));  // B - A with b the front point
}

// The naive formulas themselves are shown failing by chapter 03's program (they are not part
// of the library); here: the library's midpoint has none of their faults.
template <class P>
void no_naive_faults() {
  const P a = make<P>(1, 0, 0), b = make<P>(1, 4, 2), a3 = make<P>(3, 0, 0);
  EXPECT_TRUE(midpoint(a, b) == midpoint(a3, b));  // a function of the points, not the triples
  EXPECT_EQ(side_of(midpoint(antipode(a), antipode(b))), Side::back);  // back stays back
  EXPECT_TRUE(is_at_infinity(midpoint(a, antipode(b))));  // across the sides: on Omega
}

TEST(Midpoint, HasNoneOfTheNaiveFaults) {
  no_naive_faults<Point>();
  no_naive_faults<ExactPoint>();
}

}  // namespace
}  // namespace t2
