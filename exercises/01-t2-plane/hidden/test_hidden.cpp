// Exercise 01, hidden tests: the T² cases a Euclidean answer gets wrong. The oracle is exact
// rational arithmetic, independent of the student's code and of the library.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <t2/kernel/number.hpp>
#include <t2/kernel/point.hpp>

#include "classify.hpp"

namespace {

using ex01::Where;
using t2::Point;
using t2::Rational;

// +1 same point, -1 antipodes, 0 neither: exact, with rationals.
int oracle(const Point& p, const Point& q) {
  const Rational a[3] = {t2::to_rational(p.w()), t2::to_rational(p.x()), t2::to_rational(p.y())};
  const Rational b[3] = {t2::to_rational(q.w()), t2::to_rational(q.x()), t2::to_rational(q.y())};
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (a[i] * b[j] != a[j] * b[i]) return 0;
  const Rational d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  return sgn(d);
}

void expect_like_oracle(const Point& p, const Point& q) {
  const int o = oracle(p, q);
  EXPECT_EQ(ex01::same_point(p, q), o > 0) << t2::to_string(p) << " vs " << t2::to_string(q);
  EXPECT_EQ(ex01::antipodal(p, q), o < 0) << t2::to_string(p) << " vs " << t2::to_string(q);
}

TEST(Hidden, WhereOnOmega) {
  EXPECT_TRUE(ex01::where(Point(0, 1, 2)) == Where::infinity);
  EXPECT_TRUE(ex01::where(Point(0, -3, 0)) == Where::infinity);
  EXPECT_TRUE(ex01::where(Point(-1e-300, 1, 1)) == Where::back);
}

TEST(Hidden, EqualityOnTheBackSide) {
  expect_like_oracle(Point(-1, -2, -3), Point(-2, -4, -6));
  expect_like_oracle(Point(-1, -2, -3), Point(1, 2, 3));
  expect_like_oracle(Point(-4, 2, 8), Point(2, -1, -4));
  expect_like_oracle(Point(-4, 2, 8), Point(-2, 1, 4));
}

TEST(Hidden, EqualityAtInfinity) {
  expect_like_oracle(Point(0, 1, 2), Point(0, 2, 4));
  expect_like_oracle(Point(0, 1, 2), Point(0, -1, -2));
  expect_like_oracle(Point(0, 1, 0), Point(0, 1e-300, 0));
  expect_like_oracle(Point(0, 1, 2), Point(0, 1, 3));
}

TEST(Hidden, EqualityIsExactForDoubles) {
  // q = [fl(3x), x, 0] against p = [3, 1, 0]: the rounded cross product is 0, the exact one not.
  double x = 1;
  for (int i = 0; i < 40; ++i) {
    x = std::nextafter(x, 2.0);
    const Point p(3, 1, 0), q(3 * x, x, 0);
    expect_like_oracle(p, q);
    expect_like_oracle(p, t2::antipode(q));
  }
  // Exact scalings by powers of two keep the point.
  expect_like_oracle(Point(0.1, 0.2, 0.3), Point(0.1 * 1024, 0.2 * 1024, 0.3 * 1024));
  expect_like_oracle(Point(1e-300, 3e-300, 0), Point(1e-300 * 0x1p-40, 3e-300 * 0x1p-40, 0));
}

TEST(Hidden, RandomAgreesWithOracle) {
  std::mt19937_64 rng(2026);
  std::uniform_int_distribution<int> c(-3, 3), f(-4, 4);
  for (int i = 0; i < 3000; ++i) {
    const double w = c(rng), xx = c(rng), y = c(rng);
    if (w == 0 && xx == 0 && y == 0) continue;
    const Point p(w, xx, y);
    const int k = f(rng);
    const Point q = k != 0 && i % 2 ? Point(k * w, k * xx, k * y) : Point(c(rng) + 0.5, c(rng), c(rng));
    expect_like_oracle(p, q);
    if (HasFailure()) return;
  }
}

}  // namespace
