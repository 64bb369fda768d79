// Exercise 15b, public tests: run them with `t2 check 15b`.
#include <gtest/gtest.h>

#include <t2/kernel/isorect.hpp>
#include <t2/kernel/point.hpp>

#include "locus.hpp"

namespace {

using t2::IsoRect;
using t2::Point;
using t2::T1;

// The chapter's example: three front points, two back points, two points of Ω.
const std::vector<Point> kP = {Point::cartesian(0, 0), Point::cartesian(1, 1),   Point::cartesian(2, -1),
                               Point(-1, -1, -1),      Point(-2, -2, -4),        Point::at_infinity(1, 0),
                               Point::at_infinity(1, 1)};

TEST(Public, FiniteRectangles) {
  const std::vector<IsoRect> R = {IsoRect(Point::cartesian(-1, -1), T1(1, 3), T1(1, 2)),
                                  IsoRect(Point::cartesian(1, 1), T1(1, 1), T1(1, -2))};
  const std::vector<long> want = {3, 2};
  EXPECT_EQ(ex15b::count(kP, R), want) << "hint: closed rectangles; a negative extent goes left or down from a";
}

TEST(Public, QuadrantReachesOmega) {
  const std::vector<IsoRect> R = {IsoRect(Point::cartesian(0, 0), T1(0, 1), T1(0, 1))};
  const std::vector<long> want = {4};
  EXPECT_EQ(ex15b::count(kP, R), want)
      << "hint: x, y >= 0 holds (0, 0), (1, 1), and on Ω [0, 1, 0] and [0, 1, 1] (Theorem 3)";
}

TEST(Public, BackRectangle) {
  const std::vector<IsoRect> R = {IsoRect(Point(-1, 0, 0), T1(1, 2), T1(1, 2))};
  const std::vector<long> want = {2};
  EXPECT_EQ(ex15b::count(kP, R), want)
      << "hint: only back points: [-1, -1, -1] is drawn at (1, 1), [-2, -2, -4] at (1, 2); the front (1, 1) is not in it";
}

}  // namespace
