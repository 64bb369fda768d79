// Exercise 11, public tests: run them with `t2 check 11`.
#include <gtest/gtest.h>

#include <t2/kernel/error.hpp>
#include <t2/kernel/point.hpp>

#include "oracle.hpp"
#include "vertex.hpp"

namespace {

using t2::Point;

TEST(Public, ChapterExample) {
  // Chapter 11, section 5: the circle of (0, 0), (4, 0), (2, 5) has its centre at (2, 2.1).
  const Point a = Point::cartesian(0, 0), b = Point::cartesian(4, 0), c = Point::cartesian(2, 5);
  EXPECT_EQ(ex11test::check(a, b, c, ex11::voronoi_vertex(a, b, c)), "")
      << "hint: counter-clockwise: the front point [10, 20, 21] or a positive multiple";
  EXPECT_EQ(ex11test::check(a, c, b, ex11::voronoi_vertex(a, c, b)), "")
      << "hint: clockwise: the antipode, [-10, -20, -21]";
}

TEST(Public, APole) {
  // Two front sites and a direction: the vertex is on Ω, perpendicular to (0, 0) -> (4, 0), on
  // its left: [0, 0, 1].
  const Point a = Point::cartesian(0, 0), b = Point::cartesian(4, 0), z = Point(0, 1, -3);
  EXPECT_EQ(ex11test::check(a, b, z, ex11::voronoi_vertex(a, b, z)), "")
      << "hint: the pole [0, l_x, l_y] of the line l = p x q (the cross product)";
}

TEST(Public, Undefined) {
  const Point a = Point::cartesian(0, 0), b = Point(-1, 2, 0), z = Point(0, 1, 0);
  EXPECT_THROW(ex11::voronoi_vertex(a, b, z), t2::Undefined) << "hint: no two consecutive sites on one side";
  const Point c = Point(-1, 0, 3);
  EXPECT_EQ(ex11test::check(b, c, a, ex11::voronoi_vertex(b, c, a)), "")
      << "hint: two back sites b -> c: the pole of their line";
}

}  // namespace
