// Predicates on the crossing (a ∨ b) ∧ (c ∨ d) of two joins, given by four points
// (t2/kernel/join_meet.hpp): the error bounds the filter derives for their polynomials against
// a derivation by hand, and their signs on random near-degenerate, exactly degenerate, far and
// tiny input against an oracle in exact rationals that constructs the point (two cross products)
// and divides by w.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "t2/kernel/join_meet.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

using R3 = std::array<Rational, 3>;
constexpr double u = 0x1p-53;

TEST(JoinMeet, DerivedBoundsMatchTheHandDerivation) {
  // A join coefficient is a 2×2 minor: 2 monomials, 2 roundings (product, difference). A meet
  // coordinate is a minor of two join coefficients: 2·2·2 = 8 monomials, 2 + 2 + 1 + 1 = 6.
  constexpr auto w = [](const auto& a, const auto& b, const auto& c, const auto& d) {
    return detail::join_meet_coordinate<0>(a, b, c, d);
  };
  constexpr auto bw = detail::derive_bound<Point, Point, Point, Point>(w);
  static_assert(bw.per_argument && bw.count == 8 && bw.total == 4 && bw.c == 8 * 6 * u * (1 + 0x1p-40));
  // orient(p, q, X) = Σ n_k·X_k: 3·2·8 = 48 monomials; a product of a join coefficient (2) and a
  // meet coordinate (6) is 9, and two more sums: 11.
  constexpr auto o = [](const auto& p, const auto& q, const auto& a, const auto& b, const auto& c, const auto& d) {
    const auto n = detail::join_of(p, q), l = detail::join_of(a, b), m = detail::join_of(c, d);
    return n.W * detail::meet_w(l, m) + n.X * detail::meet_x(l, m) + n.Y * detail::meet_y(l, m);
  };
  constexpr auto bo = detail::derive_bound<Point, Point, Point, Point, Point, Point>(o);
  static_assert(bo.per_argument && bo.count == 48 && bo.total == 6 && bo.c == 48 * 11 * u * (1 + 0x1p-40));
  // x₁w₂ − x₂w₁ of two meets: 2·8·8 = 128 monomials, 6 + 6 + 1 + 1 = 14 roundings, degree 8.
  constexpr auto cx = [](const auto& a, const auto& b, const auto& c, const auto& d, const auto& e, const auto& f,
                         const auto& g, const auto& h) {
    return detail::join_meet_coordinate<1>(a, b, c, d) * detail::join_meet_coordinate<0>(e, f, g, h) -
           detail::join_meet_coordinate<1>(e, f, g, h) * detail::join_meet_coordinate<0>(a, b, c, d);
  };
  constexpr auto bc = detail::derive_bound<Point, Point, Point, Point, Point, Point, Point, Point>(cx);
  static_assert(bc.per_argument && bc.count == 128 && bc.total == 8 && bc.c == 128 * 14 * u * (1 + 0x1p-40));
  // x·r.w − r.x·w of a meet and a point: 16 monomials, 6 + 0 + 1 + 1 = 8 roundings.
  constexpr auto cp = [](const auto& a, const auto& b, const auto& c, const auto& d, const auto& r) {
    return detail::join_meet_coordinate<1>(a, b, c, d) * r.w - r.x * detail::join_meet_coordinate<0>(a, b, c, d);
  };
  constexpr auto bp = detail::derive_bound<Point, Point, Point, Point, Point>(cp);
  static_assert(bp.per_argument && bp.count == 16 && bp.total == 5 && bp.c == 16 * 8 * u * (1 + 0x1p-40));
  SUCCEED();
}

// ---------------------------------------------------------------------------------------------
// The oracle: the crossing constructed in rationals, its normalized coordinates by division.

R3 cross(const R3& a, const R3& b) {
  return {Rational(a[1] * b[2] - a[2] * b[1]), Rational(a[2] * b[0] - a[0] * b[2]),
          Rational(a[0] * b[1] - a[1] * b[0])};
}
template <class P>
R3 meet_oracle(const P& a, const P& b, const P& c, const P& d) {
  return cross(cross(testing::triple(a), testing::triple(b)), cross(testing::triple(c), testing::triple(d)));
}
bool is_zero(const R3& v) { return v[0] == 0 && v[1] == 0 && v[2] == 0; }
Sign dot_sign(const R3& a, const R3& b) { return testing::sign_oracle(a[0] * b[0] + a[1] * b[1] + a[2] * b[2]); }

/// Every predicate of join_meet.hpp on X = (a∨b)∧(c∨d), Y = (e∨f)∧(g∨h) and the points p, q,
/// against the oracle. Returns false (testing nothing) when X or Y is undefined.
template <class T>
bool check_all(const std::array<BasicPoint<T>, 8>& s, const BasicPoint<T>& p, const BasicPoint<T>& q) {
  const R3 o1 = meet_oracle(s[0], s[1], s[2], s[3]), o2 = meet_oracle(s[4], s[5], s[6], s[7]);
  if (is_zero(o1) || is_zero(o2)) return false;
  const JoinMeet<T> x = join_meet(s[0], s[1], s[2], s[3]), y = join_meet(s[4], s[5], s[6], s[7]);
  EXPECT_EQ(x.w, testing::sign_oracle(o1[0]));
  EXPECT_EQ(turn(s[4], s[5], s[6], s[7]), testing::sign_oracle(o2[0]));
  EXPECT_EQ(compare_xy(x, y), testing::xy_oracle(o1, o2));
  EXPECT_EQ(compare_x(x, y), testing::compare_oracle(testing::normal_xy(o1)[0], testing::normal_xy(o2)[0]));
  EXPECT_EQ(compare_y(y, x), testing::compare_oracle(testing::normal_xy(o2)[1], testing::normal_xy(o1)[1]));
  EXPECT_EQ(compare_xy(x, p), testing::xy_oracle(o1, testing::triple(p)));
  EXPECT_EQ(compare_xy(q, y), testing::xy_oracle(testing::triple(q), o2));
  EXPECT_EQ(compare_y(x, q), testing::compare_oracle(testing::normal_xy(o1)[1], testing::normal_xy(testing::triple(q))[1]));
  EXPECT_EQ(orient(p, q, x), dot_sign(cross(testing::triple(p), testing::triple(q)), o1));
  EXPECT_EQ(orient(s[4], s[5], x), dot_sign(cross(testing::triple(s[4]), testing::triple(s[5])), o1));
  // The exact construction is the oracle's point times a positive factor.
  const R3 e = testing::triple(to_exact(x));
  EXPECT_TRUE(is_zero(cross(e, o1)));
  EXPECT_GT(dot_sign(e, o1), ZERO);
  return true;
}

/// Eight copies of p, to be overwritten (Point has no default).
std::array<Point, 8> filled(const Point& p) { return {p, p, p, p, p, p, p, p}; }

/// Two points, rounded, on a line through P in a random direction, at random distances; the
/// first with w in [0.5, 4] unless `cartesian` (all w = 1: join_meet.hpp's moved filter runs).
std::array<Point, 2> through(std::mt19937_64& rng, const Point& P, bool cartesian = false) {
  std::uniform_real_distribution<double> t(-1, 1), scale(0.5, 4);
  const double dx = t(rng), dy = t(rng), s = t(rng), r = t(rng);
  const double w = cartesian ? 1 : scale(rng);
  return {Point(w, w * (P.x() + s * dx), w * (P.y() + s * dy)), Point(1, P.x() - r * dx, P.y() - r * dy)};
}

TEST(JoinMeet, NearDegenerateDoublesGetTheExactSign) {
  // Four segments nearly through one point P: both crossings lie within rounding of P and of
  // each other, and p, q lie on a line nearly through P, where a plain floating-point
  // evaluation has the wrong sign about half the time. Half the cases are Cartesian and far
  // from the origin (up to 10⁶, segments of length ~1): the moved filter's case.
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> coord(-1000, 1000);
  int tested = 0;
  for (int i = 0; i < 5000 * testing::scale(); ++i) {
    const bool cartesian = i % 2 == 1;
    const double far = cartesian ? 1000 : 1;
    const Point P(1, far * coord(rng), far * coord(rng));
    std::array<Point, 8> s = filled(P);
    for (int k = 0; k < 8; k += 2) {
      const auto ab = through(rng, P, cartesian);
      s[k] = ab[0];
      s[k + 1] = ab[1];
    }
    const auto pq = through(rng, P, cartesian);
    tested += check_all(s, pq[0], pq[1]);
    tested += check_all(s, P, pq[1]);
  }
  EXPECT_GT(tested, 9000 * testing::scale());
}

TEST(JoinMeet, ExactlyConcurrentJoinsGiveZero) {
  // Integer points on lines through (3, 5), some with w = 2 or 4: every crossing is exactly
  // (3, 5), so the orders give ZERO, and orient gives ZERO for p, q on another such line.
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> k(-50, 50);
  int zeros = 0, tested = 0;
  for (int i = 0; i < 2000 * testing::scale(); ++i) {
    std::array<Point, 8> s = filled(Point(1, 0, 0));
    for (int j = 0; j < 8; j += 2) {
      const int dx = k(rng), dy = k(rng) | 1, w = 1 << (k(rng) & 2);
      s[j] = Point(w, w * (3 + dx), w * (5 + dy));
      s[j + 1] = Point(1, 3 - 2 * dx, 5 - 2 * dy);
    }
    const int dx = k(rng) | 1;
    const Point p(1, 3 + dx, 5 + 3 * dx), q(2, 2 * (3 - dx), 2 * (5 - 3 * dx));
    if (!check_all(s, p, q)) continue;
    ++tested;
    JoinMeet<double> x = join_meet(s[0], s[1], s[2], s[3]), y = join_meet(s[4], s[5], s[6], s[7]);
    // The front one of the two antipodal points: (3, 5) both times.
    if (x.w == NEGATIVE) x = join_meet(s[2], s[3], s[0], s[1]);
    if (y.w == NEGATIVE) y = join_meet(s[6], s[7], s[4], s[5]);
    zeros += compare_xy(x, y) == ZERO && compare_xy(x, Point(1, 3, 5)) == ZERO && orient(p, q, y) == ZERO;
    // The same on Integer points, scaled far beyond 52 bits (JoinMeet<Integer>), one case in
    // ten (GMP all the way).
    if (i % 10 != 0) continue;
    const Integer big = Integer(1) << 90;
    const auto exact = [&](const Point& r) {
      const ExactPoint e = to_exact(r);
      return ExactPoint(Integer(e.w() * big), Integer(e.x() * big), Integer(e.y() * big));
    };
    std::array<ExactPoint, 8> e{exact(s[0]), exact(s[1]), exact(s[2]), exact(s[3]),
                                exact(s[4]), exact(s[5]), exact(s[6]), exact(s[7])};
    EXPECT_TRUE(check_all(e, exact(p), exact(q)));
  }
  EXPECT_EQ(zeros, tested);
  EXPECT_GT(tested, 1500 * testing::scale());
}

TEST(JoinMeet, FarAndTinyCoordinatesLeaveTheFilterRange) {
  // Some points sent far out or next to the origin (x, y scaled by 2^±300): the coordinates
  // leave the filter's range (R = 112 for degree 8) and the exact stages decide.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coord(-1000, 1000);
  for (int i = 0; i < 300 * testing::scale(); ++i) {
    const Point P(1, coord(rng), coord(rng));
    std::array<Point, 8> s = filled(P);
    for (int k = 0; k < 8; k += 2) {
      const auto ab = through(rng, P);
      s[k] = ab[0];
      s[k + 1] = ab[1];
    }
    const auto pq = through(rng, P);
    for (const int e : {300, -300}) {
      std::array<Point, 8> t = s;
      for (int k = 0; k < 8; k += 3) t[k] = Point(s[k].w(), std::ldexp(s[k].x(), e), std::ldexp(s[k].y(), e));
      ASSERT_TRUE(check_all(t, pq[0], pq[1]));
    }
  }
}

TEST(JoinMeet, CrossingsOnOmegaAndUndefinedCrossings) {
  // Parallel joins cross on Ω: the orders construct the point and compare it exactly.
  const Point a(1, 0, 0), b(1, 1, 1), c(1, 0, 1), d(1, 1, 2), e(1, 5, 0), f(1, 5, 1);
  const JoinMeet<double> x = join_meet(a, b, c, d);  // on Ω, in direction ±(1, 1)
  EXPECT_EQ(x.w, ZERO);
  EXPECT_TRUE(check_all(std::array<Point, 8>{a, b, c, d, a, b, e, f}, c, e));
  EXPECT_TRUE(check_all(std::array<Point, 8>{a, b, c, d, c, d, a, b}, a, b));
  // The same line twice, or a join of a point with itself: undefined.
  EXPECT_THROW(join_meet(a, b, b, Point(2, 6, 6)), Undefined);
  EXPECT_THROW(join_meet(a, a, c, d), Undefined);
  EXPECT_THROW(join_meet(a, b, c, Point(-1, 0, -1)), Undefined);  // c = ¬d
  EXPECT_EQ(turn(a, a, c, d), ZERO);
}

}  // namespace
}  // namespace t2
