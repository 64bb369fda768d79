// Exercise 12, hidden tests. Oracle: brute force over all sites with the exact
// t2::compare_distance (graph.hpp), on every site of the small inputs and on a random sample of
// 1500 sites of the large one. The graphs E are built without the library's triangulations
// (graph.hpp): brute-force Delaunay triangles for small sets, product grids for the large one.
#include <gtest/gtest.h>

#include <random>

#include <t2/kernel/error.hpp>
#include <t2/kernel/point.hpp>

#include "graph.hpp"
#include "nearest.hpp"

namespace {

using t2::Point;

double unit(std::mt19937_64& g) { return double(g() >> 11) * 0x1p-53; }

// n sites of one side (w of that sign, |w| random in [1, 4)) in the square [0, 10)².
void sites(std::mt19937_64& g, int n, double sign, std::vector<Point>& P) {
  for (int k = 0; k < n; ++k) {
    const double w = sign * (1 + 3 * unit(g));
    P.push_back(Point(w, 10 * unit(g) * w, 10 * unit(g) * w));
  }
}

void expect_brute(const std::vector<Point>& P) {
  const auto want = ex12test::brute(P);
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
  for (long i : sample) EXPECT_EQ(got[i], ex12test::brute_nearest(P, i).value_or(-1)) << i;
}

}  // namespace
