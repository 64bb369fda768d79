// Exercise 06b, public tests: run them with `t2 check 06b`.
#include <gtest/gtest.h>

#include <t2/kernel/error.hpp>
#include <t2/kernel/point.hpp>

#include "cycle.hpp"
#include "hull.hpp"

namespace {

using ex06btest::compare;
using t2::Point;

TEST(Public, SquareWithAnEdgePointAndACentre) {
  const std::vector<Point> P = {Point::cartesian(0, 0), Point::cartesian(2, 0), Point::cartesian(1, 0),
                                Point::cartesian(2, 2), Point::cartesian(0, 2), Point::cartesian(1, 1)};
  EXPECT_EQ(compare(P, ex06b::hull(P), {0, 1, 3, 4}), "")
      << "hint: (1, 0) lies inside the edge from (0, 0) to (2, 0): it is not a strict vertex";
}

TEST(Public, AcrossInfinity) {
  // The rectangle (0,0) (2,0) (2,1) (0,1) with the midpoint (1,0) of its bottom edge, under the
  // map [w, x, y] -> [w - x, x, y] (determinant 1): the line x = 1 goes to Ω. So the hull is
  // [1,0,0] [-1,2,0] [-1,2,1] [1,0,1] — two back points, drawn at (-2, 0) and (-2, -1) — and the
  // midpoint, now [0,1,0] on Ω, lies inside the edge from p0 to p1 that crosses Ω there.
  const std::vector<Point> P = {Point(1, 0, 0), Point(-1, 2, 0), Point(0, 1, 0), Point(-1, 2, 1), Point(1, 0, 1)};
  EXPECT_EQ(compare(P, ex06b::hull(P), {0, 1, 3, 4}), "")
      << "hint: counter-clockwise means Δ(v_i, v_{i+1}, v_{i+2}) > 0 with t2::orient, never x/w and y/w";
}

TEST(Public, AntipodesHaveNoHull) {
  const std::vector<Point> P = {Point::cartesian(0, 0), Point::cartesian(2, 1), Point(-1, -2, -1)};
  EXPECT_THROW(ex06b::hull(P), t2::Undefined) << "p2 is the antipode of p1: no open hemisphere holds them";
  const std::vector<Point> Q = {Point::cartesian(0, 0), Point::cartesian(2, 1), Point::cartesian(1, 2)};
  EXPECT_EQ(compare(Q, ex06b::hull(Q), {0, 1, 2}), "") << "without the antipode: a triangle";
}

}  // namespace
