// sign_of_root_sum: the exact sign of A + B√C (sign_sqrt.hpp), and its floating-point filter.
// Two oracles, neither using the library's rule: answers known by construction (A = −B·k with
// C = k² is zero; C = k² ± 1 moves √C to either side of k), and A + B√C evaluated with GMP
// floats of 16,384 bits, whose sign is certain because a nonzero A + B√C of these inputs cannot
// be that small (see `oracle`).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <gmpxx.h>
#include <random>
#include <stdexcept>

#include "t2/kernel/sign_sqrt.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

using testing::scale;

// The test's polynomials of four numbers (a, b, c, t): A = a·t, B = b, C = c·t. A² and B²C have
// total degree 4. With t = 1 this is a + b√c; scaling all four by λ scales A + B√C by λ², so
// (λa, λb, λc, λ) has the sign of a + b√c for every λ > 0: the same question at every exponent.
constexpr auto kA = [](const auto& a, const auto&, const auto&, const auto& t) { return a * t; };
constexpr auto kB = [](const auto&, const auto& b, const auto&, const auto&) { return b; };
constexpr auto kC = [](const auto&, const auto&, const auto& c, const auto& t) { return c * t; };

template <class T>
Sign root_sum(const T& a, const T& b, const T& c, const T& t) {
  return sign_of_root_sum(kA, kB, kC, a, b, c, t);
}
/// The filter alone: a certified sign, or 2 when it leaves the question to the exact stage.
int filter_only(double a, double b, double c, double t) {
  int known[3];
  return detail::root_sum_filter<decltype(kA), decltype(kB), decltype(kC)>(known, a, b, c, t);
}

/// The sign of A + B√C from 16,384-bit GMP floats (each operation errs by at most 2⁻¹⁶³⁸³ of its
/// result). For inputs made from doubles as above, A, C are multiples of 2⁻²¹⁴⁸ and B of 2⁻¹⁰⁷⁴,
/// all below 2²⁰⁴⁸ in magnitude, so A² − B²C is a multiple of 2⁻⁴²⁹⁶; if A + B√C ≠ 0 then
/// |A + B√C| = |A² − B²C|/|A − B√C| ≥ 2⁻⁴²⁹⁶/2²⁰⁴⁹, at least 2⁻⁸⁴⁰⁰ of m = |A| + |B|√C ≤ 2²⁰⁴⁹
/// (integer inputs of at most 400 bits: at least 2⁻²⁴⁰⁰ of m). The float errs by far less than
/// 2⁻¹²⁰⁰⁰·m, so a value below that is an exact zero, and any other value has the exact sign.
Sign oracle(const mpq_class& A, const mpq_class& B, const mpq_class& C) {
  constexpr int kBits = 16384;
  const mpf_class a(A, kBits), b(B, kBits), c(C, kBits);
  const mpf_class r = sqrt(c);
  const mpf_class v = a + b * r, m = abs(a) + abs(b) * r;
  mpf_class tiny(m, kBits);
  mpf_div_2exp(tiny.get_mpf_t(), tiny.get_mpf_t(), 12000);
  if (abs(v) <= tiny) return ZERO;
  return static_cast<Sign>(sgn(v));
}
Sign oracle(double a, double b, double c, double t) {
  return oracle(mpq_class(a) * mpq_class(t), mpq_class(b), mpq_class(c) * mpq_class(t));
}

TEST(SignOfRootSum, EverySignCombination) {
  // a, b, c small integers: a + b√c by hand, c a square or not.
  struct Case {
    double a, b, c;
    Sign expected;
  };
  const Case cases[] = {
      {0, 0, 0, ZERO},       {0, 0, 5, ZERO},      {3, 0, 5, POSITIVE},  {-3, 0, 5, NEGATIVE},
      {0, 2, 5, POSITIVE},   {0, -2, 5, NEGATIVE}, {0, 2, 0, ZERO},      {3, 2, 0, POSITIVE},
      {-3, 7, 0, NEGATIVE},  {3, 2, 5, POSITIVE},  {-3, -2, 5, NEGATIVE}, {-3, 1, 9, ZERO},
      {3, -1, 9, ZERO},      {-3, 1, 4, NEGATIVE}, {-3, 1, 10, POSITIVE}, {3, -1, 8, POSITIVE},
      {3, -1, 10, NEGATIVE}, {-6, 2, 9, ZERO},     {-7, 2, 12, NEGATIVE}, {-7, 2, 13, POSITIVE},
  };
  for (const Case& k : cases) {
    EXPECT_EQ(root_sum(k.a, k.b, k.c, 1.0), k.expected) << k.a << " + " << k.b << "√" << k.c;
    EXPECT_EQ(oracle(k.a, k.b, k.c, 1.0), k.expected) << "oracle " << k.a << " + " << k.b << "√" << k.c;
    const Integer ia(static_cast<long>(k.a)), ib(static_cast<long>(k.b)), ic(static_cast<long>(k.c));
    EXPECT_EQ(root_sum(ia, ib, ic, Integer(1)), k.expected) << "Integer " << k.a << " + " << k.b << "√" << k.c;
    for (const int e : {-1000, -537, -300, 0, 300, 511, 600}) {  // scaled: the same sign
      EXPECT_EQ(root_sum(std::ldexp(k.a, e), std::ldexp(k.b, e), std::ldexp(k.c, e), std::ldexp(1.0, e)), k.expected)
          << k.a << " + " << k.b << "√" << k.c << " scaled by 2^" << e;
    }
  }
}

TEST(SignOfRootSum, NegativeCThrows) {
  EXPECT_THROW(root_sum(1.0, 1.0, -1.0, 1.0), Undefined);  // even where sign(A) = sign(B)
  EXPECT_THROW(root_sum(0.0, 0.0, -0x1p-1000, 1.0), Undefined);
  EXPECT_THROW(root_sum(-1.0, 1.0, -1.0, 1.0), Undefined);
  EXPECT_THROW(root_sum(Integer(1), Integer(-1), Integer(-1), Integer(1)), Undefined);
  // C = c·t < 0 with c > 0: the sign of C, not of c.
  EXPECT_THROW(root_sum(-1.0, -1.0, 1.0, -1.0), Undefined);
}

/// A random double with `bits` significant bits and exponent in [lo, hi].
double random_double(std::mt19937_64& rng, int bits, int lo, int hi) {
  const auto m = static_cast<double>(rng() >> (65 - bits)) + std::ldexp(1.0, bits - 1);  // bits bits
  return std::ldexp(m, std::uniform_int_distribution<int>(lo, hi)(rng) - bits);
}

TEST(SignOfRootSum, ConstructedZerosAndNearMissesAtEveryExponent) {
  // a = −b·k, c = k²: exactly zero. c = k² ± ulp: √c moves just off k, and the sign is ±sign(b).
  // k and b have 26 bits, so k², b·k are exact doubles; double arithmetic a + b·sqrt(c) often
  // gets these signs wrong (counted below, so this test is known to ask hard questions).
  std::mt19937_64 rng(23);
  int naive_wrong = 0, n = 0;
  for (int i = 0; i < 2000 * scale(); ++i) {
    const double k = random_double(rng, 26, -200, 200), b0 = random_double(rng, 26, -200, 200);
    const double b = (rng() & 1) ? b0 : -b0, a = -b * k, c = k * k;
    const int e = std::uniform_int_distribution<int>(-300, 300)(rng);  // the same questions, scaled
    const double t = std::ldexp(1.0, e);
    EXPECT_EQ(root_sum(a * t, b * t, c * t, t), ZERO) << a << " " << b << " " << c;
    for (const double dir : {-1.0, 1.0}) {
      const double c2 = std::nextafter(c, dir * HUGE_VAL);
      const Sign expected = dir > 0 ? sign_of(b) : -sign_of(b);
      ++n;
      naive_wrong += sign_of(a + b * std::sqrt(c2)) != expected;
      ASSERT_EQ(oracle(a, b, c2, 1.0), expected);
      EXPECT_EQ(root_sum(a, b, c2, 1.0), expected) << a << " + " << b << "√" << c2;
      EXPECT_EQ(root_sum(a * t, b * t, c2 * t, t), expected) << a << " + " << b << "√" << c2 << " at 2^" << e;
      const int f = filter_only(a, b, c2, 1.0);
      if (f != 2) {
        EXPECT_EQ(f, expected) << "the filter certified a wrong sign";
      }
    }
  }
  std::printf("double arithmetic got %d of %d near misses wrong\n", naive_wrong, n);
  EXPECT_GT(naive_wrong, n / 4) << "double arithmetic should get many of these wrong";
}

TEST(SignOfRootSum, RandomAgainstTheOracle) {
  // Random a, b, c (c ≥ 0), with random exponents over the whole range and t a power of two,
  // and near-cancelling ones: |a| ≈ |b|√c within a few units in the last place, or within a
  // relative 2⁻⁵² to 2⁻³⁸, where the filter's comparison of squares decides or gives up.
  std::mt19937_64 rng(2323);
  int certified = 0, well_separated = 0, filter_decided = 0, near[2] = {0, 0}, near_decided[2] = {0, 0};
  for (int i = 0; i < 3000 * scale(); ++i) {
    const int kind = i % 4;
    const int lo = kind == 0 ? -1074 : -60, hi = kind == 0 ? 1000 : 60;
    double a = random_double(rng, 53, lo, hi), b = random_double(rng, 53, lo, hi),
           c = random_double(rng, 53, lo, hi);
    if (rng() & 1) a = -a;
    if (rng() & 1) b = -b;
    if (kind == 2) {  // |a| = |b|·√c up to rounding, nudged by a few ulps
      a = -b * std::sqrt(c);
      for (int s = std::uniform_int_distribution<int>(-3, 3)(rng); s != 0; s += s > 0 ? -1 : 1)
        a = std::nextafter(a, s > 0 ? HUGE_VAL : -HUGE_VAL);
    }
    if (kind == 3) {  // |a| = |b|·√c·(1 ± 2⁻ʲ), j in [38, 52]
      const int j = std::uniform_int_distribution<int>(38, 52)(rng);
      a = -b * std::sqrt(c) * (1 + ((rng() & 1) ? 1 : -1) * std::ldexp(1.0, -j));
    }
    const double t = kind == 0 ? 1.0 : std::ldexp(1.0, std::uniform_int_distribution<int>(-200, 200)(rng));
    if (!std::isfinite(a * t) || !std::isfinite(c * t) || a * t == 0 || c * t == 0) continue;
    const double at = a * t, bt = b * t, ct = c * t;  // exact: t is a power of two
    if (at / t != a || ct / t != c || bt / t != b) continue;  // underflowed: skip
    const Sign expected = oracle(a, b, c, 1.0);
    EXPECT_EQ(root_sum(a, b, c, 1.0), expected) << a << " + " << b << "√" << c;
    EXPECT_EQ(root_sum(at, bt, ct, t), expected) << a << " + " << b << "√" << c << " scaled by " << t;
    const int f = filter_only(at, bt, ct, t);
    if (f != 2) {
      ++certified;
      EXPECT_EQ(f, expected) << "the filter certified a wrong sign: " << a << " + " << b << "√" << c;
    }
    if (kind == 1) {
      ++well_separated;
      filter_decided += f != 2;
    }
    if (kind >= 2) {
      ++near[kind - 2];
      near_decided[kind - 2] += f != 2;
    }
  }
  EXPECT_GT(certified, 0);
  // Measured, not proved: on random inputs of moderate exponents the filter decides almost all.
  std::printf("filter decided %d of %d random well-separated cases, %d of %d within a few ulps, %d of %d within "
              "2^-52..2^-38\n",
              filter_decided, well_separated, near_decided[0], near[0], near_decided[1], near[1]);
  EXPECT_GT(filter_decided, well_separated * 9 / 10);
}

// A that cancels: A = a·t − d·t with d within 2⁻ʲ of a, so fl(A) errs by up to 2ʲ·u·|A|, the
// case where the filter's error bounds e_A, e_C decide (with A, B, C exact in doubles, as above,
// the margin of K alone would hide a wrong e). B = b, C = c·t: A² and B²C have total degree 4.
constexpr auto kA2 = [](const auto& a, const auto& d, const auto&, const auto&, const auto& t) {
  return a * t - d * t;
};
constexpr auto kB2 = [](const auto&, const auto&, const auto& b, const auto&, const auto&) { return b; };
constexpr auto kC2 = [](const auto&, const auto&, const auto&, const auto& c, const auto& t) { return c * t; };

TEST(SignOfRootSum, CancellingPolynomialsAgainstTheOracle) {
  std::mt19937_64 rng(2024);
  int decided = 0, n = 0;
  for (int i = 0; i < 4000 * scale(); ++i) {
    // In [1, 2), so that M² (the filter's total-degree bound) is close to |a·t|: the bound is
    // within a small factor of the worst rounding, and a bound 4 times too small fails here.
    const double a = random_double(rng, 53, 1, 1), c = random_double(rng, 53, 1, 1), t = random_double(rng, 53, 1, 1);
    const int j = std::uniform_int_distribution<int>(4, 30)(rng);
    const double d = a * (1 + ((rng() & 1) ? 1 : -1) * std::ldexp(1.0, -j));
    // b√(ct) ≈ −A within a relative 2⁻ᵏ, k from 0 to j + 56: some far, some inside fl(A)'s error.
    const int k = std::uniform_int_distribution<int>(0, j + 56)(rng);
    const double b =
        -(a * t - d * t) / std::sqrt(c * t) * (1 + ((rng() & 1) ? 1 : -1) * std::ldexp(1.0, -k));
    if (b == 0) continue;
    const Sign expected = oracle(mpq_class(a) * t - mpq_class(d) * t, mpq_class(b), mpq_class(c) * t);
    ++n;
    EXPECT_EQ(sign_of_root_sum(kA2, kB2, kC2, a, d, b, c, t), expected) << a << " " << d << " " << b << " " << c;
    int known[3];
    const int f = detail::root_sum_filter<decltype(kA2), decltype(kB2), decltype(kC2)>(known, a, d, b, c, t);
    if (f != 2) {
      ++decided;
      EXPECT_EQ(f, expected) << "the filter certified a wrong sign: " << a << " " << d << " " << b << " " << c;
    }
  }
  std::printf("filter decided %d of %d with A cancelling\n", decided, n);
}

// Fortune's question: where is the site x = s against a breakpoint of the parabolas of sites p,
// q above the sweep line y = l? The heights of the two parabolas agree where α x² − 2β x + γ = 0,
// α = q_y − p_y, β = p_x(q_y − l) − q_x(p_y − l), γ = (q_y − l)(p_x² + p_y² − l²) −
// (p_y − l)(q_x² + q_y² − l²): at r = (β ± √C)/α, C = β² − αγ, and s − r = (αs − β ∓ √C)/α.
// A = (αs − β)·w, B = ∓w, with w = 1 the points' weight, so that A² and B²C have degree 6.
constexpr auto kFortuneA = [](const auto& px, const auto& py, const auto& qx, const auto& qy, const auto& l,
                              const auto& s, const auto& w) {
  return ((qy - py) * s - (px * (qy - l) - qx * (py - l))) * w;
};
constexpr auto kFortuneMinus = [](const auto&, const auto&, const auto&, const auto&, const auto&, const auto&,
                                  const auto& w) { return -w; };
constexpr auto kFortunePlus = [](const auto&, const auto&, const auto&, const auto&, const auto&, const auto&,
                                 const auto& w) { return w; };
constexpr auto kFortuneC = [](const auto& px, const auto& py, const auto& qx, const auto& qy, const auto& l,
                              const auto&, const auto&) {
  const auto beta = px * (qy - l) - qx * (py - l);
  const auto gamma = (qy - l) * (px * px + py * py - l * l) - (py - l) * (qx * qx + qy * qy - l * l);
  return beta * beta - (qy - py) * gamma;
};

/// sign(s − r) for the root r = (β + √C)/α (`plus`) or (β − √C)/α, from sign_of_root_sum.
Sign side_of_breakpoint(double px, double py, double qx, double qy, double l, double s, bool plus) {
  const Sign sa = sign_of(qy - py);  // the difference of two doubles has the exact sign
  return sa * (plus ? sign_of_root_sum(kFortuneA, kFortuneMinus, kFortuneC, px, py, qx, qy, l, s, 1.0)
                    : sign_of_root_sum(kFortuneA, kFortunePlus, kFortuneC, px, py, qx, qy, l, s, 1.0));
}

/// The same from the parabolas only, in exact rationals: h(x) = ((x − p_x)² + p_y² − l²)/(2(p_y − l))
/// is p's parabola; h_p − h_q has the sign of α (x − r₁)(x − r₂) (p_y, q_y > l), which is
/// negative between the roots when α > 0. The vertex v = β/α of that quadratic lies between them.
Sign side_of_breakpoint_oracle(double px, double py, double qx, double qy, double l, double s, bool plus) {
  const mpq_class Px(px), Py(py), Qx(qx), Qy(qy), L(l), S(s);
  const mpq_class hp = ((S - Px) * (S - Px) + Py * Py - L * L) / (2 * (Py - L));
  const mpq_class hq = ((S - Qx) * (S - Qx) + Qy * Qy - L * L) / (2 * (Qy - L));
  const int sa = sgn(mpq_class(Qy - Py)), sq = sgn(mpq_class(hp - hq));
  const int sv = sgn(mpq_class(S - (Px * (Qy - L) - Qx * (Py - L)) / (Qy - Py)));  // sign(s − v)
  const int sr = plus ? sa : -sa;  // sign(r − v): r₂ lies beyond v on the side of sign(α)
  if (sq == 0) return static_cast<Sign>(sv == sr ? 0 : -sr);  // s is r, or the other root
  if (sq != sa) return static_cast<Sign>(-sr);                 // between the roots
  return static_cast<Sign>(sv);                                 // beyond both, on the side of v
}

TEST(SignOfRootSum, FortuneBreakpointsAgainstTheParabolas) {
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> small(-8, 8), drop(1, 4);
  int ties = 0;
  for (int i = 0; i < 4000 * scale(); ++i) {
    double px, py, qx, qy, l, s;
    if (i % 3 == 0) {  // small integers: many exact ties
      px = small(rng), py = small(rng), qx = small(rng), qy = small(rng), s = small(rng) / 2.0;
      l = std::min(py, qy) - drop(rng);
    } else if (i % 3 == 1) {  // a breakpoint b built first: p, q at distance 65k = b_y − l from b
      const int k = 1 + static_cast<int>(rng() % 1000), triples[][2] = {{16, 63}, {33, 56}, {39, 52}, {25, 60}};
      const double bx = small(rng) * 1e3 + 0.5, by = small(rng);
      const auto* tp = triples[rng() % 4];
      const auto* tq = triples[rng() % 4];
      const int sp = (rng() & 1) ? 1 : -1, sq = (rng() & 1) ? 1 : -1, flip = (rng() & 1);
      px = bx + sp * k * tp[flip], py = by + (rng() & 1 ? 1 : -1) * k * tp[1 - flip];
      qx = bx + sq * k * tq[1 - flip], qy = by + (rng() & 1 ? 1 : -1) * k * tq[flip];
      l = by - 65.0 * k, s = bx;
    } else {  // random doubles
      px = random_double(rng, 53, -10, 10), py = random_double(rng, 53, -10, 10);
      qx = random_double(rng, 53, -10, 10), qy = random_double(rng, 53, -10, 10);
      s = random_double(rng, 53, -10, 10), l = std::min(py, qy) - random_double(rng, 53, -10, 10);
      if (rng() & 1) px = -px, s = -s;
    }
    if (py == qy || (px == qx && py == qy) || !(l < py && l < qy)) continue;
    for (const bool plus : {false, true}) {
      const Sign expected = side_of_breakpoint_oracle(px, py, qx, qy, l, s, plus);
      ties += expected == ZERO;
      EXPECT_EQ(side_of_breakpoint(px, py, qx, qy, l, s, plus), expected)
          << "p = (" << px << ", " << py << "), q = (" << qx << ", " << qy << "), l = " << l << ", s = " << s;
    }
  }
  std::printf("%d exact ties among the breakpoints\n", ties);
  EXPECT_GT(ties, 1000 * scale());
}

TEST(SignOfRootSum, BigIntegers) {
  // k of 100 to 200 bits: c = k² is a zero with a = −b·k, c = k² ± 1 a near miss whose sign is
  // ±sign(b); and random integers against the oracle.
  gmp_randclass g(gmp_randinit_default);
  g.seed(23);
  for (int i = 0; i < 300 * scale(); ++i) {
    const Integer k = g.get_z_bits(100 + i % 101) + 1, b = g.get_z_bits(150) + 1;
    const Integer bs = (i & 1) ? Integer(b) : Integer(-b);
    const Integer a = -bs * k, c = k * k, one = 1;
    EXPECT_EQ(root_sum(a, bs, c, one), ZERO);
    EXPECT_EQ(root_sum(a, bs, Integer(c + 1), one), sign_of(bs));
    EXPECT_EQ(root_sum(a, bs, Integer(c - 1), one), -sign_of(bs));
    EXPECT_EQ(oracle(a, bs, Integer(c + 1)), sign_of(bs));
    const Integer ra = g.get_z_bits(1 + i % 300) * ((i & 2) ? 1 : -1), rc = g.get_z_bits(1 + i % 250);
    EXPECT_EQ(root_sum(ra, bs, rc, one), oracle(ra, bs, rc)) << ra << " + " << bs << "√" << rc;
  }
}

}  // namespace
}  // namespace t2
