// The proximity problems of T² (chapter 12) against brute force: the spanning tree against
// Kruskal and Prim on all pairs with the exact rational weights of proximity_oracle.hpp, the
// nearest neighbours against every comparison of the kernel, the closest pair both ways
// against the rational weights — on front, back, mixed, Ω and repeated sites, many seeds.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "proximity_oracle.hpp"
#include "t2/kernel/distance.hpp"
#include "t2/kernel/error.hpp"
#include "t2/proximity/closest_pair.hpp"
#include "t2/proximity/nearest_neighbors.hpp"
#include "t2/proximity/spanning_tree.hpp"
#include "t2/proximity/union_find.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

using testing::Edge;
using testing::Parts;

const Parts kParts[] = {Parts::front, Parts::back, Parts::mixed, Parts::front_omega, Parts::mixed_omega, Parts::omega};
const char* kNames[] = {"front", "back", "mixed", "front+omega", "mixed+omega", "omega"};

/// The nearest to i by the kernel's three-point order: the smallest index among the sites no
/// other site is nearer to i than (an Undefined comparison certifies nothing); none if no site
/// is certified.
std::uint32_t nearest_oracle(const std::vector<Point>& P, std::uint32_t i) {
  for (std::uint32_t j = 0; j < P.size(); ++j) {
    if (j == i) continue;
    bool certified = true;
    for (std::uint32_t k = 0; k < P.size() && certified; ++k) {
      if (k == i || k == j) continue;
      try {
        certified = compare_distance(P[j], P[k], P[i]) != POSITIVE;
      } catch (const Undefined&) {
        certified = false;
      }
    }
    if (certified) return j;
  }
  return Triangulation::none;
}

Edge closest_oracle(const std::vector<Point>& P) {
  Edge best{0, 1};
  for (std::uint32_t i = 0; i < P.size(); ++i)
    for (std::uint32_t j = i + 1; j < P.size(); ++j)
      if (testing::pair_weight(P[i], P[j]) < testing::pair_weight(P[best.first], P[best.second])) best = {i, j};
  return best;
}

std::string show(const std::vector<Point>& P) {
  std::string s;
  for (const Point& p : P) s += "[" + std::to_string(int(p.w())) + " " + std::to_string(int(p.x())) + " " + std::to_string(int(p.y())) + "] ";
  return s;
}

TEST(UnionFind, CountsSetsAndRefusesCycles) {
  UnionFind uf(5);
  EXPECT_EQ(uf.sets(), 5u);
  EXPECT_TRUE(uf.join(0, 1));
  EXPECT_TRUE(uf.join(3, 4));
  EXPECT_FALSE(uf.join(1, 0));
  EXPECT_TRUE(uf.join(1, 4));
  EXPECT_EQ(uf.find(0), uf.find(3));
  EXPECT_NE(uf.find(2), uf.find(3));
  EXPECT_EQ(uf.sets(), 2u);
}

TEST(Proximity, AgreesWithBruteForceOnEveryPart) {
  const int seeds = 60 * testing::scale();
  for (std::size_t part = 0; part < std::size(kParts); ++part)
    for (int seed = 0; seed < seeds; ++seed) {
      std::mt19937 rng(1000 * part + seed);
      const int n = 2 + seed % 14, range = 1 + seed % 5;
      const std::vector<Point> P = testing::proximity_sites_random(rng, kParts[part], n, range);
      SCOPED_TRACE(std::string(kNames[part]) + " seed " + std::to_string(seed) + ": " + show(P));
      // The tree: Kruskal's on all pairs edge for edge, and Prim's weights.
      std::vector<Edge> tree = minimum_spanning_tree(P);
      ASSERT_EQ(tree.size(), P.size() - 1);
      std::vector<Edge> want = testing::kruskal_all_pairs(P);
      EXPECT_EQ(std::set<Edge>(tree.begin(), tree.end()), std::set<Edge>(want.begin(), want.end()));
      EXPECT_EQ(testing::tree_weights(P, tree), testing::prim_weights(P));
      // The closest pair, both ways.
      const Edge cp = closest_oracle(P);
      EXPECT_EQ(closest_pair_brute(P), cp);
      EXPECT_EQ(closest_pair(P), cp);
      // The nearest neighbours, or Undefined where some site has no certified nearest.
      std::vector<std::uint32_t> nn(P.size());
      bool defined = true;
      for (std::uint32_t i = 0; i < P.size(); ++i) {
        nn[i] = nearest_oracle(P, i);
        defined = defined && nn[i] != Triangulation::none;
      }
      if (defined)
        EXPECT_EQ(all_nearest_neighbors(P), nn);
      else
        EXPECT_THROW(all_nearest_neighbors(P), Undefined);
    }
}

TEST(Proximity, LargerFrontInputAgreesWithBruteForce) {
  for (int seed = 0; seed < 5 * testing::scale(); ++seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<Point> P;
    for (int k = 0; k < 300; ++k) P.emplace_back(1, u(rng), u(rng));
    P.push_back(P[17]);  // one repeat
    EXPECT_EQ(testing::tree_weights(P, minimum_spanning_tree(P)), testing::prim_weights(P));
    EXPECT_EQ(closest_pair(P), closest_pair_brute(P));
    const auto nn = all_nearest_neighbors(P);
    for (std::uint32_t i = 0; i < P.size(); i += 7) EXPECT_EQ(nn[i], nearest_oracle(P, i)) << i;
  }
}

// The cases by hand, each with the rule of the headers that decides it.
TEST(Proximity, RulesByHand) {
  // Front and back, no Ω: one edge beyond infinity, between the sites farthest apart drawn
  // (the back sites are drawn at (−5, 0) and (−6, 0): the pair is (1, 0) and (−6, 0)).
  const std::vector<Point> fb = {{1, 0, 0}, {1, 1, 0}, {-1, 5, 0}, {-1, 6, 0}};
  EXPECT_EQ(minimum_spanning_tree(fb), (std::vector<Edge>{{0, 1}, {2, 3}, {1, 3}}));
  EXPECT_EQ(all_nearest_neighbors(fb), (std::vector<std::uint32_t>{1, 0, 3, 2}));
  // One site per side: the front site's nearest is the back one (beyond infinity).
  const std::vector<Point> two = {{1, 0, 0}, {-1, 2, 0}};
  EXPECT_EQ(closest_pair(two), (Edge{0, 1}));
  EXPECT_EQ(all_nearest_neighbors(two), (std::vector<std::uint32_t>{1, 0}));
  // A site on Ω with sites on both sides and no other direction: undefined nearest.
  const std::vector<Point> z = {{1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {0, 1, 0}};
  EXPECT_THROW(all_nearest_neighbors(z), Undefined);
  EXPECT_EQ(minimum_spanning_tree(z).size(), 3u);  // the tree is defined: +∞ edges by index
  // A direction under 90° settles it.
  const std::vector<Point> z2 = {{1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {0, 1, 0}, {0, 1, 1}};
  EXPECT_EQ(all_nearest_neighbors(z2)[3], 4u);
  // Equal sites: distance 0, the first of them.
  const std::vector<Point> eq = {{1, 3, 3}, {1, 0, 0}, {2, 6, 6}, {1, 3, 3}};
  EXPECT_EQ(closest_pair(eq), (Edge{0, 2}));
  EXPECT_EQ(all_nearest_neighbors(eq), (std::vector<std::uint32_t>{2, 0, 0, 0}));
  EXPECT_THROW(all_nearest_neighbors(std::vector<Point>{{1, 0, 0}}), BadInput);
  EXPECT_TRUE(minimum_spanning_tree(std::vector<Point>{{1, 0, 0}}).empty());
}

}  // namespace
}  // namespace t2
