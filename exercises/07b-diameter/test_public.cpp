// Exercise 07b, public tests: run them with `t2 check 07b`.
#include <gtest/gtest.h>

#include <t2/kernel/error.hpp>
#include <t2/kernel/point.hpp>

#include "diameter.hpp"
#include "farthest.hpp"

namespace {

using ex07btest::check;
using t2::Point;

TEST(Public, FrontSquare) {
  const std::vector<Point> P = {Point::cartesian(0, 0), Point::cartesian(3, 0), Point::cartesian(3, 2),
                                Point::cartesian(0, 2), Point::cartesian(1, 1)};
  EXPECT_EQ(check(P, ex07b::diameter(P)), "") << "hint: the diameter is the LARGEST distance (seed 003 says min)";
}

TEST(Public, FrontAndBack) {
  // Chapter 07's example: front (0,0), (6,2); back points drawn at (-2,3) and (5,-1). Pairs
  // across sides are beyond infinity, and the nearest as drawn, p1 p3, is the farthest.
  const std::vector<Point> P = {Point::cartesian(0, 0), Point::cartesian(6, 2), Point(-1, 2, -3), Point(-1, -5, 1)};
  EXPECT_EQ(check(P, ex07b::diameter(P)), "") << "hint: compare squared distances in T¹, not in the plane";
}

TEST(Public, TwoPointsOfOmega) {
  const std::vector<Point> P = {Point::cartesian(0, 0), Point(0, 1, 0), Point(0, 0, 1)};
  EXPECT_THROW(ex07b::diameter(P), t2::Undefined) << "two different points of Ω are an angle apart";
  const std::vector<Point> Q = {Point::cartesian(0, 0), Point(0, 1, 0)};
  EXPECT_EQ(check(Q, ex07b::diameter(Q)), "") << "one point of Ω is infinitely far from every proper point";
}

}  // namespace
