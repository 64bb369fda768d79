// Exercise 07, public tests: run them with `t2 check 07`.
#include <gtest/gtest.h>

#include <t2/kernel/error.hpp>
#include <t2/kernel/point.hpp>

#include "strip.hpp"
#include "width.hpp"

namespace {

using ex07test::check;
using t2::Point;

TEST(Public, FrontTriangle) {
  // (0,0), (4,0), (1,3) and a point inside: the heights of the triangle are 3 (over the bottom
  // edge), 12/√10 ≈ 3.79 and 12/√18 ≈ 2.83: the strip lies along the edge from (4,0) to (1,3).
  const std::vector<Point> P = {Point::cartesian(0, 0), Point::cartesian(4, 0), Point::cartesian(1, 3),
                                Point::cartesian(1, 1)};
  EXPECT_EQ(check(P, ex07::width(P)), "") << "hint: a narrowest strip has a side along a hull edge";
}

TEST(Public, ADirectionAtInfinity) {
  // The point [0, 1, 0] of Ω is the end of every horizontal strip and of no other: the strip
  // must be horizontal, from y = 0 to y = 3, though a slanted one would be narrower.
  const std::vector<Point> P = {Point::cartesian(0, 0), Point::cartesian(4, 0), Point::cartesian(1, 3), Point(0, 1, 0)};
  EXPECT_EQ(check(P, ex07::width(P)), "") << "hint: P[j] may be the point of Ω: the line through P[i] in its direction";
}

TEST(Public, BothSides) {
  const std::vector<Point> P = {Point::cartesian(0, 0), Point::cartesian(4, 0), Point(-1, -1, -3)};
  EXPECT_THROW(ex07::width(P), t2::Undefined) << "a strip lies on one side of T²";
  const std::vector<Point> F = {Point::cartesian(0, 0), Point::cartesian(4, 0), Point::cartesian(1, 3)};
  EXPECT_EQ(check(F, ex07::width(F)), "") << "the front points alone have a strip";
}

}  // namespace
