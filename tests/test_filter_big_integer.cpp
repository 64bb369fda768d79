// The bound on big integers (filter.hpp, "Big integers"): exact constructions give Integer
// coordinates of hundreds of bits, whose signs sign_of_poly and orient first try on the doubles
// just below them. The oracle is GMP on a formula of its own (the determinant expanded along
// its last column, the dot product summed backwards), never the library's polynomial.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <random>

#include "t2/kernel/line.hpp"
#include "t2/kernel/orient.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

using testing::scale;

constexpr double u = 0x1p-53;

// A random integer of exactly `bits` bits (0 for bits = 0), of either sign.
Integer big(std::mt19937_64& rng, int bits) {
  Integer x = 0;
  for (int b = 0; b < bits; b += 64) {
    x <<= 64;
    x += static_cast<unsigned long>(rng());
  }
  if (bits == 0) return x;
  mpz_fdiv_r_2exp(x.get_mpz_t(), x.get_mpz_t(), static_cast<mp_bitcnt_t>(bits - 1));
  mpz_setbit(x.get_mpz_t(), static_cast<mp_bitcnt_t>(bits - 1));
  return rng() % 2 ? x : Integer(-x);
}

Sign sign_oracle(const Integer& v) { return v > 0 ? POSITIVE : v < 0 ? NEGATIVE : ZERO; }

// det |p; q; r| along its last column.
Sign det_oracle(const ExactPoint& p, const ExactPoint& q, const ExactPoint& r) {
  const Integer d = p.y() * (q.w() * r.x() - q.x() * r.w()) - q.y() * (p.w() * r.x() - p.x() * r.w()) +
                    r.y() * (p.w() * q.x() - p.x() * q.w());
  return sign_oracle(d);
}

Sign side_oracle(const ExactLine& l, const ExactPoint& p) {
  return sign_oracle(Integer(l.Y() * p.y() + l.X() * p.x() + l.W() * p.w()));
}

// Coordinates of 0 to max_bits bits each, not all zero.
ExactPoint random_point(std::mt19937_64& rng, int max_bits) {
  std::uniform_int_distribution<int> bits(0, max_bits);
  for (;;) {
    Integer w = big(rng, bits(rng)), x = big(rng, bits(rng)), y = big(rng, bits(rng));
    if (w != 0 || x != 0 || y != 0) return ExactPoint(w, x, y);
  }
}

// α·p + β·q + ε·e: a point on the line p ∨ q when ε = 0, within a hair of it otherwise.
ExactPoint combination(const ExactPoint& p, const ExactPoint& q, const Integer& a, const Integer& b,
                       const Integer& eps, const ExactPoint& e) {
  return ExactPoint(Integer(a * p.w() + b * q.w() + eps * e.w()), Integer(a * p.x() + b * q.x() + eps * e.x()),
                    Integer(a * p.y() + b * q.y() + eps * e.y()));
}

TEST(BigIntegerFilter, ConstantsAddThreeRoundingsPerFactor) {
  // side: k = 3, D = 2, so k + 3D = 9; det3 as orient.hpp writes it: k = 5, D = 3, so 14.
  constexpr auto side_poly = [](const auto& m, const auto& p) { return m.W * p.w + m.X * p.x + m.Y * p.y; };
  static_assert(detail::derive_bound<ExactLine, ExactPoint>(side_poly).c3 == 9 * u * (1 + 0x1p-40));
  constexpr auto det = [](const auto& a, const auto& b, const auto& c) { return det3(a, b, c); };
  static_assert(detail::derive_bound<ExactPoint, ExactPoint, ExactPoint>(det).c3 == 14 * u * (1 + 0x1p-40));
}

TEST(BigIntegerFilter, RandomPointsAndLinesOfUpTo300Bits) {
  std::mt19937_64 rng(11);
  constexpr auto det = [](const auto& a, const auto& b, const auto& c) { return det3(a, b, c); };
  const auto& b3 = detail::bound_of<ExactPoint, ExactPoint, ExactPoint>(det);
  int decided = 0, n = 0;
  for (int i = 0; i < 2000 * scale(); ++i, ++n) {
    // up to 300 bits: the products of three stay below 2^900, in the range of doubles
    const ExactPoint p = random_point(rng, 300), q = random_point(rng, 300), r = random_point(rng, 300);
    const Sign want = det_oracle(p, q, r);
    ASSERT_EQ(orient(p, q, r), want) << i;
    const int s = detail::big_integer_filter(b3, det, p, q, r);
    if (s != 2) {
      ASSERT_EQ(s, static_cast<int>(want)) << i;
    }
    decided += s != 2;
    const ExactLine l(p.w(), p.x(), p.y());
    ASSERT_EQ(side(l, q), side_oracle(l, q)) << i;
  }
  // Random input is far from degenerate: the doubles decide nearly every case.
  EXPECT_GT(decided, n * 99 / 100);
}

TEST(BigIntegerFilter, NearlyAndExactlyCollinearTriples) {
  std::mt19937_64 rng(12);
  constexpr auto det = [](const auto& a, const auto& b, const auto& c) { return det3(a, b, c); };
  const auto& b3 = detail::bound_of<ExactPoint, ExactPoint, ExactPoint>(det);
  int zeros = 0, undecided = 0;
  for (int i = 0; i < 1000 * scale(); ++i) {
    const ExactPoint p = random_point(rng, 200), q = random_point(rng, 200), e = random_point(rng, 200);
    // ε from 0 to 2^40 against coordinates of up to 2^300: far below what doubles resolve.
    const Integer eps = big(rng, static_cast<int>(rng() % 41));
    const ExactPoint r = combination(p, q, big(rng, 100), big(rng, 100), eps, e);
    const Sign want = det_oracle(p, q, r);
    zeros += want == ZERO;
    for (const auto& [a, b, c] : {std::array{p, q, r}, std::array{r, p, q}, std::array{q, r, p}}) {
      ASSERT_EQ(orient(a, b, c), want) << i;
      const int s = detail::big_integer_filter(b3, det, a, b, c);
      if (s != 2) {
      ASSERT_EQ(s, static_cast<int>(want)) << i;
    }
      undecided += s == 2;
    }
    // The line through p and q against r: the same hair.
    const ExactLine l = join(p, q);
    ASSERT_EQ(side(l, r), side_oracle(l, r)) << i;
  }
  EXPECT_GT(zeros, 0);
  EXPECT_GT(undecided, 0);  // the near misses reach GMP
}

TEST(BigIntegerFilter, ZerosBeyondTheDoubleRangeAndMixedSizes) {
  std::mt19937_64 rng(13);
  // Coordinates of 1100 to 1500 bits do not fit a double (mpz_get_d gives ∞): GMP decides.
  for (int i = 0; i < 200 * scale(); ++i) {
    const ExactPoint p = random_point(rng, 1500), q = random_point(rng, 1500);
    const ExactPoint r = combination(p, q, big(rng, 3), big(rng, 3), Integer(i % 3) - 1, random_point(rng, 5));
    ASSERT_EQ(orient(p, q, r), det_oracle(p, q, r)) << i;
  }
  // A zero factor in every monomial is a certified zero.
  constexpr auto product = [](const auto& x, const auto& y) { return x * y - y * x; };
  const Integer zero = 0, a = big(rng, 300);
  EXPECT_EQ(detail::big_integer_filter(detail::bound_of<Integer, Integer>(product), product, zero, a), 0);
  EXPECT_EQ(detail::big_integer_filter(detail::bound_of<Integer, Integer>(product), product, a, a), 2);
  // One huge coordinate beside small ones.
  const Integer h = Integer(1) << 2000;
  EXPECT_EQ(orient(ExactPoint(1, 0, 0), ExactPoint(1, h, 0), ExactPoint(1, 0, 1)), POSITIVE);
  EXPECT_EQ(orient(ExactPoint(1, 0, 0), ExactPoint(1, h, 0), ExactPoint(1, h + 1, 0)), ZERO);
}

}  // namespace
}  // namespace t2
