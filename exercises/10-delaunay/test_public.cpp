// Exercise 10, public tests: run them with `t2 check 10`.
#include <gtest/gtest.h>

#include <t2/kernel/point.hpp>

#include "certificate.hpp"
#include "lawson.hpp"

namespace {

using t2::Point;

TEST(Public, OneFlip) {
  // A(0,0), B(1,-1), C(1,1), D(1.5,0): the input joins B C, and D is inside the circle of
  // A, B, C (centre (1, 0), radius 1), so B C must be flipped to A D.
  const std::vector<Point> P = {Point::cartesian(0, 0), Point::cartesian(1, -1), Point::cartesian(1, 1),
                                Point::cartesian(1.5, 0)};
  const std::vector<long> T = {0, 1, 2, 1, 3, 2};
  EXPECT_EQ(ex10test::check(P, T, ex10::delaunay_flips(P, T)), "")
      << "hint: for the edge a b shared by (a, b, c) and (b, a, d), flip when t2::in_circle(a, b, c, d) > 0";
}

TEST(Public, AlreadyDelaunay) {
  // A square and its centre: four triangles, every edge legal; nothing to flip.
  const std::vector<Point> P = {Point::cartesian(0, 0), Point::cartesian(2, 0), Point::cartesian(2, 2),
                                Point::cartesian(0, 2), Point::cartesian(1, 1)};
  const std::vector<long> T = {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
  EXPECT_EQ(ex10test::check(P, T, ex10::delaunay_flips(P, T)), "")
      << "hint: hull edges have one triangle only; never flip them";
}

}  // namespace
