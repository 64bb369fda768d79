// Exercise 03b, hidden tests. Oracle: Cartesian coordinates and cosines in exact rationals
// (cos² with its sign, compared as rationals).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <t2/kernel/number.hpp>
#include <t2/kernel/point.hpp>

#include "angles.hpp"

namespace {

using t2::Point;
using t2::Rational;

// The signed square of cos ∠abc: sign(cos)·cos².
Rational signed_cos2(const Point& a, const Point& b, const Point& c) {
  auto X = [](const Point& p) -> Rational { return t2::to_rational(p.x()) / t2::to_rational(p.w()); };
  auto Y = [](const Point& p) -> Rational { return t2::to_rational(p.y()) / t2::to_rational(p.w()); };
  const Rational ux = X(a) - X(b), uy = Y(a) - Y(b), vx = X(c) - X(b), vy = Y(c) - Y(b);
  const Rational dot = ux * vx + uy * vy;
  const Rational r = dot * dot / ((ux * ux + uy * uy) * (vx * vx + vy * vy));
  return dot < 0 ? Rational(-r) : r;
}

int oracle(const Point& a, const Point& b, const Point& c, const Point& d, const Point& e, const Point& f) {
  return -sgn(Rational(signed_cos2(a, b, c) - signed_cos2(d, e, f)));  // larger cosine, smaller angle
}

void check(const Point& a, const Point& b, const Point& c, const Point& d, const Point& e, const Point& f) {
  ASSERT_EQ(static_cast<int>(ex03b::compare_angles(a, b, c, d, e, f)), oracle(a, b, c, d, e, f))
      << t2::to_string(a) << t2::to_string(b) << t2::to_string(c) << " vs " << t2::to_string(d)
      << t2::to_string(e) << t2::to_string(f);
}

bool same_place(const Point& p, const Point& q) { return p.x() * q.w() == q.x() * p.w() && p.y() * q.w() == q.y() * p.w(); }

Point random_point(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> c(-5, 5), w(1, 3);
  const double k = w(rng);
  return Point(k, k * c(rng), k * c(rng));
}

TEST(Hidden, AgreesWithOracle) {
  std::mt19937_64 rng(21);
  for (int i = 0; i < 3000; ++i) {
    const Point a = random_point(rng), b = random_point(rng), c = random_point(rng);
    const Point d = random_point(rng), e = random_point(rng), f = random_point(rng);
    if (same_place(a, b) || same_place(c, b) || same_place(d, e) || same_place(f, e)) continue;
    check(a, b, c, d, e, f);
  }
}

TEST(Hidden, CongruentAnglesAreEqual) {
  // The rotation by the angle with cos 4/5, sin 3/5, a translation and a different positive
  // weight for each point: [w, x, y] -> k·[5w, 4x − 3y + 5w·tx, 3x + 4y + 5w·ty].
  std::mt19937_64 rng(23);
  std::uniform_int_distribution<int> t(-3, 3), k(1, 7);
  auto move = [&](const Point& p, int tx, int ty) {
    const double s = k(rng);
    return Point(s * 5 * p.w(), s * (4 * p.x() - 3 * p.y() + 5 * p.w() * tx), s * (3 * p.x() + 4 * p.y() + 5 * p.w() * ty));
  };
  for (int i = 0; i < 2000; ++i) {
    const Point a = random_point(rng), b = random_point(rng), c = random_point(rng);
    if (same_place(a, b) || same_place(c, b)) continue;
    const int tx = t(rng), ty = t(rng);
    const Point d = move(a, tx, ty), e = move(b, tx, ty), f = move(c, tx, ty);
    ASSERT_EQ(ex03b::compare_angles(a, b, c, d, e, f), t2::ZERO) << t2::to_string(a) << t2::to_string(b) << t2::to_string(c);
    ASSERT_EQ(ex03b::compare_angles(c, b, a, d, e, f), t2::ZERO);
  }
}

TEST(Hidden, ObtuseAgainstAcute) {
  const Point o(1, 0, 0), x(1, 1, 0);
  check(x, o, Point(1, -1, 1), x, o, Point(1, 1, 1));    // 135° vs 45°
  check(x, o, Point(2, 1, 0), x, o, Point(1, -1, 0));    // 0° vs 180°
  check(x, o, Point(1, 0, 1), x, o, Point(1, -1, 2));    // 90° vs obtuse
}

TEST(Hidden, NearlyEqualAngles) {
  // The second angle is the first one moved by a few ulps of one coordinate.
  std::mt19937_64 rng(25);
  std::uniform_real_distribution<double> u(-10, 10);
  std::uniform_int_distribution<int> ulps(-2, 2);
  for (int i = 0; i < 2000; ++i) {
    const Point a(1, u(rng), u(rng)), b(1, u(rng), u(rng)), c(1, u(rng), u(rng));
    double cx = c.x();
    for (int k = ulps(rng); k != 0; k += k > 0 ? -1 : 1) cx = std::nextafter(cx, k > 0 ? 100.0 : -100.0);
    check(a, b, c, a, b, Point(1, cx, c.y()));
    check(a, b, c, Point(3, 3 * a.x(), 3 * a.y()), b, c);  // the same angle, a weighted 3 (exact)
  }
}

}  // namespace
