// Exercise 10b, hidden tests. Oracle: the exact certificate of certificate.hpp (a triangulation
// of the points tiling their hull, every point a vertex or equal to
// one, every interior edge locally Delaunay under the exact in-circle test). Inputs: random
// points; an integer grid (every unit square cocircular); copies equal in T², points on the
// lines of hull edges, all-collinear input; weights w != 1; nearly cocircular points whose
// in-circle signs are a few units in the last place. LargeRandom: 25 000 points, where locating
// by testing every triangle runs out of time (the certificate takes O(n log n) with a hull of a
// few hundred edges).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <t2/kernel/error.hpp>
#include <t2/kernel/point.hpp>

#include "certificate.hpp"
#include "incremental.hpp"

namespace {

using t2::Point;

double unit(std::mt19937_64& g) { return double(g() >> 11) * 0x1p-53; }

TEST(Hidden, RandomPoints) {
  std::mt19937_64 g(1010);
  for (int n : {200, 400}) {
    std::vector<Point> P;
    for (int k = 0; k < n; ++k) P.push_back(Point::cartesian(unit(g), unit(g)));
    EXPECT_EQ(ex10btest::check(P, ex10b::delaunay(P)), "") << n;
  }
}

// The grid {0..11}²: every unit square has four cocircular corners, and a flip on ">= 0" never ends.
TEST(Hidden, CocircularGrid) {
  std::vector<Point> P;
  for (int k = 0; k < 144; ++k) P.push_back(Point::cartesian(k % 12, k / 12));
  std::shuffle(P.begin(), P.end(), std::mt19937_64(12));
  EXPECT_EQ(ex10btest::check(P, ex10b::delaunay(P)), "");
}

TEST(Hidden, DuplicatesAndCollinear) {
  std::mt19937_64 g(1011);
  std::vector<Point> P;
  for (int k = 0; k < 30; ++k) P.push_back(Point::cartesian(k, 0));            // the hull's bottom edge
  for (int k = 0; k < 30; ++k) P.push_back(Point::cartesian(k / 2.0, k / 2.0));  // a diagonal
  for (int k = 0; k < 40; ++k) P.push_back(Point::cartesian(std::floor(30 * unit(g)), std::floor(15 * unit(g))));
  for (int k = 0; k < 40; k += 3) P.push_back(Point(4, 4 * P[k].x(), 4 * P[k].y()));  // equal in T²
  std::shuffle(P.begin(), P.end(), g);
  EXPECT_EQ(ex10btest::check(P, ex10b::delaunay(P)), "");
  std::vector<Point> L;
  for (int k = 0; k < 10; ++k) L.push_back(Point(2, 2.0 * k, 6.0 * k));
  L.push_back(L[3]);
  EXPECT_THROW(ex10b::delaunay(L), t2::Undefined);
}

TEST(Hidden, Homogeneous) {
  std::mt19937_64 g(1012);
  const double w[] = {0.5, 2, 3, 7, 1e-3, 1e3};
  std::vector<Point> P;
  for (int k = 0; k < 150; ++k) {
    const double s = w[g() % 6];
    P.push_back(Point(s, s * unit(g), s * unit(g)));
  }
  EXPECT_EQ(ex10btest::check(P, ex10b::delaunay(P)), "");
}

// Points of the unit circle ((1 - t²)/(1 + t²), 2t/(1 + t²)), rounded to doubles: every in-circle
// sign that decides their triangulation is a few units in the last place.
TEST(Hidden, NearlyCocircular) {
  for (int m : {60, 150}) {
    std::vector<Point> P;
    for (int k = -m; k <= m; ++k) {
      const double t = double(k) / m, d = 1 + t * t;
      P.push_back(Point::cartesian((1 - t * t) / d, 2 * t / d));
      if (k != -m && k != m) P.push_back(Point::cartesian(-(1 - t * t) / d, 2 * t / d));
    }
    EXPECT_EQ(ex10btest::check(P, ex10b::delaunay(P)), "") << m;
  }
}

// 25 000 points: random in the unit square at weights 1, 2, 0.5 and 3 (the last rounded: points
// near, not on, the drawn ones), 20 on the bottom edge, the two bottom corners, and 1 500 copies
// at weight 4 (equal in T²), shuffled.
TEST(Hidden, LargeRandom) {
  std::mt19937_64 g(1013);
  const double w[] = {1, 2, 0.5, 3};
  std::vector<Point> P = {Point::cartesian(0, 0), Point::cartesian(1, 0)};
  for (int k = 0; k < 20; ++k) P.push_back(Point::cartesian(unit(g), 0));
  for (int k = 0; k < 23480; ++k) {
    const double s = w[g() % 4];
    P.push_back(Point(s, s * unit(g), s * unit(g)));
  }
  for (int k = 0; k < 1500; ++k) {
    const Point p = P[g() % P.size()];
    P.push_back(Point(4 * p.w(), 4 * p.x(), 4 * p.y()));
  }
  std::shuffle(P.begin(), P.end(), g);
  EXPECT_EQ(ex10btest::check(P, ex10b::delaunay(P)), "");
}

}  // namespace
