// Exercise 07b, hidden tests. Oracle: the brute force of farthest.hpp, every pair's squared
// distance as an exact rational with its rank in the order of T¹ (one side < +∞ < beyond
// infinity, where nearer as drawn is farther). Inputs: one side (front, and back, where the
// drawing is the antipodes'), both sides, points of Ω, and pairs whose distances differ by a few
// units in the last place of their coordinates, which squared distances in doubles cannot tell.
// LargeHull: 20 000 points, 10 000 of them on their hull, where the brute force (every pair) runs
// out of time; its oracle is no brute force but a certificate (below).
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

// Two points A = (a, b), B = −A and 20 000 others strictly inside the circle with diameter AB
// (checked exactly: |p|² < |A|²): every other pair is nearer than A and B, so {A, B} (or a copy of
// A or B at another scale) is the farthest pair of one side. 10 000 points are rounded from a
// circle of radius 0.999·|A| ≈ 10⁹, hence on the hull; 9 000 are inside, 1 000 are copies at
// another scale; each point at a scale ±1, ±2 or ±0.5. Rounds: front; back; front with a point
// of Ω (+∞: any proper point with it).
TEST(Hidden, LargeHull) {
  std::mt19937_64 g(70000007);
  const double pi = std::acos(-1.0);
  for (int round = 0; round < 3; ++round) {
    const double a = std::round(6e8 + 1e8 * unit(g)), b = std::round(7e8 + 1e8 * unit(g));
    const t2::Integer A2 = t2::Integer(a) * t2::Integer(a) + t2::Integer(b) * t2::Integer(b);
    const double r = 0.999 * std::sqrt(a * a + b * b), phase = unit(g);
    std::vector<Point> P = {Point(1, a, b), Point(1, -a, -b)};
    for (int k = 0; k < 10000; ++k) {
      const double t = 2 * pi * (k + phase) / 10000;
      P.push_back(Point(1, std::round(r * std::cos(t)), std::round(r * std::sin(t))));
    }
    for (int k = 0; k < 9000; ++k) P.push_back(Point(1, std::round(r * (unit(g) - 0.5)), std::round(r * (unit(g) - 0.5))));
    for (std::size_t k = 2; k < P.size(); ++k) {
      const t2::Integer x(P[k].x()), y(P[k].y());
      ASSERT_TRUE(x * x + y * y < A2) << "the test's construction";
    }
    for (int k = 0; k < 1000; ++k) P.push_back(P[g() % P.size()]);
    const double sign = round == 1 ? -1 : 1;
    for (std::size_t k = 0; k < P.size(); ++k) {
      const double s = sign * std::ldexp(1.0, static_cast<int>(g() % 3) - 1) * (k >= 19002 ? 3 : 1);
      P[k] = Point(s, s * P[k].x(), s * P[k].y());
    }
    const Point A = P[0], B = P[1];
    if (round == 2) P.push_back(Point(0, 3, -4));
    std::shuffle(P.begin(), P.end(), g);
    const std::vector<long> got = ex07b::diameter(P);
    ASSERT_EQ(got.size(), 2u) << "round " << round;
    ASSERT_TRUE(got[0] >= 0 && got[0] < long(P.size()) && got[1] >= 0 && got[1] < long(P.size())) << "round " << round;
    const auto D = ex07btest::drawn({P[got[0]], P[got[1]], A, B});
    const auto want = round == 2 ? std::pair<int, t2::Rational>{1, 0} : *ex07btest::key(D[2], D[3]);
    EXPECT_TRUE(ex07btest::key(D[0], D[1]) == want) << "round " << round << ": p" << got[0] << " p" << got[1]
                                                    << " is not a farthest pair";
  }
}

}  // namespace
