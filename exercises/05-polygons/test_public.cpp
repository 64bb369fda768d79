// Exercise 05, public tests: run them with `t2 check 05`.
#include <gtest/gtest.h>

#include <t2/kernel/point.hpp>

#include "locate.hpp"

namespace {

using t2::Point;

// The unit square, counter-clockwise, on the front.
const std::vector<Point> square = {Point(1, 0, 0), Point(1, 1, 0), Point(1, 1, 1), Point(1, 0, 1)};

TEST(Public, InsideAndOutsideOfAFrontSquare) {
  EXPECT_EQ(ex05::locate(square, Point(2, 1, 1)), t2::POSITIVE)
      << "[2,1,1] is (0.5, 0.5), inside a counter-clockwise square: POSITIVE";
  EXPECT_EQ(ex05::locate(square, Point(1, 3, 0.5)), t2::NEGATIVE) << "(3, 0.5) is outside: NEGATIVE";
}

TEST(Public, OnTheBoundary) {
  EXPECT_EQ(ex05::locate(square, Point(1, 1, 0.25)), t2::ZERO) << "(1, 0.25) is on the right edge";
  EXPECT_EQ(ex05::locate(square, Point(3, 3, 3)), t2::ZERO)
      << "[3,3,3] is the vertex (1,1): vertices are on the boundary. Hint: compare Cartesian "
         "positions without dividing, e.g. x·w' against x'·w.";
}

TEST(Public, VerticesOnBothSides) {
  // Two back vertices: the edges [1,1,0]–[-1,1,0] and [1,1,1]–[-1,1,1] leave the front through
  // Ω and come back on the back sheet. The polygon is still simple: on the sphere it is a
  // quadrilateral, and it is clockwise, so its left region is the larger one.
  const std::vector<Point> Q = {Point(-1, 1, 0), Point(1, 1, 0), Point(1, 1, 1), Point(-1, 1, 1)};
  EXPECT_EQ(ex05::locate(Q, Point(5, 1, 0.5)), t2::POSITIVE)
      << "(0.2, 0.1) on the front is in the left region. Hint: planar ray casting cannot see edges "
         "that cross Ω; walk from a vertex to q as in Algorithm 2 (chapter 05).";
  EXPECT_EQ(ex05::locate(Q, Point(-2, 4, 1)), t2::NEGATIVE) << "this back point is in the small region";
  EXPECT_EQ(ex05::locate(Q, Point(2, 4, 1)), t2::NEGATIVE) << "so is the front point (2, 0.5)";
}

}  // namespace
