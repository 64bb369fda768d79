// mix(α, p, β, q) = αp + βq against an oracle that does the same sum in exact rationals from
// the inputs, and against what the sum means: collinear with p and q, on the segment pq
// (Cartesian convex combination for front points), p and q at the ends, ¬p + p undefined.
#include <gtest/gtest.h>

#include <array>
#include <limits>
#include <random>

#include "t2/kernel/orient.hpp"
#include "t2/kernel/point.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

using testing::q;
using testing::scale;

using V = std::array<Rational, 3>;

template <class P>
V vec(const P& p) {
  return {q(p.w()), q(p.x()), q(p.y())};
}

// The oracle: αp + βq, coordinate by coordinate, in rationals.
template <class T, class P>
V sum_oracle(const T& a, const P& p, const T& b, const P& r) {
  const V u = vec(p), v = vec(r);
  return {q(a) * u[0] + q(b) * v[0], q(a) * u[1] + q(b) * v[1], q(a) * u[2] + q(b) * v[2]};
}

Integer big(std::mt19937_64& g, int bits) {
  Integer v = 0;
  for (int i = 0; i < bits; i += 32) v = v * Integer(1u << 16) * Integer(1u << 16) + Integer(static_cast<unsigned>(g()));
  return g() % 2 ? v : Integer(-v);
}

TEST(Mix, ExactSumOfBigIntegerPoints) {
  std::mt19937_64 g(11);
  for (int i = 0; i < 2000 * scale(); ++i) {
    const ExactPoint p(big(g, 96), big(g, 96), big(g, 96)), r(big(g, 64), big(g, 128), big(g, 32));
    const Integer a = abs(big(g, 64)), b = abs(big(g, 40));
    if (a == 0 && b == 0) continue;
    try {
      const ExactPoint m = mix(a, p, b, r);
      EXPECT_EQ(vec(m), sum_oracle(a, p, b, r));
      EXPECT_EQ(orient(p, r, m), ZERO);  // on the line pq
    } catch (const Undefined&) {
      EXPECT_EQ(sum_oracle(a, p, b, r), (V{0, 0, 0}));
    }
  }
}

TEST(Mix, FrontPointsGiveTheCartesianConvexCombination) {
  // For w_p, w_q > 0 and α, β > 0, αp + βq is the Cartesian point t·P + (1 − t)·Q with
  // t = α w_p / (α w_p + β w_q) in (0, 1): strictly between P and Q.
  std::mt19937_64 g(12);
  std::uniform_int_distribution<long> c(-1000000, 1000000), w(1, 1000000), k(1, 1000);
  for (int i = 0; i < 2000 * scale(); ++i) {
    const ExactPoint p(Integer(w(g)), Integer(c(g)), Integer(c(g))), r(Integer(w(g)), Integer(c(g)), Integer(c(g)));
    const Integer a(k(g)), b(k(g));
    const ExactPoint m = mix(a, p, b, r);
    const Rational wp = q(p.w()), wq = q(r.w());
    const Rational t = q(a) * wp / (q(a) * wp + q(b) * wq);
    ASSERT_GT(t, 0);
    ASSERT_LT(t, 1);
    EXPECT_EQ(q(m.x()) / q(m.w()), t * q(p.x()) / wp + (1 - t) * q(r.x()) / wq);
    EXPECT_EQ(q(m.y()) / q(m.w()), t * q(p.y()) / wp + (1 - t) * q(r.y()) / wq);
  }
}

TEST(Mix, DoubleAgreesWithIntegerWhenTheSumsAreRepresentable) {
  // Integers below 2^20 times integers below 2^20, summed: below 2^41, exact in a double.
  std::mt19937_64 g(13);
  std::uniform_int_distribution<long> c(-(1L << 20), 1L << 20), k(0, 1L << 20);
  for (int i = 0; i < 2000 * scale(); ++i) {
    const Point p(double(c(g)), double(c(g)), double(c(g))), r(double(c(g)), double(c(g)), double(c(g)));
    const double a = double(k(g)), b = double(k(g));
    if (a == 0 && b == 0) continue;
    try {
      const Point m = mix(a, p, b, r);
      EXPECT_EQ(vec(m), sum_oracle(a, p, b, r));
    } catch (const Undefined&) {
      EXPECT_EQ(sum_oracle(a, p, b, r), (V{0, 0, 0}));
    }
  }
}

TEST(Mix, EndsScalingAndTheUndefinedSum) {
  const ExactPoint p(Integer(2), Integer(3), Integer(-5)), r(Integer(-1), Integer(4), Integer(7));
  EXPECT_EQ(vec(mix(Integer(1), p, Integer(0), r)), vec(p));
  EXPECT_EQ(vec(mix(Integer(0), p, Integer(1), r)), vec(r));
  EXPECT_EQ(mix(Integer(6), p, Integer(10), r), mix(Integer(3), p, Integer(5), r));  // the same point of T²
  EXPECT_THROW(mix(Integer(1), p, Integer(1), antipode(p)), Undefined);
  EXPECT_THROW(mix(Integer(2), p, Integer(1), ExactPoint(Integer(-4), Integer(-6), Integer(10))), Undefined);
  const double huge = std::numeric_limits<double>::max();
  EXPECT_THROW(mix(huge, Point(huge, 1, 1), 1.0, Point(1, 1, 1)), BadInput);  // overflow
}

}  // namespace
}  // namespace t2
