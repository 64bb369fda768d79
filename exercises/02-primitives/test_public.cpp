// Exercise 02, public tests: run them with `t2 check 02`.
#include <gtest/gtest.h>

#include <t2/kernel/point.hpp>

#include "segments.hpp"

namespace {

using ex02::Shape;
using t2::Point;

TEST(Public, ShapeOfFrontAndBackSegments) {
  EXPECT_TRUE(ex02::shape(Point(1, 0, 0), Point(1, 2, 1)) == Shape::front) << "both ends have w > 0";
  EXPECT_TRUE(ex02::shape(Point(-1, 0, 0), Point(-2, -4, -2)) == Shape::back)
      << "both ends have w < 0: the segment stays on the back sheet. Hint: look at the sign of w.";
  EXPECT_TRUE(ex02::shape(Point(1, 0, 0), Point(-1, -2, 0)) == Shape::two_rays)
      << "one end on each side: the segment leaves the front through Ω and comes back on the back sheet.";
}

TEST(Public, ContainsOnAFrontSegment) {
  const Point p(1, 0, 0), q(1, 4, 2);
  EXPECT_TRUE(ex02::contains(p, q, Point(2, 4, 2))) << "[2,4,2] is the Cartesian point (2,1), halfway";
  EXPECT_TRUE(ex02::contains(p, q, p)) << "the segment is closed: it holds its ends";
  EXPECT_FALSE(ex02::contains(p, q, Point(1, 6, 3))) << "(6,3) is on the line of p and q, but past q";
  EXPECT_FALSE(ex02::contains(p, q, Point(1, 1, 1))) << "(1,1) is not even on the line";
}

}  // namespace
