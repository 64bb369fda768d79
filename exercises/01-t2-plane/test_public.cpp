// Exercise 01, public tests: run them with `t2 check 01`.
#include <gtest/gtest.h>

#include <t2/kernel/point.hpp>

#include "classify.hpp"

namespace {

using ex01::Where;
using t2::Point;

const char* name(Where w) {
  return w == Where::front ? "front" : w == Where::back ? "back" : "infinity";
}

TEST(Public, WhereFrontAndBack) {
  EXPECT_EQ(name(ex01::where(Point(1, 5, -7))), std::string("front"))
      << "for [1, 5, -7]. Hint: the side is the sign of w alone; x and y do not matter.";
  EXPECT_EQ(name(ex01::where(Point(-2, 5, -7))), std::string("back"))
      << "for [-2, 5, -7]. Hint: w < 0 is the back side, even though x/w and y/w look ordinary.";
}

TEST(Public, SamePointUpToAPositiveFactor) {
  EXPECT_TRUE(ex01::same_point(Point(1, 2, 3), Point(2, 4, 6)))
      << "[1,2,3] and [2,4,6] are the same point: [2,4,6] = 2·[1,2,3], and 2 > 0.";
  EXPECT_FALSE(ex01::same_point(Point(1, 2, 3), Point(1, 2, 4)))
      << "[1,2,3] and [1,2,4] are different points (different y/w).";
}

TEST(Public, AFrontPointAndItsAntipode) {
  const Point p(1, 2, 3), q(-1, -2, -3);
  EXPECT_FALSE(ex01::same_point(p, q))
      << "[1,2,3] and [-1,-2,-3] differ by the factor -1: they are antipodes, not equal. Hint: "
         "you tested parallel triples (equality in P²); T² also needs the factor to be positive.";
  EXPECT_TRUE(ex01::antipodal(p, q)) << "[-1,-2,-3] = ¬[1,2,3]: antipodal must say true.";
  EXPECT_FALSE(ex01::antipodal(p, p)) << "a point is not its own antipode.";
}

}  // namespace
