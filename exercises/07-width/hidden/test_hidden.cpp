// Exercise 07, hidden tests. Oracle: strip.hpp — the answer's strip checked exactly (its first
// line a side with every point on one side of it, every point of Ω on it, no point beyond the
// parallel through the third), and its squared width, an exact rational, against the least over
// every candidate strip by brute force. Inputs: one side (front, and back, drawn at the
// antipodes' places), repeated points at another scale, a direction at infinity that fixes the
// strip (with both of its ends ±d), sets that no strip holds, and two strips whose widths differ
// by a few units in the last place. LargeHull: 20 000 points, half of them vertices of their
// hull, where the brute force (O(n²) lines) runs out of time; its oracle is no brute force but a
// certificate on the hull, which is known by construction (below).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <random>

#include <t2/kernel/error.hpp>
#include <t2/kernel/point.hpp>

#include "strip.hpp"
#include "width.hpp"

namespace {

using ex07test::check;
using t2::Integer;
using t2::Point;

double unit(std::mt19937_64& g) { return double(g() >> 11) * 0x1p-53; }

// n points of a side, scaled by ±1, ±2 or ±0.5 (the same drawing).
std::vector<Point> side(std::mt19937_64& g, int n, double sign) {
  std::vector<Point> P;
  for (int k = 0; k < n; ++k) {
    const double s = sign * std::ldexp(1.0, static_cast<int>(g() % 3) - 1);
    P.push_back(Point(s, s * 100 * unit(g), s * 60 * unit(g)));
  }
  return P;
}

TEST(Hidden, OneSide) {
  std::mt19937_64 g(70);
  for (int round = 0; round < 16; ++round) {
    const std::vector<Point> P = side(g, 4 + 3 * round, round % 2 ? -1 : 1);
    EXPECT_EQ(check(P, ex07::width(P)), "") << "round " << round;
  }
}

TEST(Hidden, RepeatedPoints) {
  std::mt19937_64 g(707);
  for (int round = 0; round < 12; ++round) {
    std::vector<Point> P = side(g, 5 + 2 * round, round % 2 ? -1 : 1);
    for (int k = 0; k < 4; ++k) {
      const Point& p = P[g() % P.size()];
      P.push_back(Point(3 * p.w(), 3 * p.x(), 3 * p.y()));  // the same point, scaled
    }
    std::shuffle(P.begin(), P.end(), g);
    EXPECT_EQ(check(P, ex07::width(P)), "") << "round " << round;
  }
}

TEST(Hidden, DirectionAtInfinity) {
  std::mt19937_64 g(7007);
  for (int round = 0; round < 12; ++round) {
    std::vector<Point> P = side(g, 6 + 2 * round, round % 2 ? -1 : 1);
    const double dx = static_cast<double>(g() % 7) - 3, dy = static_cast<double>(g() % 5) + 1;
    P.push_back(Point(0, dx, dy));
    if (round % 3 == 0) P.push_back(Point(0, -2 * dx, -2 * dy));  // the strip's other end
    std::shuffle(P.begin(), P.end(), g);
    EXPECT_EQ(check(P, ex07::width(P)), "") << "round " << round;
  }
}

TEST(Hidden, NoStrip) {
  std::mt19937_64 g(70007);
  for (int round = 0; round < 10; ++round) {
    std::vector<Point> P = side(g, 8, 1);
    EXPECT_EQ(check(P, ex07::width(P)), "") << "before the last points, round " << round;
    if (round % 2) {
      P.push_back(side(g, 1, -1)[0]);  // one back point
    } else {
      P.push_back(Point(0, 1, 2));
      P.push_back(Point(0, 2, 1));  // two directions at infinity
    }
    std::shuffle(P.begin(), P.end(), g);
    EXPECT_THROW(ex07::width(P), t2::Undefined) << "round " << round;
  }
}

// A quadrilateral (0,0), (X,0), (X,Y), (0,X) far from the origin's scale (X ≈ 10⁸) with Y a
// few units in the last place from X: the strips along the bottom, the left and the top edge
// have widths that agree to about 2⁻⁵⁰ relative, and only exact arithmetic orders them.
TEST(Hidden, NearTies) {
  std::mt19937_64 g(700007);
  for (int round = 0; round < 60; ++round) {
    const double X = 1e8 + static_cast<double>(g() % 1000);
    double Y = X;
    for (int k = static_cast<int>(g() % 7) - 3; k != 0; k += k > 0 ? -1 : 1) Y = std::nextafter(Y, k > 0 ? 9e9 : 0);
    std::vector<Point> P = {Point::cartesian(0, 0), Point::cartesian(X, 0), Point::cartesian(X, Y),
                            Point::cartesian(0, X)};
    if (round % 2)
      for (Point& p : P) p = Point(-1, -p.x(), -p.y());  // the same on the back
    std::shuffle(P.begin(), P.end(), g);
    EXPECT_EQ(check(P, ex07::width(P)), "") << "round " << round;
  }
}

// The least squared width of the strictly convex polygon H (integer vertices, counter-clockwise):
// for each edge a vertex at least as far from its line as both its neighbours, which on a strictly
// convex polygon is a farthest one (the distances along the polygon rise, then fall).
t2::Rational least_width(const std::vector<std::array<Integer, 2>>& H) {
  const std::size_t h = H.size();
  const auto at = [&](std::size_t i) -> const std::array<Integer, 2>& { return H[i % h]; };
  std::optional<t2::Rational> least;
  std::size_t j = 1;
  for (std::size_t i = 0; i < h; ++i) {
    const auto &a = at(i), &b = at(i + 1);
    const auto height = [&](std::size_t v) -> Integer {  // twice the area of a, b, v: |ab| times the distance
      return (b[0] - a[0]) * (at(v)[1] - a[1]) - (b[1] - a[1]) * (at(v)[0] - a[0]);
    };
    j = std::max(j, i + 1);
    while (height(j + 1) > height(j)) ++j;
    EXPECT_TRUE(height(j) >= height(j - 1) && height(j) >= height(j + 1) && height(j) > 0) << "the test's certificate";
    const t2::Rational w = t2::Rational(height(j) * height(j)) /
                           t2::Rational((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]));
    if (!least || w < *least) least = w;
  }
  return *least;
}

// h integer points rounded from a circle of radius 10⁹ (a strictly convex polygon, checked: every
// turn strictly left, every edge farther than 0.9·10⁹ from the centre) and m points in the square
// |x|, |y| ≤ 0.6·10⁹, inside the disk of radius 0.85·10⁹, hence strictly inside the polygon; each
// point at a scale ±1, ±2 or ±0.5, and some vertices repeated at another.
TEST(Hidden, LargeHull) {
  std::mt19937_64 g(7000007);
  const double R = 1e9, pi = std::acos(-1.0);
  for (int round = 0; round < 2; ++round) {
    const int h = 10000, m = 9000;
    std::vector<std::array<Integer, 2>> H;
    std::vector<Point> P;
    const double phase = unit(g);
    for (int k = 0; k < h; ++k) {
      const double t = 2 * pi * (k + phase) / h, x = std::round(R * std::cos(t)), y = std::round(R * std::sin(t));
      H.push_back({Integer(x), Integer(y)});
      P.push_back(Point(1, x, y));
    }
    for (int k = 0; k < h; ++k) {
      const auto &a = H[k], &b = H[(k + 1) % h], &c = H[(k + 2) % h];
      ASSERT_TRUE((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) > 0) << "the test's construction";
      const Integer twice = a[0] * b[1] - a[1] * b[0], len2 = (b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]);
      ASSERT_TRUE(twice * twice * 100 > len2 * 81 * Integer(1000000000) * Integer(1000000000)) << "the test's construction";
    }
    for (int k = 0; k < m; ++k) P.push_back(Point(1, std::round(1.2 * R * (unit(g) - 0.5)), std::round(1.2 * R * (unit(g) - 0.5))));
    for (int k = 0; k < 1000; ++k) P.push_back(P[g() % h]);
    const double sign = round % 2 ? -1 : 1;
    for (std::size_t k = 0; k < P.size(); ++k) {
      const double s = sign * std::ldexp(1.0, static_cast<int>(g() % 3) - 1) * (k >= std::size_t(h + m) ? 3 : 1);
      P[k] = Point(s, s * P[k].x(), s * P[k].y());
    }
    std::shuffle(P.begin(), P.end(), g);
    EXPECT_EQ(ex07test::judge(P, ex07::width(P), least_width(H)), "") << "round " << round;
  }
}

}  // namespace
