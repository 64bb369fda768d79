// Exercise 02, hidden tests. Oracle: exact rational solution of r = αp + βq.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>

#include <t2/kernel/error.hpp>
#include <t2/kernel/number.hpp>
#include <t2/kernel/point.hpp>

#include "segments.hpp"

namespace {

using ex02::Shape;
using t2::Point;
using t2::Rational;

bool oracle_contains(const Point& p, const Point& q, const Point& r) {
  const Rational a[3] = {t2::to_rational(p.w()), t2::to_rational(p.x()), t2::to_rational(p.y())};
  const Rational b[3] = {t2::to_rational(q.w()), t2::to_rational(q.x()), t2::to_rational(q.y())};
  const Rational c[3] = {t2::to_rational(r.w()), t2::to_rational(r.x()), t2::to_rational(r.y())};
  const Rational det = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                       a[2] * (b[0] * c[1] - b[1] * c[0]);
  if (det != 0) return false;
  bool parallel = true;
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) parallel = parallel && a[i] * b[j] == a[j] * b[i];
  if (parallel) {  // p = q (the caller never passes q = ¬p): the one-point segment {p}
    for (int i = 0; i < 3; ++i)
      for (int j = i + 1; j < 3; ++j)
        if (a[i] * c[j] != a[j] * c[i]) return false;
    return a[0] * c[0] + a[1] * c[1] + a[2] * c[2] > 0;
  }
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) {
      const Rational m = a[i] * b[j] - a[j] * b[i];
      if (m == 0) continue;
      const Rational alpha = (c[i] * b[j] - c[j] * b[i]) / m, beta = (a[i] * c[j] - a[j] * c[i]) / m;
      return alpha >= 0 && beta >= 0;
    }
  ADD_FAILURE() << "test bug: p and q are parallel";
  return false;
}

TEST(Hidden, ShapeWithPointsAtInfinity) {
  EXPECT_TRUE(ex02::shape(Point(0, 1, 0), Point(1, 2, 3)) == Shape::ray_front);
  EXPECT_TRUE(ex02::shape(Point(-1, 2, 3), Point(0, 1, 0)) == Shape::ray_back);
  EXPECT_TRUE(ex02::shape(Point(0, 1, 0), Point(0, 0, 1)) == Shape::at_infinity);
}

TEST(Hidden, UndefinedForAntipodalEnds) {
  EXPECT_THROW(ex02::shape(Point(-1, 2, 3), Point(1, -2, -3)), t2::Undefined);
  EXPECT_THROW(ex02::shape(Point(0, 1, 2), Point(0, -2, -4)), t2::Undefined);
  // ... and only then: a positive multiple is the point itself, a nearly antipodal end is fine.
  EXPECT_TRUE(ex02::shape(Point(-1, 2, 3), Point(-2, 4, 6)) == Shape::point);
  EXPECT_TRUE(ex02::shape(Point(0, 1, 2), Point(0, -2, -3)) == Shape::at_infinity);
}

TEST(Hidden, OnePointSegments) {
  // p = q is allowed (chapter 02): the segment is {p}, on whichever side p is.
  for (const auto& [p, q] : {std::pair{Point(2, 2, 2), Point(1, 1, 1)}, {Point(-1, 3, 0), Point(-2, 6, 0)},
                             {Point(0, 1, 2), Point(0, 3, 6)}}) {
    EXPECT_TRUE(ex02::shape(p, q) == Shape::point) << t2::to_string(p);
    for (const Point& r : {p, Point(3 * p.w(), 3 * p.x(), 3 * p.y()), Point(-p.w(), -p.x(), -p.y()),
                           Point(p.w() + 1, p.x(), p.y()), Point(1, 0, 0)})
      EXPECT_EQ(ex02::contains(p, q, r), oracle_contains(p, q, r)) << t2::to_string(p) << " " << t2::to_string(r);
  }
}

TEST(Hidden, ContainsAcrossInfinity) {
  // p at the origin of the front, q the back point over (1, 0): the segment is the front ray to
  // the left of the origin, the point at infinity [0,-1,0], and the back ray right of (1, 0).
  const Point p(1, 0, 0), q(-1, -1, 0);
  for (const Point& r : {Point(1, -5, 0), Point(1, 0.5, 0), Point(0, -1, 0), Point(0, 1, 0),
                         Point(-1, -5, 0), Point(-2, -1, 0), Point(1, 5, 0), Point(-1, 5, 0)})
    EXPECT_EQ(ex02::contains(p, q, r), oracle_contains(p, q, r)) << t2::to_string(r);
}

TEST(Hidden, ContainsAgreesWithOracle) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> c(-4, 4);
  for (int i = 0; i < 3000; ++i) {
    const Point p(c(rng), c(rng), c(rng) + 0.5), q(c(rng) + 0.5, c(rng), c(rng));
    const double a = c(rng), b = c(rng);
    const double rw = a * p.w() + b * q.w(), rx = a * p.x() + b * q.x(), ry = a * p.y() + b * q.y();
    if (rw == 0 && rx == 0 && ry == 0) continue;
    const Point r(rw, rx, ry);
    ASSERT_EQ(ex02::contains(p, q, r), oracle_contains(p, q, r))
        << t2::to_string(p) << " " << t2::to_string(q) << " " << t2::to_string(r);
  }
}

TEST(Hidden, NearlyOnTheLineIsExact) {
  // r is the double nearest to a point of the line of p and q, then moved a few units in the
  // last place: mostly just off the line, sometimes exactly on it. Only exact signs tell.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1), t(-0.5, 1.5);
  std::uniform_int_distribution<int> ulps(-3, 3);
  for (int i = 0; i < 400; ++i) {
    const Point p(1, 0.1 + u(rng), 0.3 + u(rng)), q(1, 7.3 + u(rng), 12.9 + u(rng));
    const double s = t(rng);
    double x = p.x() + s * (q.x() - p.x()), y = p.y() + s * (q.y() - p.y());
    for (int k = ulps(rng); k != 0; k += k > 0 ? -1 : 1) x = std::nextafter(x, k > 0 ? 10.0 : -10.0);
    for (int k = ulps(rng); k != 0; k += k > 0 ? -1 : 1) y = std::nextafter(y, k > 0 ? 20.0 : -20.0);
    const double w = i % 2 ? 1.0 : -1.0;  // half of them: the antipodal query, never on the segment
    const Point r(w, w * x, w * y);
    ASSERT_EQ(ex02::contains(p, q, r), oracle_contains(p, q, r))
        << t2::to_string(p) << " " << t2::to_string(q) << " " << t2::to_string(r);
  }
}

}  // namespace
