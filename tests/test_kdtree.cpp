// The kd-tree of points of T² (range/kdtree.hpp) against the definition (`contains`, one point
// at a time), Boost.Geometry's rtree and nanoflann, and its √n bound on visited nodes.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "range_testing.hpp"
#include "t2/range/kdtree.hpp"

namespace {

using range_testing::brute;
using t2::ExactIsoRect;
using t2::ExactT1;
using t2::KdTree;
using t2::Point;

TEST(KdTree, ReportsAndCountsWhatContainsSeesOnBothSidesAndOnOmega) {
  range_testing::check_mixed<KdTree>(27, 40);
}

TEST(KdTree, AgreesWithBoostRtreeAndNanoflannOnFrontDoubles) {
  range_testing::check_front<KdTree>(271, 3000, 2000);
  range_testing::check_front<KdTree>(272, 40, 500);  // few points: leaves only, or one split
}

TEST(KdTree, ComparesDrawnPositionsExactlyNearBoundsThatAreNoDoubles) {
  range_testing::check_near_thirds<KdTree>();
}

TEST(KdTree, EdgesCornersAndDuplicates) {
  // A 5 x 5 grid with every point twice: the closed square [1, 3] x [1, 3] holds 9 of them twice.
  std::vector<Point> P;
  for (int rep = 0; rep < 2; ++rep)
    for (int x = 0; x < 5; ++x)
      for (int y = 0; y < 5; ++y) P.push_back(Point::cartesian(x, y));
  const KdTree t(P);
  const ExactIsoRect sq(t2::ExactPoint(1, 1, 1), ExactT1(1, 2), ExactT1(1, 2));
  EXPECT_EQ(t.count(sq), 18u);
  EXPECT_EQ(t.report(sq), brute(P, sq));
  // A one-point rectangle on a corner, and a flat one along a row.
  const ExactIsoRect corner(t2::ExactPoint(1, 4, 4), ExactT1(1, 0), ExactT1(1, 0));
  EXPECT_EQ(t.report(corner), (std::vector<std::size_t>{24, 49}));
  const ExactIsoRect row(t2::ExactPoint(1, 0, 2), ExactT1(1, 4), ExactT1(1, 0));
  EXPECT_EQ(t.count(row), 10u);
  EXPECT_EQ(t.report(row), brute(P, row));
  // The same rectangles on the back side hold nothing: the points are in front.
  EXPECT_EQ(t.count(ExactIsoRect(t2::ExactPoint(-1, -1, -1), ExactT1(1, 2), ExactT1(1, 2))), 0u);
}

TEST(KdTree, ClosedQuadrantsHoldTheirPointsOfOmega) {
  const std::vector<Point> P = {Point::cartesian(0, 0), Point(0, 1, 0), Point(0, 1, 1), Point(0, 0, 1),
                                Point(0, -1, 1), Point(0, 1, -1), Point(-1, 0, 0)};
  const KdTree t(P);
  const ExactIsoRect quadrant(t2::ExactPoint(1, 0, 0), ExactT1(0, 1), ExactT1(0, 1));  // x, y >= 0
  EXPECT_EQ(t.report(quadrant), (std::vector<std::size_t>{0, 1, 2, 3}));
  const ExactIsoRect strip(t2::ExactPoint(1, 0, 0), ExactT1(0, 1), ExactT1(1, 0));  // y = 0, x >= 0
  EXPECT_EQ(t.report(strip), (std::vector<std::size_t>{0, 1}));
  const ExactIsoRect back(t2::ExactPoint(-1, 0, 0), ExactT1(0, 1), ExactT1(0, 1));
  // On the back the directions are mirrored: its quadrant x, y >= 0 reaches [0, -1, -1]'s quarter.
  EXPECT_EQ(t.report(back), brute(P, back));
  EXPECT_EQ(t.report(back), (std::vector<std::size_t>{6}));
}

// The √n bound: a window that is a vertical segment enters O(√n) nodes besides its answers,
// also when every point has the window's x (every x-cut is then a tie with both of the window's
// x-bounds, which the composite order separates), and the count is right there.
TEST(KdTree, AThinWindowEntersOrderSqrtNNodes) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  for (const bool same_x : {false, true}) {
    std::vector<Point> P;
    const std::size_t n = 1 << 16;
    for (std::size_t k = 0; k < n; ++k) P.push_back(Point::cartesian(same_x ? 0.5 : u(rng), u(rng)));
    const KdTree t(P);
    for (const double x : {0.25, 0.5, 0.75}) {
      const ExactIsoRect line(t2::to_exact(Point::cartesian(x, 0.25)), ExactT1(1, 0), ExactT1(1024, 1));
      const std::size_t k = t.count(line);
      const std::size_t visits = t.visits(line);
      // 2^⌈d/2⌉ nodes at depth d meet a line: about 4√(n / kLeaf) in all, plus the answers.
      EXPECT_LE(visits, 8 * std::sqrt(double(n)) + 2 * k) << "x = " << x << (same_x ? ", all on x = 0.5" : "");
      if (same_x && x != 0.5) {
        EXPECT_EQ(k, 0u);
      } else if (same_x) {
        EXPECT_EQ(k, range_testing::brute(P, line).size());
        EXPECT_GT(k, 20u);
      }
    }
  }
}

}  // namespace
