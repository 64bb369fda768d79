// The wxy order of §4.3.3 against normalized coordinates computed in exact rationals, and the
// order along a line against its parametrization in the planar model: ¬D, the front points by
// their drawn position along the direction d of the line, D, then the back points, also by
// their drawn position along d (going round the back of the sphere the drawing runs from −∞ to +∞).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>
#include <tuple>
#include <vector>

#include "t2/kernel/lexicographic.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

using testing::scale;

using testing::make;
using testing::q;

/// Normalized coordinates, exactly: [±1, x/|w|, y/|w|] or [0, x/m, y/m], m = max(|x|, |y|).
template <class P>
std::array<Rational, 3> normalized_oracle(const P& p) {
  const Rational w = q(p.w()), x = q(p.x()), y = q(p.y());
  const Rational s = w != 0 ? Rational(abs(w)) : Rational(std::max(abs(x), abs(y)));
  return {w / s, x / s, y / s};
}

template <class V>
Sign lex(const V& a, const V& b) {
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i] != b[i]) return a[i] < b[i] ? NEGATIVE : POSITIVE;
  return ZERO;
}

template <class P>
void wxy_matches_normalized(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<long> u(-4, 4);
  int ties = 0;
  for (int i = 0; i < 5000 * scale(); ++i) {
    long a[3] = {u(rng), u(rng), u(rng)}, b[3] = {u(rng), u(rng), u(rng)};
    if (a[0] == 0 && a[1] == 0 && a[2] == 0) a[0] = 1;
    if (b[0] == 0 && b[1] == 0 && b[2] == 0) b[2] = -1;
    const P p = make<P>(a[0], a[1], a[2]), r = make<P>(b[0], b[1], b[2]);
    const auto np = normalized_oracle(p), nr = normalized_oracle(r);
    const Sign want = lex(np, nr);
    ties += want == ZERO;
    ASSERT_EQ(compare_lexicographic(p, r), want);
    ASSERT_EQ(compare_lexicographic(r, p), -want);
    ASSERT_EQ(want == ZERO, p == r);  // only equal points tie
    ASSERT_EQ(less_wxy(p, r), want == NEGATIVE);
    ASSERT_EQ(compare_x(p, r), lex(std::array{np[1]}, std::array{nr[1]}));
    ASSERT_EQ(compare_y(p, r), lex(std::array{np[2]}, std::array{nr[2]}));
    ASSERT_EQ(compare_xy(p, r), lex(std::array{np[1], np[2]}, std::array{nr[1], nr[2]}));
    ASSERT_EQ(less_xy(p, r), compare_xy(p, r) == NEGATIVE);
  }
  EXPECT_GT(ties, 0);
}

TEST(Lexicographic, NearlyEqualRatiosAtEveryScale) {
  // compare_x on doubles: x/|w| of two points that are nearly (or exactly) the same multiple,
  // at every exponent, against the rational normalized coordinates.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1), w(0.5, 4);
  std::uniform_int_distribution<int> k(-2, 2), side(0, 2);
  int ties = 0;
  for (int e : {0, 60, -60, 300, -300, 484, -484, 501, -520, 1000, -1060}) {
    for (int i = 0; i < 300 * scale(); ++i) {
      const double x = u(rng), pw = w(rng), qw = i % 3 ? w(rng) : pw, f = qw / pw;
      double qx = x * f;  // rounded: q's ratio is within an ulp or two of p's
      for (int j = k(rng); j != 0; j += j > 0 ? -1 : 1) qx = std::nextafter(qx, j > 0 ? 9.0 : -9.0);
      const double sp = side(rng) ? 1 : -1, sq = side(rng) ? 1 : -1;
      const Point p(sp * pw, sp * std::ldexp(x, e), u(rng)), r(sq * qw, sq * std::ldexp(qx, e), u(rng));
      const Sign want = lex(std::array{normalized_oracle(p)[1]}, std::array{normalized_oracle(r)[1]});
      ties += want == ZERO;
      ASSERT_EQ(compare_x(p, r), want) << e;
      ASSERT_EQ(compare_x(r, p), -want) << e;
    }
  }
  EXPECT_GT(ties, 0);
}

TEST(Lexicographic, WxyOrderIsTheOrderOfNormalizedCoordinates) {
  wxy_matches_normalized<Point>(1);
  wxy_matches_normalized<ExactPoint>(2);
}

TEST(Lexicographic, BackThenOmegaThenFrontAndDoublesAgreeWithIntegers) {
  std::vector<Point> pts = {Point(1, 5, 5), Point(0, 1, 0), Point(-1, 0, 0), Point(2, 0, 0), Point(0, -3, 7)};
  std::sort(pts.begin(), pts.end(), less_wxy<double>);
  EXPECT_EQ(side_of(pts[0]), Side::back);
  EXPECT_EQ(side_of(pts[1]), Side::infinity);
  EXPECT_EQ(side_of(pts[2]), Side::infinity);
  EXPECT_EQ(side_of(pts[3]), Side::front);
  EXPECT_TRUE(pts[3] == Point(1, 0, 0));  // x = 0 < 5
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> e(-300, 300), z(0, 4);
  for (int i = 0; i < 5000 * scale(); ++i) {
    auto c = [&] { return z(rng) == 0 ? 0.0 : std::ldexp(u(rng), e(rng)); };
    const Point p(c(), c() + 0.5, c()), r(c(), c(), c() - 0.5);
    ASSERT_EQ(compare_lexicographic(p, r), compare_lexicographic(to_exact(p), to_exact(r)));
    ASSERT_EQ(compare_lexicographic(p, r), lex(normalized_oracle(p), normalized_oracle(r)));
  }
}

/// The oracle key of a point p of the line l (not ±Ω) in the order along l.
template <class P>
std::pair<int, Rational> along_key(const BasicLine<typename P::Coordinate>& l, const P& p) {
  const Rational dx = q(l.Y()), dy = -q(l.X());  // d: the direction l runs in
  const Rational w = q(p.w()), x = q(p.x()), y = q(p.y());
  if (w == 0) return {dx * x + dy * y > 0 ? 2 : 0, Rational(0)};
  return {w > 0 ? 1 : 3, (dx * x + dy * y) / w};  // position of the drawing along d
}

template <class P>
void along_matches_parametrization(std::uint64_t seed) {
  using T = typename P::Coordinate;
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<long> u(-6, 6), k(-4, 4);
  int checked = 0;
  for (int i = 0; i < 300 * scale(); ++i) {
    const P a = make<P>(u(rng), u(rng), u(rng) | 1), b = make<P>(u(rng), u(rng) | 1, u(rng));
    if (orient(a, b, make<P>(1, 0, 0)) == ZERO && orient(a, b, make<P>(0, 1, 0)) == ZERO &&
        orient(a, b, make<P>(0, 0, 1)) == ZERO)
      continue;  // a = ±b
    const auto l = join(a, b);
    if (l.X() == 0 && l.Y() == 0) continue;  // Omega: tested below
    std::vector<P> pts;
    for (int j = 0; j < 12; ++j) {
      const long s = k(rng), t = k(rng);
      const T w = T(s) * a.w() + T(t) * b.w(), x = T(s) * a.x() + T(t) * b.x(), y = T(s) * a.y() + T(t) * b.y();
      if (w == 0 && x == 0 && y == 0) continue;
      pts.push_back(P(w, x, y));
    }
    pts.push_back(meet(l, omega<T>()));
    pts.push_back(antipode(pts.back()));
    for (const P& p : pts)
      for (const P& r : pts) {
        const auto kp = along_key(l, p), kr = along_key(l, r);
        const Sign want = kp < kr ? NEGATIVE : (kr < kp ? POSITIVE : ZERO);
        ASSERT_EQ(compare_along_line(l, p, r), want) << to_string(p) << to_string(r);
        ++checked;
      }
    const auto sorted = sort_along(l, pts);
    ASSERT_EQ(sorted.size(), pts.size());
    ASSERT_TRUE(std::is_sorted(sorted.begin(), sorted.end(),
                               [&](const P& p, const P& r) { return along_key(l, p) < along_key(l, r); }));
    ASSERT_TRUE(std::is_permutation(sorted.begin(), sorted.end(), pts.begin(),
                                    [](const P& p, const P& r) { return p.w() == r.w() && p.x() == r.x() && p.y() == r.y(); }));
    for (const P& off : {make<P>(1, 0, 0), make<P>(0, 1, 0), make<P>(0, 0, 1)})
      if (side(l, off) != ZERO) {
        ASSERT_THROW(compare_along_line(l, off, pts[0]), Undefined);
        ASSERT_THROW(sort_along(l, std::vector<P>{pts[0], off}), Undefined);
      }
  }
  EXPECT_GT(checked, 1000);
}

TEST(AlongLine, OrderIsTheParametrizationOfTheLine) {
  along_matches_parametrization<Point>(4);
  along_matches_parametrization<ExactPoint>(5);
}

template <class P>
void along_omega() {
  using T = typename P::Coordinate;
  std::vector<std::pair<long, long>> ds;
  for (long x = -4; x <= 4; ++x)
    for (long y = -4; y <= 4; ++y)
      if (x != 0 || y != 0) ds.emplace_back(x, y);
  auto theta = [](long x, long y) {  // counter-clockwise from (1, 0), in [0, 2π)
    const double t = std::atan2(double(y), double(x));
    return t < 0 ? t + 2 * std::numbers::pi : t;
  };
  auto same = [](long x1, long y1, long x2, long y2) {
    const long g1 = std::gcd(x1, y1), g2 = std::gcd(x2, y2);
    return x1 / g1 == x2 / g2 && y1 / g1 == y2 / g2;
  };
  for (int sense : {1, -1}) {
    const BasicLine<T> l(T(sense), T(0), T(0));
    for (auto [x1, y1] : ds)
      for (auto [x2, y2] : ds) {
        Sign want = ZERO;
        if (!same(x1, y1, x2, y2)) {
          // Along -Omega the turn is clockwise: the angle measured is the mirror one.
          const double t1 = theta(x1, sense * y1), t2 = theta(x2, sense * y2);
          want = t1 < t2 ? NEGATIVE : POSITIVE;
        }
        ASSERT_EQ(compare_along_line(l, make<P>(0, x1, y1), make<P>(0, x2, y2)), want);
      }
  }
  EXPECT_THROW(compare_along_line(omega<T>(), make<P>(1, 0, 0), make<P>(0, 1, 0)), Undefined);
}

TEST(AlongLine, OmegaTurnsFromTheXAxis) {
  along_omega<Point>();
  along_omega<ExactPoint>();
}

}  // namespace
}  // namespace t2
