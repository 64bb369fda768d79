// Predicates on points given as the meet of two lines (t2/kernel/meet_point.hpp): the error
// bounds the filter derives for their polynomials against a derivation by hand, and their signs
// on random near-degenerate and exactly degenerate input against an oracle in exact rationals
// that constructs the point (the cross product of the lines) and divides by w.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "t2/kernel/meet_point.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

using t2::Rational;
using R3 = std::array<Rational, 3>;

constexpr double u = 0x1p-53;

TEST(MeetPoint, DerivedBoundsMatchTheHandDerivation) {
  // x₁w₂ − x₂w₁ with xᵢ, wᵢ 2×2 minors: 2·2 monomials per product, 8 in all, degree 1 in each
  // of the four lines. A monomial meets the product and the difference of its minor (2), the
  // product of the two minors (2 + 2 + 1) and the final difference: k = 6.
  constexpr auto cmp = [](const auto& k, const auto& l, const auto& m, const auto& n) {
    return detail::meet_x(k, l) * detail::meet_w(m, n) - detail::meet_x(m, n) * detail::meet_w(k, l);
  };
  constexpr auto c = detail::derive_bound<Line, Line, Line, Line>(cmp);
  static_assert(c.per_argument && c.count == 8 && c.total == 4);
  static_assert(c.degree[0] == 1 && c.degree[1] == 1 && c.degree[2] == 1 && c.degree[3] == 1);
  static_assert(c.c == 8 * 6 * u * (1 + 0x1p-40));
  // side(n, l ∧ m) = n.W·w + n.X·x + n.Y·y: 6 monomials; a minor (2), the product (3), and at
  // most two sums: k = 5.
  constexpr auto sd = [](const auto& k, const auto& l, const auto& m) {
    return k.W * detail::meet_w(l, m) + k.X * detail::meet_x(l, m) + k.Y * detail::meet_y(l, m);
  };
  constexpr auto s = detail::derive_bound<Line, Line, Line>(sd);
  static_assert(s.per_argument && s.count == 6 && s.c == 6 * 5 * u * (1 + 0x1p-40));
  SUCCEED();
}

// ---------------------------------------------------------------------------------------------
// The oracle: the meet constructed in rationals, its normalized coordinates by division.

template <class L>
R3 coefficients(const L& l) {
  return {testing::q(l.W()), testing::q(l.X()), testing::q(l.Y())};
}
template <class L>
R3 meet_oracle(const L& l, const L& m) {
  const R3 a = coefficients(l), b = coefficients(m);
  return {Rational(a[1] * b[2] - a[2] * b[1]), Rational(a[2] * b[0] - a[0] * b[2]),
          Rational(a[0] * b[1] - a[1] * b[0])};
}
template <class P>
R3 point_triple(const P& p) {
  return {testing::q(p.w()), testing::q(p.x()), testing::q(p.y())};
}
Sign dot_sign(const R3& a, const R3& b) { return testing::sign_oracle(a[0] * b[0] + a[1] * b[1] + a[2] * b[2]); }

/// Every predicate of meet_point.hpp on these lines and points, against the oracle.
template <class T>
void check_all(const BasicLine<T>& a, const BasicLine<T>& b, const BasicLine<T>& c, const BasicLine<T>& d,
               const BasicPoint<T>& p, const BasicPoint<T>& q) {
  const MeetPoint<T> m1{a, b}, m2{c, d};
  const R3 o1 = meet_oracle(a, b), o2 = meet_oracle(c, d);
  ASSERT_EQ(compare_xy(m1, m2), testing::xy_oracle(o1, o2));
  ASSERT_EQ(compare_x(m1, m2), testing::compare_oracle(testing::normal_xy(o1)[0], testing::normal_xy(o2)[0]));
  ASSERT_EQ(compare_xy(m1, p), testing::xy_oracle(o1, point_triple(p)));
  ASSERT_EQ(compare_xy(p, m1), testing::xy_oracle(point_triple(p), o1));
  ASSERT_EQ(compare_y(m2, q), testing::compare_oracle(testing::normal_xy(o2)[1], testing::normal_xy(point_triple(q))[1]));
  ASSERT_EQ(side(c, m1), dot_sign(coefficients(c), o1));
  // Δ(p, q, m) = (p × q)·m.
  const R3 pp = point_triple(p), qq = point_triple(q);
  const R3 pq = {Rational(pp[1] * qq[2] - pp[2] * qq[1]), Rational(pp[2] * qq[0] - pp[0] * qq[2]),
                 Rational(pp[0] * qq[1] - pp[1] * qq[0])};
  ASSERT_EQ(orient(p, q, m1), dot_sign(pq, o1));
  ASSERT_EQ(turn(a, b), testing::sign_oracle(o1[0]));
}

TEST(MeetPoint, NearDegenerateDoublesGetTheExactSign) {
  // Lines through nearly one point P, each rounded: their meets lie within rounding of P and of
  // each other, where a plain floating-point evaluation has the wrong sign about half the time.
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> coord(-1000, 1000), dir(-1, 1);
  const int n = 20000 * testing::scale();
  int zero_x = 0;
  for (int i = 0; i < n; ++i) {
    const double px = coord(rng), py = coord(rng);
    const Point P(1, px, py);
    auto through = [&] {
      const double dx = dir(rng), dy = dir(rng);
      return join(P, Point(1, px + dx, py + dy));  // rounded: nearly through P
    };
    const Line a = through(), b = through(), c = through(), d = through();
    if (turn(a, b) == ZERO || turn(c, d) == ZERO) continue;
    // p and q on a line nearly through P too.
    const double t = dir(rng);
    check_all(a, b, c, d, P, Point(1, px + t, py - t));
    zero_x += compare_x(MeetPoint<double>{a, b}, MeetPoint<double>{c, d}) == ZERO;
  }
  RecordProperty("equal_x", zero_x);
}

TEST(MeetPoint, ExactlyConcurrentLinesGiveZero) {
  // Integer lines through the integer point (3, 5): every meet is exactly that point.
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> k(-50, 50);
  int zeros = 0, tested = 0;
  for (int i = 0; i < 2000 * testing::scale(); ++i) {
    auto through = [&](auto zero) {
      using P = BasicPoint<decltype(zero)>;
      const int dx = k(rng), dy = k(rng) | 1;
      const int s = 1 + (k(rng) & 3);  // a second representative, [s, 3s, 5s]
      return join(testing::make<P>(s, 3 * s, 5 * s), testing::make<P>(1, 3 + dx, 5 + dy));
    };
    const Line a = through(0.0), b = through(0.0), c = through(0.0), d = through(0.0);
    if (turn(a, b) == ZERO || turn(c, d) == ZERO) continue;
    const Point P(1, 3, 5), Q(2, 6 + 2 * k(rng), 10 + 2 * k(rng));
    check_all(a, b, c, d, P, Q);
    ++tested;
    // Of the two antipodal common points, take the front one: [1, 3, 5] both times.
    const MeetPoint<double> m1 = turn(a, b) == POSITIVE ? MeetPoint<double>{a, b} : MeetPoint<double>{b, a};
    const MeetPoint<double> m2 = turn(c, d) == POSITIVE ? MeetPoint<double>{c, d} : MeetPoint<double>{d, c};
    zeros += compare_xy(m1, m2) == ZERO && compare_xy(m1, P) == ZERO;
    // The same on Integer lines (big integers, scaled far beyond 52 bits).
    const Integer big = Integer(1) << 90;
    auto exact = [&](const Line& l) {
      const ExactLine e = detail::exact_line(l);
      return ExactLine(Integer(e.W() * big), Integer(e.X() * big), Integer(e.Y() * big));
    };
    check_all(exact(a), exact(b), exact(c), exact(d), to_exact(P), to_exact(Q));
  }
  EXPECT_EQ(zeros, tested);  // every meet is (3, 5)
  EXPECT_GT(tested, 500);
}

TEST(MeetPoint, MeetsOnOmegaAndUndefinedMeets) {
  // Parallel lines meet on Ω: the orders fall back to the constructed point.
  const Line h1(0, 0, 1), h2(-1, 0, 1), v1(0, 1, 0), v2(-2, 1, 0), diag(0, 1, -1);
  check_all(h1, h2, v1, v2, Point(1, 0, 0), Point(0, 1, 1));
  check_all(v1, v2, h1, diag, Point(0, -1, 0), Point(1, 2, 3));
  check_all(h1, v1, diag, Line(-1, 1, -1), Point(-1, 4, 4), Point(1, 0, 0));  // back point p
  EXPECT_THROW(compare_xy(MeetPoint<double>{h1, opposite(h1)}, Point(1, 0, 0)), Undefined);
  EXPECT_THROW(side(v1, MeetPoint<double>{h1, h1}), Undefined);
  EXPECT_EQ(point_of(MeetPoint<double>{h1, v1}), meet(h1, v1));
  EXPECT_EQ(point_of(MeetPoint<Integer>{detail::exact_line(h1), detail::exact_line(v1)}),
            meet(detail::exact_line(h1), detail::exact_line(v1)));
}

}  // namespace
}  // namespace t2
