// Exercise 07b, hidden tests. Oracle: the brute force of farthest.hpp, every pair's squared
// distance as an exact rational with its rank in the order of T¹ (one side < +∞ < beyond
// infinity, where nearer as drawn is farther). Inputs: one side (front, and back, where the
// drawing is the antipodes'), both sides, points of Ω, and pairs whose distances differ by a few
// units in the last place of their coordinates, which squared distances in doubles cannot tell.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <t2/kernel/error.hpp>
#include <t2/kernel/point.hpp>

#include "diameter.hpp"
#include "farthest.hpp"

namespace {

using ex07btest::check;
using t2::Point;

double unit(std::mt19937_64& g) { return double(g() >> 11) * 0x1p-53; }

// n points of a side (w = ±1, ±2, ±0.5: the drawing does not depend on the scale).
std::vector<Point> side(std::mt19937_64& g, int n, double sign, double spread) {
  std::vector<Point> P;
  for (int k = 0; k < n; ++k) {
    const double s = sign * std::ldexp(1.0, static_cast<int>(g() % 3) - 1);
    P.push_back(Point(s, s * spread * unit(g), s * spread * unit(g)));
  }
  return P;
}

TEST(Hidden, OneSide) {
  std::mt19937_64 g(7);
  for (int round = 0; round < 12; ++round) {
    const std::vector<Point> P = side(g, 10 + 12 * round, round % 2 ? -1 : 1, 100);
    EXPECT_EQ(check(P, ex07b::diameter(P)), "") << "round " << round;
  }
  const std::vector<Point> same = {Point(1, 2, 3), Point(2, 4, 6), Point(0.5, 1, 1.5)};
  EXPECT_EQ(check(same, ex07b::diameter(same)), "") << "one point three times";
}

TEST(Hidden, BeyondInfinity) {
  std::mt19937_64 g(77);
  for (int round = 0; round < 16; ++round) {
    std::vector<Point> P = side(g, 5 + 8 * round, 1, 100);
    for (const Point& p : side(g, 1 + round % 7, -1, 100)) P.push_back(p);
    std::shuffle(P.begin(), P.end(), g);
    EXPECT_EQ(check(P, ex07b::diameter(P)), "") << "round " << round;
    if (round % 4 == 0) {  // a point and its antipode: the farthest of all
      P.push_back(t2::antipode(P[g() % P.size()]));
      EXPECT_EQ(check(P, ex07b::diameter(P)), "") << "antipodes, round " << round;
    }
  }
}

TEST(Hidden, PointsAtInfinity) {
  std::mt19937_64 g(777);
  for (int round = 0; round < 10; ++round) {
    std::vector<Point> P = side(g, 20, round % 2 ? -1 : 1, 100);
    P.push_back(Point(0, 3, -4));
    P.push_back(Point(0, 6, -8));  // the same point of Ω
    std::shuffle(P.begin(), P.end(), g);
    EXPECT_EQ(check(P, ex07b::diameter(P)), "") << "one side and Ω, round " << round;
    P.push_back(Point(-1, 5, 5));
    EXPECT_EQ(check(P, ex07b::diameter(P)), "") << "both sides and Ω, round " << round;
    P.push_back(Point(0, -3, 4));  // the antipode of the point of Ω: a different point of Ω
    EXPECT_THROW(ex07b::diameter(P), t2::Undefined) << "two points of Ω, round " << round;
  }
  EXPECT_EQ(check({Point(0, 1, 1), Point(0, 2, 2)}, ex07b::diameter({Point(0, 1, 1), Point(0, 2, 2)})), "");
}

// Two pairs whose squared distances agree to about 2⁻⁵⁰ relative: (±X, 0) and (0, −Y), (0, Y′)
// with Y, Y′ within a few units in the last place of X. In doubles the squares round to the
// same value; exactly, one pair is farther (or they tie). On one side, and beyond infinity.
TEST(Hidden, NearTies) {
  std::mt19937_64 g(7777);
  int differ = 0;
  for (int round = 0; round < 200; ++round) {
    const double X = 1e8 + static_cast<double>(g() % 1000);
    double Y = X, Y2 = X;
    for (int k = static_cast<int>(g() % 5); k > 0; --k) Y = std::nextafter(Y, 9e9);
    for (int k = static_cast<int>(g() % 5); k > 0; --k) Y2 = std::nextafter(Y2, 0);
    std::vector<Point> P = {Point::cartesian(-X, 0), Point::cartesian(X, 0), Point::cartesian(0, -Y),
                            Point::cartesian(0, Y2), Point::cartesian(1, 1)};
    differ += (Y + Y2 != 2 * X);
    if (round % 2) {  // the same beyond infinity: front (−X, 0), (L, −Y) and back points drawn at
                      // (X, 0), (L, Y′), L far away: the nearer of the two pairs as drawn is farther
      const double L = 1e12;
      P = {Point::cartesian(-X, 0), Point(-1, -X, 0), Point::cartesian(L, -Y), Point(-1, -L, -Y2)};
    }
    std::shuffle(P.begin(), P.end(), g);
    EXPECT_EQ(check(P, ex07b::diameter(P)), "") << "round " << round;
  }
  EXPECT_GT(differ, 50);
}

}  // namespace
