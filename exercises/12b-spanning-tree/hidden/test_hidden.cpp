// Exercise 12b, hidden tests. Oracle: Kruskal on all pairs sorted by the exact t2::pair_before
// (below) for the small inputs; the answer must be a spanning tree with the oracle's sorted
// weights. For the large input, whose n(n − 1)/2 pairs are too many for it, the oracle is
// Kruskal on a candidate graph known to hold a minimum tree: the sides and diagonals of the
// cells of two product grids (their Delaunay edges, Theorem 2 (i)) and the 16 pairs of grid
// corners (the pair beyond infinity is between hull corners, Theorem 2 (ii)); the same candidates
// are checked against brute force on small grids first.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <utility>

#include <t2/kernel/point.hpp>
#include <t2/kernel/pair_distance.hpp>

#include "graph.hpp"
#include "tree.hpp"

namespace {

using t2::Point;

namespace oracle {

/// Kruskal on the pairs `cand` (flat), sorted by the exact t2::pair_before; a union–find of
/// its own. With all pairs it is the brute-force oracle.
std::vector<long> kruskal(const std::vector<Point>& P, std::vector<long> cand) {
  std::vector<std::pair<long, long>> pairs;
  for (std::size_t k = 0; k + 1 < cand.size(); k += 2) pairs.push_back({cand[k], cand[k + 1]});
  std::sort(pairs.begin(), pairs.end(), [&](const auto& a, const auto& b) {
    return t2::pair_before(P, std::uint32_t(a.first), std::uint32_t(a.second), std::uint32_t(b.first),
                           std::uint32_t(b.second));
  });
  std::vector<long> parent(P.size());
  std::iota(parent.begin(), parent.end(), 0L);
  auto find = [&](long x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::vector<long> T;
  for (const auto& [a, b] : pairs)
    if (find(a) != find(b)) {
      parent[find(a)] = find(b);
      T.insert(T.end(), {a, b});
    }
  return T;
}

/// The oracle on all pairs: O(n² log n), small sets only.
std::vector<long> brute_tree(const std::vector<Point>& P) {
  std::vector<long> all;
  for (long i = 0; i < long(P.size()); ++i)
    for (long j = i + 1; j < long(P.size()); ++j) all.insert(all.end(), {i, j});
  return kruskal(P, all);
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
  EXPECT_EQ(ex12btest::check(P, ex12b::spanning_tree(P, ex12btest::brute_graph(P)), oracle::brute_tree(P)), "");
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
    return oracle::kruskal(P, E);
  };
  {  // the candidates hold a minimum tree: on small grids, against brute force
    std::vector<Point> P;
    std::vector<long> E, corners;
    grids(7, P, E, corners);
    ASSERT_EQ(ex12btest::check(P, oracle(P, E, corners), oracle::brute_tree(P)), "") << "bad oracle";
    EXPECT_EQ(ex12btest::check(P, ex12b::spanning_tree(P, E), oracle::brute_tree(P)), "");
  }
  std::vector<Point> P;
  std::vector<long> E, corners;
  grids(150, P, E, corners);
  EXPECT_EQ(ex12btest::check(P, ex12b::spanning_tree(P, E), oracle(P, E, corners)), "");
}

}  // namespace
