// Angles as points of Ω (§4.3.7): compare_angle against atan2 by brute force on every small
// integer direction, the seed's Algorithm 1 as printed failing exactly where angle.hpp says, and
// the angular difference ^− checked as a rotation.
//
// Why atan2 is a trustworthy oracle here: two distinct directions (x1, y1), (x2, y2) with integer
// coordinates of absolute value at most N make an angle whose sine is |x1 y2 - x2 y1| / (|d1||d2|)
// >= 1 / (2 N²), i.e. at least 1/(2N²) radians ≈ 0.0139 for N = 6, while std::atan2 on small
// integers is accurate to a few units in the last place (~1e-15). Equal directions are decided
// exactly instead, by reducing each vector to its primitive form (divide by the gcd).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <numeric>
#include <random>
#include <vector>

#include "t2/kernel/angle.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

using testing::scale;

struct Dir {
  long x, y;
  double theta() const {  // in [0, 2π)
    const double t = std::atan2(double(y), double(x));
    return t < 0 ? t + 2 * std::numbers::pi : t;
  }
  std::pair<long, long> primitive() const {
    const long g = std::gcd(x, y);
    return {x / g, y / g};
  }
};

std::vector<Dir> small_directions(long n) {
  std::vector<Dir> out;
  for (long x = -n; x <= n; ++x)
    for (long y = -n; y <= n; ++y)
      if (x != 0 || y != 0) out.push_back({x, y});
  return out;
}

Sign atan2_oracle(const Dir& p, const Dir& q) {
  if (p.primitive() == q.primitive()) return ZERO;
  return p.theta() < q.theta() ? NEGATIVE : POSITIVE;
}

template <class P>
P make_point(long w, long x, long y) {
  using T = typename P::Coordinate;
  return P(T(w), T(x), T(y));
}

template <class P>
P dir(const Dir& d) {
  using T = typename P::Coordinate;
  return P(T(0), T(d.x), T(d.y));
}

template <class P>
void brute_force_against_atan2() {
  const auto ds = small_directions(6);
  for (const Dir& a : ds)
    for (const Dir& b : ds)
      ASSERT_EQ(compare_angle(dir<P>(a), dir<P>(b)), atan2_oracle(a, b)) << a.x << ',' << a.y << ' ' << b.x << ',' << b.y;
}

TEST(CompareAngle, MatchesAtan2OnEverySmallDirection) {
  brute_force_against_atan2<Point>();
  brute_force_against_atan2<ExactPoint>();
}

TEST(CompareAngle, DoublesAgreeWithTheSameIntegerPoints) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> e(-200, 200), pick(0, 3);
  for (int i = 0; i < 5000 * scale(); ++i) {
    const double s = std::ldexp(1.0, e(rng));
    double px = u(rng) * s, py = u(rng) * s, qx = u(rng), qy = u(rng);
    switch (pick(rng)) {  // also exactly parallel, antiparallel and axis directions
      case 0: qx = 3 * px; qy = 3 * py; break;
      case 1: qx = -px; qy = -py; break;
      case 2: py = 0; break;
      default: break;
    }
    const Point p(0, px, py), q(0, qx, qy);
    ASSERT_EQ(compare_angle(p, q), compare_angle(to_exact(p), to_exact(q)));
    ASSERT_EQ(compare_angle(q, p), -compare_angle(p, q));
  }
}

TEST(CompareAngle, RejectsProperPoints) {
  EXPECT_THROW(compare_angle(Point(1, 0, 0), Point(0, 1, 0)), Undefined);
}

Rational to_rational_any(const double& v) { return to_rational(v); }
Rational to_rational_any(const Integer& v) { return Rational(v); }

template <class P>
void difference_is_a_rotation() {
  const auto ds = small_directions(4);
  for (const Dir& a : ds)
    for (const Dir& b : ds) {
      const P r = angle_difference(dir<P>(a), dir<P>(b));
      ASSERT_TRUE(is_at_infinity(r));
      // Rotating b by r must give a, which fixes r up to a positive factor:
      // (b.x + i b.y)(r.x + i r.y) is a positive multiple of a.x + i a.y.
      const Rational rx = to_rational_any(r.x()), ry = to_rational_any(r.y());
      const Rational zx = b.x * rx - b.y * ry, zy = b.x * ry + b.y * rx;
      ASSERT_EQ(zx * a.y - zy * a.x, 0);
      ASSERT_GT(zx * a.x + zy * a.y, 0);
    }
}

TEST(AngleDifference, RotatesTheSecondDirectionOntoTheFirst) {
  difference_is_a_rotation<Point>();
  difference_is_a_rotation<ExactPoint>();
  EXPECT_THROW(angle_difference(Point(1, 0, 0), Point(0, 1, 0)), Undefined);
  EXPECT_THROW(angle_difference(ExactPoint(0, 1, 0), ExactPoint(2, 1, 0)), Undefined);
}

template <class P>
void angle_of_three_points(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<long> u(-9, 9), w(1, 3);
  for (int i = 0; i < 3000 * scale(); ++i) {
    const long qw = w(rng), qx = u(rng), qy = u(rng);
    const P p = make_point<P>(w(rng), u(rng), u(rng)), q = make_point<P>(qw, qx, qy), r = make_point<P>(w(rng), u(rng), u(rng));
    if (p == q || r == q) {
      ASSERT_THROW(angle(p, q, r), Undefined);
      continue;
    }
    const P a = angle(p, q, r);
    ASSERT_TRUE(is_at_infinity(a));
    // Oracle: the rotation taking R - Q onto P - Q, in exact rationals.
    auto pos = [](const P& v) {
      return std::pair<Rational, Rational>{to_rational_any(v.x()) / to_rational_any(v.w()),
                                           to_rational_any(v.y()) / to_rational_any(v.w())};
    };
    const auto [px, py] = pos(p);
    const auto [qqx, qqy] = pos(q);
    const auto [rx, ry] = pos(r);
    const Rational ux = rx - qqx, uy = ry - qqy, vx = px - qqx, vy = py - qqy;
    const Rational ax = to_rational_any(a.x()), ay = to_rational_any(a.y());
    const Rational zx = ux * ax - uy * ay, zy = ux * ay + uy * ax;  // (R - Q) rotated by a
    ASSERT_EQ(zx * vy - zy * vx, 0);
    ASSERT_GT(zx * vx + zy * vy, 0);
    // The back copy of the figure has the same angle; seen from a point at infinity it is zero.
    ASSERT_TRUE(angle(antipode(p), antipode(q), antipode(r)) == a);
    ASSERT_EQ(compare_angle(angle(p, make_point<P>(0, qx | 1, qy), r), make_point<P>(0, 1, 0)), ZERO);
  }
  EXPECT_THROW(angle(make_point<P>(1, 0, 0), make_point<P>(1, 1, 1), make_point<P>(-1, -1, -1)), Undefined);
}

TEST(Angle, OfThreePointsRotatesQrOntoQp) {
  angle_of_three_points<Point>(2);
  angle_of_three_points<ExactPoint>(3);
}

}  // namespace
}  // namespace t2
