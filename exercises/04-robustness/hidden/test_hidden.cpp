// Exercise 04, hidden tests. Oracle: the determinant in exact rationals.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <t2/kernel/number.hpp>
#include <t2/kernel/point.hpp>

#include "exact_orient.hpp"

namespace {

using t2::Point;
using t2::Rational;

t2::Sign oracle(const Point& p, const Point& q, const Point& r) {
  auto R = [](double v) { return t2::to_rational(v); };
  const Rational a = R(p.w()), b = R(p.x()), c = R(p.y()), d = R(q.w()), e = R(q.x()), f = R(q.y()),
                 g = R(r.w()), h = R(r.x()), i = R(r.y());
  const Rational det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
  return static_cast<t2::Sign>(sgn(det));
}

TEST(Hidden, NearlyCollinearAgreesWithOracle) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-100, 100), t(0, 1);
  std::uniform_int_distribution<int> ulps(-2, 2);
  for (int i = 0; i < 2000; ++i) {
    const double px = u(rng), py = u(rng), qx = u(rng), qy = u(rng), s = t(rng);
    double rx = px + s * (qx - px);
    const double ry = py + s * (qy - py);
    for (int k = ulps(rng); k != 0; k += (k > 0 ? -1 : 1)) rx = std::nextafter(rx, k > 0 ? 1e9 : -1e9);
    const Point p(1, px, py), q(1, qx, qy), r(1, rx, ry);
    ASSERT_EQ(ex04::orient_exact(p, q, r), oracle(p, q, r))
        << t2::to_string(p) << " " << t2::to_string(q) << " " << t2::to_string(r);
  }
}

TEST(Hidden, TinyTrianglesAreNotCollinear) {
  const Point p(1, 0, 0), q(1, 1e-6, 0), r(1, 0, 1e-6);
  EXPECT_EQ(ex04::orient_exact(p, q, r), oracle(p, q, r));
  EXPECT_EQ(ex04::orient_exact(Point(1e-5, 0, 0), Point(1e-5, 1e-5, 0), Point(1e-5, 0, 1e-5)), t2::POSITIVE);
}

TEST(Hidden, HugeCoordinatesDoNotOverflow) {
  const Point p(1e300, 0, 0), q(1e300, 1e300, 0), r(1e300, 0, 1e300);
  EXPECT_EQ(ex04::orient_exact(p, q, r), t2::POSITIVE);
  EXPECT_EQ(ex04::orient_exact(Point(1, 1e200, 1e200), Point(1, -1e200, 1e200), Point(-1, 3e200, 1e200)),
            oracle(Point(1, 1e200, 1e200), Point(1, -1e200, 1e200), Point(-1, 3e200, 1e200)));
}

}  // namespace
