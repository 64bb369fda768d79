// Exercise 12, hidden tests. Oracle: brute force over all sites with the exact
// t2::compare_distance (below), on every site of the small inputs and on a random sample of
// 1500 sites of the large one. The graphs E are built without the library's triangulations
// (graph.hpp): brute-force Delaunay triangles for small sets, product grids for the large one.
#include <gtest/gtest.h>

#include <optional>
#include <random>

#include <t2/kernel/distance.hpp>
#include <t2/kernel/error.hpp>
#include <t2/kernel/point.hpp>

#include "graph.hpp"
#include "nearest.hpp"

namespace {

using t2::Point;

namespace oracle {
/// Site i's nearest by brute force over all sites; nullopt when undefined. A site z of Ω is
/// undefined exactly when no other direction is under 90° from z and both sides hold sites.
std::optional<long> brute_nearest(const std::vector<Point>& P, long i) {
  bool front = false, back = false;
  long proper = -1;
  for (long j = 0; j < long(P.size()); ++j) {
    front |= P[j].w() > 0, back |= P[j].w() < 0;
    if (P[j].w() != 0) proper = j;
  }
  long best = -1;
  if (P[i].w() == 0 && front && back) {
    // Only a direction under 90° from z, nearer than every proper site by the 90° convention
    // (compare_distance against any proper site), settles it: the nearest is the best of them.
    for (long j = 0; j < long(P.size()); ++j)
      if (j != i && P[j].w() == 0 && t2::compare_distance(P[j], P[proper], P[i]) < 0 &&
          (best < 0 || t2::compare_distance(P[j], P[best], P[i]) < 0))
        best = j;
    if (best < 0) return std::nullopt;
    return best;
  }
  for (long j = 0; j < long(P.size()); ++j)  // never undefined here: one side, or i proper
    if (j != i && (best < 0 || t2::compare_distance(P[j], P[best], P[i]) < 0)) best = j;
  return best;
}

/// The whole answer by brute force; nullopt when some site's nearest is undefined.
std::optional<std::vector<long>> brute(const std::vector<Point>& P) {
  std::vector<long> r(P.size());
  for (long i = 0; i < long(P.size()); ++i) {
    const auto b = brute_nearest(P, i);
    if (!b) return std::nullopt;
    r[i] = *b;
  }
  return r;
}

}  // namespace oracle

double unit(std::mt19937_64& g) { return double(g() >> 11) * 0x1p-53; }

// n sites of one side (w of that sign, |w| random in [1, 4)) in the square [0, 10)².
void sites(std::mt19937_64& g, int n, double sign, std::vector<Point>& P) {
  for (int k = 0; k < n; ++k) {
    const double w = sign * (1 + 3 * unit(g));
    P.push_back(Point(w, 10 * unit(g) * w, 10 * unit(g) * w));
  }
}

void expect_brute(const std::vector<Point>& P) {
  const auto want = oracle::brute(P);
  ASSERT_TRUE(want.has_value()) << "bad test input: undefined";
  EXPECT_EQ(ex12::nearest_neighbours(P, ex12test::brute_graph(P)), *want);
}

// One side holds one site: its nearest is on Ω or, with no site on Ω, the site of the other side
// farthest as drawn.
TEST(Hidden, LoneSites) {
  std::mt19937_64 g(12);
  for (double lone : {1.0, -1.0}) {
    std::vector<Point> P;
    sites(g, 30, -lone, P);
    sites(g, 1, lone, P);
    expect_brute(P);
    P.push_back(Point(0, 1, -2));  // a direction: now the nearest of the lone site
    P.push_back(Point(0, 2, -1));
    expect_brute(P);
  }
}

// Sites on both sides and directions, each with another under 90°, among them an antipodal
// pair: every site of Ω has a defined nearest.
TEST(Hidden, Directions) {
  std::mt19937_64 g(1212);
  std::vector<Point> P;
  sites(g, 25, 1, P);
  sites(g, 25, -1, P);
  for (const Point& z : {Point(0, 1, 0), Point(0, 3, 1), Point(0, -1, 0), Point(0, -2, -3), Point(0, 0.5, -4),
                         Point(0, 1, -7)})
    P.push_back(z);
  expect_brute(P);
  // One side and directions more than 90° apart: each direction's nearest is by the sweep rule.
  std::vector<Point> Q;
  sites(g, 30, -1, Q);
  for (const Point& z : {Point(0, 1, 0), Point(0, -1, 2), Point(0, -1, -2)}) Q.push_back(z);
  expect_brute(Q);
}

// A direction with no other under 90° and sites on both sides has no nearest; with a second
// direction near each, or the sites of one side only, every nearest is defined.
TEST(Hidden, UndefinedDirection) {
  std::mt19937_64 g(121212);
  std::vector<Point> P;
  sites(g, 20, 1, P);
  sites(g, 20, -1, P);
  P.push_back(Point(0, 2, 1));
  P.push_back(Point(0, -2, -1.5));
  EXPECT_THROW(ex12::nearest_neighbours(P, ex12test::brute_graph(P)), t2::Undefined);
  P.push_back(Point(0, 2, 2));
  P.push_back(Point(0, -1, -2));
  expect_brute(P);
  std::vector<Point> Q(P.begin(), P.begin() + 20);
  Q.push_back(Point(0, 2, 1));
  expect_brute(Q);
}

// Two product grids of 150 × 150 sites, front and back, and two directions: 45 002 sites. The
// graph of the statement is linear in size, all pairs are a billion: brute force is too slow.
TEST(Hidden, LargeGrids) {
  std::mt19937_64 g(12121212);
  std::vector<Point> P;
  std::vector<long> E;
  ex12test::product_grid(g, 150, 1, P, E);
  ex12test::product_grid(g, 150, -2, P, E);
  P.push_back(Point(0, 1, 0.25));
  P.push_back(Point(0, 1, -0.5));
  const std::vector<long> got = ex12::nearest_neighbours(P, E);
  ASSERT_EQ(got.size(), P.size());
  std::vector<long> sample = {long(P.size()) - 2, long(P.size()) - 1};
  for (int k = 0; k < 1500; ++k) sample.push_back(long(g() % (P.size() - 2)));
  for (long i : sample) EXPECT_EQ(got[i], oracle::brute_nearest(P, i).value_or(-1)) << i;
}

}  // namespace
