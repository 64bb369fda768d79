// Exercise 09, public tests: run them with `t2 check 09`.
#include <gtest/gtest.h>

#include <t2/kernel/point.hpp>

#include "certificate.hpp"
#include "triangulate.hpp"

namespace {

using t2::Point;

TEST(Public, SquareAndCentre) {
  const std::vector<Point> P = {Point::cartesian(0, 0), Point::cartesian(2, 0), Point::cartesian(2, 2),
                                Point::cartesian(0, 2), Point::cartesian(1, 1)};
  EXPECT_EQ(ex09test::check(P, ex09::triangulate(P)), "")
      << "hint: sort the points by (x, y); each new one is outside the hull of the previous ones";
}

TEST(Public, PointInsideAHullEdge) {
  // (1, 0) lies inside the hull edge from (0, 0) to (2, 0): it must be a vertex all the same.
  const std::vector<Point> P = {Point::cartesian(0, 0), Point::cartesian(1, 0), Point::cartesian(2, 0),
                                Point::cartesian(1, 1)};
  EXPECT_EQ(ex09test::check(P, ex09::triangulate(P)), "")
      << "hint: a collinear turn is not a reflex angle: no flat triangle, and keep the point";
}

}  // namespace
