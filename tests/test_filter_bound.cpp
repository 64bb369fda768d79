// The error bound filter.hpp derives from the shape of a polynomial, and the two predicates on
// homogeneous double points that run on it most: side(l, p) and compare_distance with general w.
// Oracles in exact rationals written from the pictures, not from the library's polynomials: the
// side of a point is the side of its drawn position (x/w, y/w) on the Cartesian line
// W + X·x + Y·y = 0, read through the sign of w (w = 0: the direction's side); distances are
// Euclidean distances of drawn positions, with the rules of §4.3.1 for points of Ω.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>

#include "t2/kernel/distance.hpp"
#include "t2/kernel/line.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

using testing::pos;
using testing::q;
using testing::scale;
using testing::sq;

// ---------------------------------------------------------------------------------------------
// The derived constants against the derivation by hand.

constexpr double u = 0x1p-53;

TEST(FilterBound, DerivedConstantsMatchTheHandDerivation) {
  // side: W·w + X·x + Y·y. Three monomials; each meets its product and at most two sums: k = 3;
  // degree 1 in the line and 1 in the point. C = 3·3·u·(1 + 2⁻⁴⁰).
  constexpr auto side_poly = [](const auto& m, const auto& p) { return m.W * p.w + m.X * p.x + m.Y * p.y; };
  constexpr auto s = detail::derive_bound<Line, Point>(side_poly);
  static_assert(s.per_argument && s.degree[0] == 1 && s.degree[1] == 1 && s.total == 2 && s.count == 3);
  static_assert(s.c == 9 * u * (1 + 0x1p-40));
  // compare_distance, all proper (distance.hpp): (eₓ² + e_y²)·q_w² − (fₓ² + f_y²)·p_w² with
  // eₓ = pₓr_w − rₓp_w. Multiplied out: (2·2 + 2·2)·1 monomials per side, 16 in all, degree 2 in
  // each point; a monomial meets 2 roundings in eₓ (twice: it is squared), the square, the sum,
  // the square q_w², the product and the final difference: k = 9. C = 16·9·u·(1 + 2⁻⁴⁰).
  constexpr auto dist_poly = [](const auto& p, const auto& q, const auto& r) {
    const auto ex = p.x * r.w - r.x * p.w, ey = p.y * r.w - r.y * p.w;
    const auto fx = q.x * r.w - r.x * q.w, fy = q.y * r.w - r.y * q.w;
    return (ex * ex + ey * ey) * (q.w * q.w) - (fx * fx + fy * fy) * (p.w * p.w);
  };
  constexpr auto d = detail::derive_bound<Point, Point, Point>(dist_poly);
  static_assert(d.per_argument && d.degree[0] == 2 && d.degree[1] == 2 && d.degree[2] == 2 && d.count == 16);
  static_assert(d.c == 144 * u * (1 + 0x1p-40));
  static_assert(d.range == 0x1p150);  // R = 900/6
  // Homogeneous only in total degree: one maximum M of all arguments, M².
  constexpr auto pyth = [](const auto& a, const auto& b, const auto& c) { return a * a + b * b - c * c; };
  constexpr auto y = detail::derive_bound<double, double, double>(pyth);
  static_assert(!y.per_argument && y.total == 2 && y.c == 3 * 3 * u * (1 + 0x1p-40));
  // Not homogeneous: no bound (every call would be decided exactly).
  constexpr auto bad = detail::derive_bound<double, double>([](const auto& a, const auto& b) { return a * a - b; });
  static_assert(bad.c == HUGE_VAL);
  SUCCEED();
}

// ---------------------------------------------------------------------------------------------
// side(l, p)

/// The side of p from its drawn position: sign(w)·sign(W + X·x/w + Y·y/w), or for p on Ω the
/// side of the direction (x, y) against the line's normal (X, Y).
Sign side_oracle(const Line& l, const Point& p) {
  const Rational W = q(l.W()), X = q(l.X()), Y = q(l.Y());
  if (p.w() == 0) return static_cast<Sign>(sgn(Rational(X * q(p.x()) + Y * q(p.y()))));
  const auto [x, y] = pos(p);
  return static_cast<Sign>(sgn(q(p.w())) * sgn(Rational(W + X * x + Y * y)));
}

/// The triple times 2^e (exact unless it underflows; the oracle reads the stored values), or
/// nothing when all of it underflowed to zero.
std::optional<Point> scaled(const Point& p, int e) {
  const double w = std::ldexp(p.w(), e), x = std::ldexp(p.x(), e), y = std::ldexp(p.y(), e);
  if (w == 0 && x == 0 && y == 0) return std::nullopt;
  return Point(w, x, y);
}
std::optional<Line> scaled(const Line& l, int e) {
  const double W = std::ldexp(l.W(), e), X = std::ldexp(l.X(), e), Y = std::ldexp(l.Y(), e);
  if (W == 0 && X == 0 && Y == 0) return std::nullopt;
  return Line(W, X, Y);
}

/// Checks side(l, p) at every exponent of the issue, both orders of sign, and returns the answer.
Sign check_side(const Line& l, const Point& p) {
  const Sign want = side_oracle(l, p);
  EXPECT_EQ(side(l, p), want) << to_string(l) << " " << to_string(p);
  EXPECT_EQ(side(l, antipode(p)), -want);
  EXPECT_EQ(side(opposite(l), p), -want);
  for (int el : {60, -60, 500, -500, -1000})
    for (int ep : {0, 60, -500, 480, -1040}) {
      const auto sl = scaled(l, el);
      const auto sp = scaled(p, ep);
      if (!sl || !sp) continue;  // all underflowed
      EXPECT_EQ(side(*sl, *sp), side_oracle(*sl, *sp)) << el << " " << ep << " " << to_string(l) << to_string(p);
    }
  return want;
}

TEST(SideDouble, RandomLinesAndPointsOfEveryKind) {
  std::mt19937_64 rng(91);
  std::uniform_real_distribution<double> v(-1, 1);
  std::uniform_int_distribution<int> kind(0, 4);
  for (int i = 0; i < 800 * scale(); ++i) {
    const Line l(v(rng), v(rng), v(rng));
    const int k = kind(rng);  // front, back, Ω, subnormal w, tiny x
    const double w = k == 0 ? std::fabs(v(rng)) : k == 1 ? -std::fabs(v(rng)) : k == 2 ? 0.0 : k == 3 ? 0x1p-1070 : v(rng);
    check_side(l, Point(w, v(rng), k == 4 ? 0x1p-1060 * v(rng) : v(rng)));
  }
}

TEST(SideDouble, PointsRoundedOntoTheLineOnBothSides) {
  // l is the line through a and b written with the exact cross product of small integers, the
  // points are rounded points of the segment ab times a random weight w of either sign (the
  // products round again): each is within a few ulps of l, on either side or on it.
  std::mt19937_64 rng(92);
  std::uniform_int_distribution<int> c(-1000, 1000);
  std::uniform_real_distribution<double> t(0, 1), wt(0.1, 10);
  int counts[3] = {0, 0, 0};
  for (int i = 0; i < 1500 * scale(); ++i) {
    const double ax = c(rng), ay = c(rng), bx = c(rng), by = c(rng);
    if (ax == bx && ay == by) continue;
    const Line l(ax * by - ay * bx, ay - by, bx - ax);  // exact: [1, a] ∨ [1, b]
    // s = k/8 with w = ±1 puts the point exactly on l (small integers: nothing rounds).
    const double s = i % 4 ? t(rng) : (i % 9) / 8.0, x = ax + s * (bx - ax), y = ay + s * (by - ay);
    const double w = (i % 2 ? 1 : -1) * (i % 3 ? wt(rng) : 1.0);
    const Sign got = check_side(l, Point(w, w * x, w * y));
    ++counts[got + 1];
  }
  // The exact zeros (the rounded point fell on l) and both sides all occur.
  EXPECT_GT(counts[0], 50);
  EXPECT_GT(counts[1], 50);
  EXPECT_GT(counts[2], 50);
}

TEST(SideDouble, IntegerGridsAreExactAndAgreeWithExactLines) {
  std::mt19937_64 rng(93);
  std::uniform_int_distribution<long> c(-30, 30);
  for (int i = 0; i < 1000 * scale(); ++i) {
    const long W = c(rng), X = c(rng), Y = c(rng), w = c(rng), x = c(rng), y = c(rng);
    if ((W == 0 && X == 0 && Y == 0) || (w == 0 && x == 0 && y == 0)) continue;
    const Line l{double(W), double(X), double(Y)};
    const Point p{double(w), double(x), double(y)};
    const Sign want = check_side(l, p);
    EXPECT_EQ(side(ExactLine(W, X, Y), ExactPoint(w, x, y)), want);
  }
}

// ---------------------------------------------------------------------------------------------
// compare_distance with general w

int side_sign(const Point& p) { return p.w() > 0 ? 1 : p.w() < 0 ? -1 : 0; }

/// The rules of §4.3.1 from the pictures (distance.hpp's comment): for proper points Euclidean
/// distances on c's side, beyond infinity across; a point of Ω is at +∞ from a proper c; c on Ω:
/// the later point of the sweep towards c; a, b on Ω or all three: the angle at the origin of R³;
/// c and one of a, b on Ω: the other, proper, counts as 90° from c.
/// Throws `Undefined` for c on Ω with a, b proper on opposite sides.
Sign distance_oracle(const Point& a, const Point& b, const Point& c) {
  const int sa = side_sign(a), sb = side_sign(b), sc = side_sign(c);
  const int on_omega = (sa == 0) + (sb == 0) + (sc == 0);
  if (on_omega >= 2) {  // compare cos∠(a o c) = a·c/(|a||c|) with cos∠(b o c): the larger is nearer
    auto dot = [](const Point& p, const Point& r) {
      return Rational(q(p.w()) * q(r.w()) + q(p.x()) * q(r.x()) + q(p.y()) * q(r.y()));
    };
    const Rational da = dot(a, c), db = dot(b, c), na = dot(a, a), nb = dot(b, b);
    // c and one of a, b on Ω: the proper one is 90° from c (chapter 03, §5), its cosine is 0.
    if (sc == 0 && sa != 0) return static_cast<Sign>(sgn(db));
    if (sc == 0 && sb != 0) return static_cast<Sign>(-sgn(da));
    // sign(cos a − cos b) = sign(da/√na − db/√nb): by signs first, then by squares.
    const int ga = sgn(da), gb = sgn(db);
    if (ga != gb) return ga > gb ? NEGATIVE : POSITIVE;
    const int bigger = sgn(Rational(da * da * nb - db * db * na));  // |cos a| vs |cos b|
    return static_cast<Sign>(ga >= 0 ? -bigger : bigger);
  }
  if (sc == 0) {  // the sweep towards c = [0, u]: key u·(x, y)/|w|, the larger is nearer
    if (sa != sb) throw Undefined("opposite sides");
    auto key = [&](const Point& p) {
      return Rational((q(c.x()) * q(p.x()) + q(c.y()) * q(p.y())) / abs(q(p.w())));
    };
    return static_cast<Sign>(sgn(Rational(key(b) - key(a))));
  }
  if (sa == 0) return sb == sc ? POSITIVE : NEGATIVE;
  if (sb == 0) return sa == sc ? NEGATIVE : POSITIVE;
  auto rank = [&](const Point& p) {  // (0, d²) on c's side, (1, −d²) beyond infinity
    const Rational e = sq(pos(p), pos(c));
    return side_sign(p) == sc ? std::pair<int, Rational>{0, e} : std::pair<int, Rational>{1, -e};
  };
  const auto ra = rank(a), rb = rank(b);
  if (ra.first != rb.first) return ra.first < rb.first ? NEGATIVE : POSITIVE;
  return static_cast<Sign>(sgn(Rational(ra.second - rb.second)));
}

/// Checks compare_distance on a, b, c and on every positive power-of-two rescaling of each point
/// of the exponents (the same points when exact; the oracle reads the stored values).
void check_distance(const Point& a, const Point& b, const Point& c, int& ties) {
  Sign want;
  try {
    want = distance_oracle(a, b, c);
  } catch (const Undefined&) {
    EXPECT_THROW(compare_distance(a, b, c), Undefined);
    return;
  }
  ties += want == ZERO;
  EXPECT_EQ(compare_distance(a, b, c), want) << to_string(a) << to_string(b) << to_string(c);
  EXPECT_EQ(compare_distance(b, a, c), -want);
  for (const auto& e : {std::array{60, -60, 0}, std::array{-500, 500, 60}, std::array{140, -140, -150},
                        std::array{-1000, 0, 0}, std::array{0, -1060, 300}}) {
    const auto sa = scaled(a, e[0]), sb = scaled(b, e[1]), sc = scaled(c, e[2]);
    if (!sa || !sb || !sc) continue;  // all underflowed
    Sign w2;
    try {
      w2 = distance_oracle(*sa, *sb, *sc);
    } catch (const Undefined&) {
      EXPECT_THROW(compare_distance(*sa, *sb, *sc), Undefined);
      continue;
    }
    EXPECT_EQ(compare_distance(*sa, *sb, *sc), w2) << e[0] << " " << e[1] << " " << e[2] << to_string(a)
                                                << to_string(b) << to_string(c);
  }
}

TEST(CompareDistanceDouble, RandomHomogeneousPointsOfEveryKind) {
  std::mt19937_64 rng(94);
  std::uniform_real_distribution<double> v(-1, 1);
  std::uniform_int_distribution<int> kind(0, 5);
  auto point = [&] {
    const int k = kind(rng);  // front, back (twice), Ω, subnormal w
    const double w = k <= 1 ? std::fabs(v(rng)) : k <= 3 ? -std::fabs(v(rng)) : k == 4 ? 0.0 : 0x1p-1070;
    return Point(w, v(rng), v(rng));
  };
  int ties = 0;
  for (int i = 0; i < 600 * scale(); ++i) check_distance(point(), point(), point(), ties);
}

TEST(CompareDistanceDouble, NearlyEquidistantWithWeightsOfEitherSign) {
  // a and b rounded onto one circle around c (or a the reflection of b through c: a tie when
  // the weights are powers of two), then each point written as [w, w·x, w·y] with its own
  // weight of either sign (rounded again). Same-side and across-side pairs both occur.
  std::mt19937_64 rng(95);
  std::uniform_real_distribution<double> v(-1, 1), t(0, 6.283185307179586), wt(0.1, 10);
  std::uniform_int_distribution<int> k(-2, 2), pw(-3, 3);
  int ties = 0;
  for (int i = 0; i < 1500 * scale(); ++i) {
    const double cx = v(rng), cy = v(rng), r = 0.1 + std::fabs(v(rng)), s = t(rng), g = t(rng);
    double bx = cx + r * std::cos(g), by = cy + r * std::sin(g);
    for (int j = k(rng); j != 0; j += j > 0 ? -1 : 1) by = std::nextafter(by, j > 0 ? 9.0 : -9.0);
    const bool reflect = i % 4 == 0;
    const double ax = reflect ? 2 * cx - bx : cx + r * std::cos(s), ay = reflect ? 2 * cy - by : cy + r * std::sin(s);
    auto weight = [&] {
      const double m = i % 3 == 0 ? std::ldexp(1.0, pw(rng)) : wt(rng);
      return k(rng) < 0 ? -m : m;
    };
    const double wa = weight(), wb = weight(), wc = weight();
    check_distance(Point(wa, wa * ax, wa * ay), Point(wb, wb * bx, wb * by), Point(wc, wc * cx, wc * cy), ties);
  }
  EXPECT_GT(ties, 20);  // reflections (when 2c − b rounds to nothing) with power-of-two weights
}

TEST(CompareDistanceDouble, SweepAndAngleRulesNearTies) {
  // c on Ω and a, b nearly on one line perpendicular to c's direction (nearly equal keys);
  // two or three points of Ω at nearly equal angles.
  std::mt19937_64 rng(96);
  std::uniform_real_distribution<double> v(-1, 1), wt(0.1, 10);
  int ties = 0;
  for (int i = 0; i < 800 * scale(); ++i) {
    const double ux = v(rng), uy = v(rng);
    const Point c(0, ux, uy);
    // The line ux·x + uy·y = h, two rounded points of it, on one side.
    const double h = v(rng), s1 = v(rng), s2 = v(rng), n = ux * ux + uy * uy;
    const double x1 = ux * h / n - uy * s1, y1 = uy * h / n + ux * s1, x2 = ux * h / n - uy * s2, y2 = uy * h / n + ux * s2;
    const double sgn = i % 2 ? 1 : -1, w1 = sgn * wt(rng), w2 = i % 5 ? sgn * wt(rng) : -sgn * wt(rng);
    check_distance(Point(w1, w1 * x1, w1 * y1), Point(w2, w2 * x2, w2 * y2), c, ties);
    // Angle rule: a, b on Ω mirror images about c's direction (rounded), c anywhere.
    const double cw = i % 3 ? v(rng) : 0.0;
    const Point cc(cw, ux, uy), a(0, ux + 1e-3 * uy, uy - 1e-3 * ux), b(0, ux - 1e-3 * uy, uy + 1e-3 * ux);
    check_distance(a, b, cc, ties);
  }
}

// ---------------------------------------------------------------------------------------------
// A polynomial that varies with a parameter, written the legal way (filter.hpp, bound_of): one
// lambda without captures per parameter value, so each gets the bound of its own polynomial. A
// capturing lambda reading n would share one bound between all n (tests/compile_fail).

template <int N, class T>
constexpr auto power(const T& x) {
  if constexpr (N == 1) {
    return x;
  } else {
    return x * power<N - 1>(x);
  }
}
template <int N>
constexpr auto power_difference = [](const auto& x, const auto& y) { return power<N>(x) - power<N>(y); };

template <int N>
void expect_power_difference_exact(std::mt19937_64& rng) {
  constexpr auto b = detail::derive_bound<double, double>(power_difference<N>);
  static_assert(b.total == N && b.count == 2 && b.c < HUGE_VAL);  // its own degree, not the first n's
  std::uniform_int_distribution<int> e(-100 / N, 100 / N);
  for (int i = 0; i < 2000 * scale(); ++i) {
    const double y = std::ldexp(std::uniform_real_distribution<double>(1, 2)(rng), e(rng));
    double x = y;  // x within a few ulps of y, or of a tiny or huge y, or far
    for (int k = std::uniform_int_distribution<int>(-3, 3)(rng); k != 0; k += k > 0 ? -1 : 1)
      x = std::nextafter(x, k > 0 ? HUGE_VAL : 0.0);
    if (i % 5 == 0) x = std::ldexp(x, e(rng));
    if (i % 7 == 0) x = -x;
    Rational xn = 1, yn = 1;
    for (int k = 0; k < N; ++k) xn *= q(x), yn *= q(y);
    EXPECT_EQ(sign_of_poly(power_difference<N>, x, y), static_cast<Sign>(sgn(Rational(xn - yn))))
        << "n = " << N << ", x = " << x << ", y = " << y;
  }
}

TEST(FilterBound, OneLambdaWithoutCapturesPerParameterAgreesWithRationals) {
  std::mt19937_64 rng(23);
  expect_power_difference_exact<1>(rng);  // the order of the first call does not matter:
  expect_power_difference_exact<5>(rng);  // each n has its own type and its own bound
  expect_power_difference_exact<3>(rng);
}

}  // namespace
}  // namespace t2
