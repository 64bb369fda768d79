// Exercise 02, hidden tests. Oracle: exact rational solution of r = αp + βq.
#include <gtest/gtest.h>

#include <random>

#include <t2/error.hpp>
#include <t2/number.hpp>
#include <t2/point.hpp>

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

TEST(Hidden, UndefinedForEqualOrAntipodalEnds) {
  EXPECT_THROW(ex02::shape(Point(-1, 2, 3), Point(1, -2, -3)), t2::Undefined);
  EXPECT_THROW(ex02::shape(Point(0, 1, 2), Point(0, -2, -4)), t2::Undefined);
  EXPECT_THROW(ex02::shape(Point(2, 2, 2), Point(1, 1, 1)), t2::Undefined);
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

}  // namespace
