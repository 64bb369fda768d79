// The range tree with fractional cascading (range/range_tree.hpp) against the definition
// (`contains`, one point at a time), Boost.Geometry's rtree and nanoflann.
#include <gtest/gtest.h>

#include <vector>

#include "range_testing.hpp"
#include "t2/range/range_tree.hpp"

namespace {

using range_testing::brute;
using t2::ExactIsoRect;
using t2::ExactT1;
using t2::Point;
using t2::RangeTree;

TEST(RangeTree, ReportsAndCountsWhatContainsSeesOnBothSidesAndOnOmega) {
  range_testing::check_mixed<RangeTree>(28, 40);
}

TEST(RangeTree, AgreesWithBoostRtreeAndNanoflannOnFrontDoubles) {
  range_testing::check_front<RangeTree>(281, 3000, 2000);
  range_testing::check_front<RangeTree>(282, 5, 300);
}

TEST(RangeTree, ComparesDrawnPositionsExactlyNearBoundsThatAreNoDoubles) {
  range_testing::check_near_thirds<RangeTree>();
}

TEST(RangeTree, DuplicatesOnTheSidesAndOnePoint) {
  std::vector<Point> P(7, Point::cartesian(1, 1));  // one position, seven times
  P.push_back(Point::cartesian(2, 1));
  const RangeTree t(P);
  const ExactIsoRect at(t2::ExactPoint(1, 1, 1), ExactT1(1, 0), ExactT1(1, 0));
  EXPECT_EQ(t.count(at), 7u);
  EXPECT_EQ(t.report(at), brute(P, at));
  const ExactIsoRect both(t2::ExactPoint(1, 2, 1), ExactT1(1, -1), ExactT1(0, 1));  // [1, 2] x [1, +inf)
  EXPECT_EQ(t.count(both), 8u);
  const RangeTree one(std::vector<Point>{Point(-2, -1, 0)});
  EXPECT_EQ(one.report(ExactIsoRect(t2::ExactPoint(-2, -1, 0), ExactT1(1, 0), ExactT1(1, 0))),
            std::vector<std::size_t>{0});
  EXPECT_EQ(one.count(ExactIsoRect(t2::ExactPoint(2, 1, 0), ExactT1(1, 0), ExactT1(1, 0))), 0u);
  const RangeTree none(std::vector<Point>{});
  EXPECT_EQ(none.count(at), 0u);
}

TEST(RangeTree, StoresOneLevelArrayPerDepth) {
  std::vector<Point> P;
  for (int k = 0; k < 1000; ++k) P.push_back(Point::cartesian(k % 37, k % 41));
  const RangeTree t(P);
  EXPECT_EQ(t.entries(), 1000u * 11);  // depths 0..10: ⌈log2 1000⌉ + 1 levels
}

}  // namespace
