// Exercise 12b, hidden tests. Oracle: Kruskal on all pairs sorted by the exact t2::pair_before
// (graph.hpp) for the small inputs; the answer must be a spanning tree with the oracle's sorted
// weights. For the large input, whose n(n − 1)/2 pairs are too many for it, the oracle is
// Kruskal on a candidate graph known to hold a minimum tree: the sides and diagonals of the
// cells of two product grids (their Delaunay edges, Theorem 2 (i)) and the 16 pairs of grid
// corners (the pair beyond infinity is between hull corners, Theorem 2 (ii)); the same candidates
// are checked against brute force on small grids first.
#include <gtest/gtest.h>

#include <random>

#include <t2/kernel/point.hpp>

#include "graph.hpp"
#include "tree.hpp"

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
  EXPECT_EQ(ex12btest::check(P, ex12b::spanning_tree(P, ex12btest::brute_graph(P)), ex12btest::brute_tree(P)), "");
}

// Both sides and directions of Ω: the +∞ edges come after every finite one.
TEST(Hidden, MixedSides) {
  std::mt19937_64 g(12);
  for (int round = 0; round < 3; ++round) {
    std::vector<Point> P;
    sites(g, 25, 1, P);
    sites(g, 20, -1, P);
    P.push_back(Point(0, 1 - 2 * unit(g), 1 - 2 * unit(g)));
    if (round > 0) P.push_back(Point(0, 1 - 2 * unit(g), 1 - 2 * unit(g)));
    expect_brute(P);
  }
  std::vector<Point> Q;  // the back side and a direction only
  sites(g, 30, -1, Q);
  Q.insert(Q.begin(), Point(0, 3, -1));
  expect_brute(Q);
}

// Both sides, no site on Ω: one edge beyond infinity, the pair farthest apart as drawn.
TEST(Hidden, BothSidesNoOmega) {
  std::mt19937_64 g(1212);
  for (int round = 0; round < 3; ++round) {
    std::vector<Point> P;
    sites(g, 30, -1, P);
    sites(g, round == 0 ? 1 : 20, 1, P);
    expect_brute(P);
  }
}

// Two product grids of 150 × 150 sites, front and back: 45 000 sites, a billion pairs.
TEST(Hidden, LargeGrids) {
  auto grids = [](int m, std::vector<Point>& P, std::vector<long>& E, std::vector<long>& corners) {
    std::mt19937_64 g(12121212);
    for (double w : {1.0, -2.0}) {
      const long base = long(P.size());
      ex12btest::product_grid(g, m, w, P, E);
      for (long c : {0L, long(m) - 1, long(m) * (m - 1), long(m) * m - 1}) corners.push_back(base + c);
    }
  };
  auto oracle = [](const std::vector<Point>& P, std::vector<long> E, const std::vector<long>& corners) {
    for (int a = 0; a < 4; ++a)
      for (int b = 4; b < 8; ++b) E.insert(E.end(), {corners[a], corners[b]});
    return ex12btest::kruskal(P, E);
  };
  {  // the candidates hold a minimum tree: on small grids, against brute force
    std::vector<Point> P;
    std::vector<long> E, corners;
    grids(7, P, E, corners);
    ASSERT_EQ(ex12btest::check(P, oracle(P, E, corners), ex12btest::brute_tree(P)), "") << "bad oracle";
    EXPECT_EQ(ex12btest::check(P, ex12b::spanning_tree(P, E), ex12btest::brute_tree(P)), "");
  }
  std::vector<Point> P;
  std::vector<long> E, corners;
  grids(150, P, E, corners);
  EXPECT_EQ(ex12btest::check(P, ex12b::spanning_tree(P, E), oracle(P, E, corners)), "");
}

}  // namespace
