// Exercise 10, hidden tests. Oracle: the exact certificate of certificate.hpp (the same points
// and hull, the triangles tiling it with exact rational areas, every interior edge locally
// Delaunay under the exact in-circle test). Inputs: the sweep triangulation (a monotone-chain
// triangulation written here with the exact t2::orient), a double fan between two rows that
// needs a cascade of flips, the seed's max-min height counterexample, and nearly cocircular
// points whose in-circle signs are a few units in the last place.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include <t2/kernel/lexicographic.hpp>
#include <t2/kernel/orient.hpp>
#include <t2/kernel/point.hpp>

#include "certificate.hpp"
#include "lawson.hpp"

namespace {

using t2::Point;

// The sweep: points sorted by (x, y); each new point is joined to the lower and the upper chain.
std::vector<long> sweep(const std::vector<Point>& P) {
  std::vector<long> idx(P.size());
  std::iota(idx.begin(), idx.end(), 0L);
  std::sort(idx.begin(), idx.end(), [&](long a, long b) { return t2::compare_xy(P[a], P[b]) < 0; });
  std::vector<long> lower, upper, T;
  for (long p : idx) {
    while (lower.size() >= 2 && t2::orient(P[lower[lower.size() - 2]], P[lower.back()], P[p]) < 0) {
      T.insert(T.end(), {lower[lower.size() - 2], p, lower.back()});
      lower.pop_back();
    }
    while (upper.size() >= 2 && t2::orient(P[upper[upper.size() - 2]], P[upper.back()], P[p]) > 0) {
      T.insert(T.end(), {upper[upper.size() - 2], upper.back(), p});
      upper.pop_back();
    }
    lower.push_back(p);
    upper.push_back(p);
  }
  return T;
}

double unit(std::mt19937_64& g) { return double(g() >> 11) * 0x1p-53; }


TEST(Hidden, RandomPointsFromTheSweep) {
  std::mt19937_64 g(10);
  for (int round = 0; round < 5; ++round) {
    std::vector<Point> P;
    for (int k = 0; k < 300; ++k) P.push_back(Point::cartesian(unit(g), unit(g)));
    const std::vector<long> T = sweep(P);
    EXPECT_EQ(ex10test::check(P, T, ex10::delaunay_flips(P, T)), "");
  }
}

// Two rows, the lower fanned from the top-left point and the upper from the bottom-right one:
// every long edge must go, one flip making the next illegal.
TEST(Hidden, TwoRowsCascade) {
  for (int n : {10, 40}) {
    std::vector<Point> P;
    for (int k = 0; k < n; ++k) P.push_back(Point::cartesian(k, 0));              // b_k = k
    for (int k = 0; k < n; ++k) P.push_back(Point::cartesian(k + 0.5, 4.0 * n - k));  // t_k = n + k
    std::vector<long> T;
    for (int k = 0; k + 1 < n; ++k) T.insert(T.end(), {long(k), long(k + 1), long(n)});
    for (int k = 0; k + 1 < n; ++k) T.insert(T.end(), {long(n - 1), long(n + k + 1), long(n + k)});
    EXPECT_EQ(ex10test::check(P, T, ex10::delaunay_flips(P, T)), "") << n;
  }
}

// The quadrilateral of chapter 10 where the smallest height and the smallest angle choose
// different diagonals; the input has the Delaunay one already.
TEST(Hidden, HeightCounterexample) {
  const std::vector<Point> P = {Point::cartesian(0, 0), Point::cartesian(1, 0), Point::cartesian(2, 1),
                                Point::cartesian(0, 4)};
  const std::vector<long> T = {0, 1, 2, 0, 2, 3};
  EXPECT_EQ(ex10test::check(P, T, ex10::delaunay_flips(P, T)), "");
}

// Points of the unit circle ((1 - t²)/(1 + t²), 2t/(1 + t²)), rounded to doubles (correctly
// rounded operations, the same everywhere), and the centre: nearly cocircular, so the in-circle
// signs are decided by the rounding, a few units in the last place, beyond a determinant
// evaluated in doubles.
TEST(Hidden, NearlyCocircular) {
  for (int m : {60, 200}) {
    std::vector<Point> P = {Point::cartesian(0, 0)};
    for (int k = -m; k <= m; ++k) {
      const double t = double(k) / m, d = 1 + t * t;
      P.push_back(Point::cartesian((1 - t * t) / d, 2 * t / d));
      if (k != -m && k != m) P.push_back(Point::cartesian(-(1 - t * t) / d, 2 * t / d));
    }
    const std::vector<long> T = sweep(P);
    EXPECT_EQ(ex10test::check(P, T, ex10::delaunay_flips(P, T)), "") << m;
  }
}

}  // namespace
