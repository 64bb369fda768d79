// Exercise 07, hidden tests. Oracle: strip.hpp — the answer's strip checked exactly (its first
// line a side with every point on one side of it, every point of Ω on it, no point beyond the
// parallel through the third), and its squared width, an exact rational, against the least over
// every candidate strip by brute force. Inputs: one side (front, and back, drawn at the
// antipodes' places), repeated points at another scale, a direction at infinity that fixes the
// strip (with both of its ends ±d), sets that no strip holds, and two strips whose widths differ
// by a few units in the last place.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <t2/kernel/error.hpp>
#include <t2/kernel/point.hpp>

#include "strip.hpp"
#include "width.hpp"

namespace {

using ex07test::check;
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

}  // namespace
