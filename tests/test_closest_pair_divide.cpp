// The closest pair of T² three ways (closest_pair.hpp): brute force, the Delaunay edges and
// Shamos–Hoey divide and conquer give one pair, the one the exact rational weights of
// proximity_oracle.hpp put first — on front, back, mixed, Ω, repeated, collinear and lattice
// sites, sites with |w| ≠ 1 (rounded positions: the filter's margin) and sites beyond its range.
#include <gtest/gtest.h>

#include <string>

#include "proximity_oracle.hpp"
#include "t2/kernel/error.hpp"
#include "t2/proximity/closest_pair.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

using testing::Edge;
using testing::Parts;

/// The first pair by the rational weights and then (i, j): the definition, without the kernel.
Edge oracle(const std::vector<Point>& P) {
  Edge best{0, 1};
  auto wb = testing::pair_weight(P[0], P[1]);
  for (std::uint32_t i = 0; i < P.size(); ++i)
    for (std::uint32_t j = i + 1; j < P.size(); ++j) {
      auto w = testing::pair_weight(P[i], P[j]);
      if (w < wb) best = {i, j}, wb = std::move(w);
    }
  return best;
}

/// The three algorithms against the oracle.
void check_three(const std::vector<Point>& P, const std::string& what) {
  SCOPED_TRACE(what);
  const Edge want = oracle(P);
  EXPECT_EQ(closest_pair_divide(P), want);
  EXPECT_EQ(closest_pair_brute(P), want);
  EXPECT_EQ(closest_pair(P), want);
}

TEST(ClosestPairDivide, AgreesOnEveryPartWithTiesAndRepeats) {
  const Parts parts[] = {Parts::front, Parts::back, Parts::mixed, Parts::front_omega, Parts::mixed_omega, Parts::omega};
  for (std::size_t part = 0; part < std::size(parts); ++part)
    for (int seed = 0; seed < 80 * testing::scale(); ++seed) {
      std::mt19937 rng(7000 + 100 * part + seed);
      const int n = 2 + seed % 60, range = 1 + seed % 9;  // small ranges: lattice ties, repeats
      check_three(testing::proximity_sites_random(rng, parts[part], n, range),
                  "part " + std::to_string(part) + " seed " + std::to_string(seed));
    }
}

TEST(ClosestPairDivide, DistinctSitesWithRoundedPositions) {
  // No repeats, w in {1, 3, 7, -1, -3}: x/w is rounded, the filter's margin decides the strip.
  for (int seed = 0; seed < 40 * testing::scale(); ++seed) {
    std::mt19937 rng(9100 + seed);
    std::uniform_int_distribution<int> c(-300, 300), wp(0, 4);
    const double ws[] = {1, 3, 7, -1, -3};
    std::vector<Point> P;
    const bool mixed = seed % 2;
    for (int k = 0; k < 150; ++k) {
      const double w = ws[wp(rng) % (mixed ? 5 : 3)];
      P.emplace_back(w, c(rng), c(rng));
    }
    check_three(P, "rounded seed " + std::to_string(seed));
  }
}

TEST(ClosestPairDivide, CollinearLatticeAndCircle) {
  std::vector<Point> line, grid, vertical, circle;
  for (int k = 0; k < 40; ++k) line.emplace_back(1, 3 * k % 41, 3 * k % 41);  // one line, equal gaps
  for (int k = 0; k < 49; ++k) grid.emplace_back(1, k % 7, k / 7);           // every pair of neighbours ties
  for (int k = 0; k < 30; ++k) vertical.emplace_back(-2, 0, 2 * ((k * 7) % 30));  // back, x all equal
  const int pyth[][2] = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3}, {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
  for (auto [x, y] : pyth) circle.emplace_back(1, x, y);
  check_three(line, "line");
  check_three(grid, "grid");
  check_three(vertical, "vertical");
  check_three(circle, "circle");
  grid.emplace_back(-1, 0, 0);  // a back site and a direction change nothing
  grid.emplace_back(0, 1, 1);
  check_three(grid, "grid + back + omega");
}

TEST(ClosestPairDivide, LargerUniformInputAgreesWithBruteForce) {
  for (int seed = 0; seed < 3 * testing::scale(); ++seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<Point> P;
    for (int k = 0; k < 3000; ++k) P.emplace_back(seed == 2 ? -1 : 1, u(rng), u(rng));
    const Edge b = closest_pair_brute(P);
    EXPECT_EQ(closest_pair_divide(P), b);
    EXPECT_EQ(closest_pair(P), b);
  }
}

TEST(ClosestPairDivide, OutOfTheFiltersRangeStillExact) {
  // Tiny |w|: Cartesian coordinates near 2^600 and beyond a double (x/w = inf): every pair is
  // compared exactly.
  std::vector<Point> P = {{0x1p-600, 1, 1}, {0x1p-600, 2, 1}, {0x1p-600, 1, 3}, {1, 0, 0}, {1, 1e300, 0}, {0x1p-900, 1e300, 1}};
  check_three(P, "huge");
  P.emplace_back(0x1p-600, 1.5, 1);  // now the nearest is (0, 6) at 2^599
  check_three(P, "huge 2");
}

TEST(ClosestPairDivide, RulesByHand) {
  EXPECT_THROW(closest_pair_divide(std::vector<Point>{{1, 0, 0}}), BadInput);
  EXPECT_EQ(closest_pair_divide(std::vector<Point>{{1, 0, 0}, {-1, 2, 0}}), (Edge{0, 1}));  // beyond infinity
  EXPECT_EQ(closest_pair_divide(std::vector<Point>{{1, 0, 0}, {-1, 2, 0}, {0, 1, 0}}), (Edge{0, 2}));  // +∞
  EXPECT_EQ(closest_pair_divide(std::vector<Point>{{0, 1, 0}, {1, 0, 0}, {0, 2, 0}}), (Edge{0, 2}));  // equal directions
  EXPECT_EQ(closest_pair_divide(std::vector<Point>{{1, 3, 3}, {1, 0, 0}, {2, 6, 6}, {1, 3, 3}}), (Edge{0, 2}));
  EXPECT_EQ(closest_pair_divide(std::vector<Point>{{1, 0, 0}, {-1, 0, 0}}), (Edge{0, 1}));  // antipodes
}

}  // namespace
}  // namespace t2
