// Exercise 04b, hidden tests. Oracle: a·d − b·c in exact rationals (GMP, on the checker's side).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <t2/kernel/number.hpp>

#include "det2.hpp"

namespace {

t2::Sign oracle(double a, double b, double c, double d) {
  const t2::Rational v = t2::to_rational(a) * t2::to_rational(d) - t2::to_rational(b) * t2::to_rational(c);
  return static_cast<t2::Sign>(sgn(v));
}

// A random double of the given binary exponent, with a full random 53-bit significand and a
// random sign.
double random_double(std::mt19937_64& rng, int exponent) {
  std::uniform_real_distribution<double> m(0.5, 1.0);
  return (rng() & 1 ? -1 : 1) * std::ldexp(m(rng), exponent);
}

// b·c as close to a·d as doubles allow, then moved by a few units in the last place of c.
void check_near(std::mt19937_64& rng, int ea, int ed, int eb) {
  std::uniform_int_distribution<int> ulps(-2, 2);
  const double a = random_double(rng, ea), d = random_double(rng, ed), b = random_double(rng, eb);
  double c = a * d / b;
  for (int k = ulps(rng); k != 0; k += k > 0 ? -1 : 1) c = std::nextafter(c, k > 0 ? INFINITY : -INFINITY);
  ASSERT_EQ(ex04b::det2_sign(a, b, c, d), oracle(a, b, c, d)) << a << " " << b << " " << c << " " << d;
}

TEST(Hidden, ExactlyEqualProductsGiveZero) {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> e(-150, 150), k(-40, 40);
  std::uniform_int_distribution<long> m50(1L << 48, (1L << 50) - 1);
  for (int i = 0; i < 1000; ++i) {
    // b = a·2^k, c = d·2^-k: the same real product, whatever its rounding.
    const double a = random_double(rng, e(rng)), d = random_double(rng, e(rng));
    const int s = k(rng);
    ASSERT_EQ(ex04b::det2_sign(a, std::ldexp(a, s), std::ldexp(d, -s), d), t2::ZERO) << a << " " << d << " " << s;
    // a = 3u, d = 5v, b = 5u, c = 3v (u, v of 50 bits: the multiples are exact): 15uv twice.
    const double u = std::ldexp(static_cast<double>(m50(rng)), e(rng)), v = std::ldexp(static_cast<double>(m50(rng)), e(rng));
    ASSERT_EQ(ex04b::det2_sign(3 * u, 5 * u, 3 * v, 5 * v), t2::ZERO) << u << " " << v;
  }
  EXPECT_EQ(ex04b::det2_sign(0, 0, 0, 0), t2::ZERO);
  EXPECT_EQ(ex04b::det2_sign(0, 0x1p-400, 0x1p400, 1), t2::NEGATIVE);
}

TEST(Hidden, NearlyEqualProductsAgreeWithOracle) {
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> e(-100, 100);
  for (int i = 0; i < 3000; ++i) check_near(rng, e(rng), e(rng), e(rng));
}

TEST(Hidden, ExtremeExponents) {
  // Products near 2^±780 and factors of very different sizes: still exact, no overflow.
  std::mt19937_64 rng(7);
  for (int i = 0; i < 500; ++i) {
    check_near(rng, 395, 385, 390);
    check_near(rng, -395, -385, -390);
    check_near(rng, 395, -390, -2);
  }
}

}  // namespace
