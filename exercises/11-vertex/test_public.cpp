// Exercise 11, public tests: run them with `t2 check 11`.
#include <gtest/gtest.h>

#include <string>

#include <t2/kernel/error.hpp>
#include <t2/kernel/number.hpp>
#include <t2/kernel/point.hpp>

#include "vertex.hpp"

namespace {

using t2::Point;

// "" when `got` is a positive multiple of [w, x, y], else what is wrong.
std::string same(const t2::ExactPoint& got, long w, long x, long y) {
  const t2::Integer W(w), X(x), Y(y);
  if (got.w() * X != got.x() * W || got.w() * Y != got.y() * W || got.x() * Y != got.y() * X)
    return "not a multiple of the expected point (nor of its antipode)";
  if (sgn(got.w() * W + got.x() * X + got.y() * Y) <= 0) return "the antipode of the expected point";
  return "";
}

TEST(Public, ChapterExample) {
  // Chapter 11, section 5: the circle of (0, 0), (4, 0), (2, 5) has its centre at (2, 2.1).
  const Point a = Point::cartesian(0, 0), b = Point::cartesian(4, 0), c = Point::cartesian(2, 5);
  EXPECT_EQ(same(ex11::voronoi_vertex(a, b, c), 10, 20, 21), "")
      << "hint: counter-clockwise: the front point [10, 20, 21] or a positive multiple";
  EXPECT_EQ(same(ex11::voronoi_vertex(a, c, b), -10, -20, -21), "")
      << "hint: clockwise: the antipode, [-10, -20, -21]";
}

TEST(Public, APole) {
  // Two front sites and a direction: the vertex is on Ω, perpendicular to (0, 0) -> (4, 0), on
  // its left: [0, 0, 1].
  const Point a = Point::cartesian(0, 0), b = Point::cartesian(4, 0), z = Point(0, 1, -3);
  EXPECT_EQ(same(ex11::voronoi_vertex(a, b, z), 0, 0, 1), "")
      << "hint: the pole [0, l_x, l_y] of the line l = p x q (the cross product)";
}

TEST(Public, Undefined) {
  const Point a = Point::cartesian(0, 0), b = Point(-1, 2, 0), z = Point(0, 1, 0);
  EXPECT_THROW(ex11::voronoi_vertex(a, b, z), t2::Undefined) << "hint: no two consecutive sites on one side";
  const Point c = Point(-1, 0, 3);
  EXPECT_EQ(same(ex11::voronoi_vertex(b, c, a), 0, 3, 2), "")
      << "hint: two back sites b -> c, drawn at (-2, 0) and (0, -3): the pole of their line, [0, 3, 2]";
}

}  // namespace
