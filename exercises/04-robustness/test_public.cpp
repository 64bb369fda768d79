// Exercise 04, public tests: run them with `t2 check 04`.
#include <gtest/gtest.h>

#include <t2/kernel/point.hpp>

#include "exact_orient.hpp"

namespace {

using t2::Point;

TEST(Public, CounterClockwiseFrontTriangle) {
  EXPECT_EQ(ex04::orient_exact(Point(1, 0, 0), Point(1, 1, 0), Point(1, 0, 1)), t2::POSITIVE)
      << "(0,0), (1,0), (0,1) turn counter-clockwise";
  EXPECT_EQ(ex04::orient_exact(Point(1, 0, 0), Point(1, 0, 1), Point(1, 1, 0)), t2::NEGATIVE)
      << "swapping two points flips the sign";
}

TEST(Public, CollinearAndAntipodes) {
  EXPECT_EQ(ex04::orient_exact(Point(1, 0, 0), Point(1, 1, 1), Point(2, 4, 4)), t2::ZERO)
      << "(0,0), (1,1), (2,2) are collinear";
  EXPECT_EQ(ex04::orient_exact(Point(-1, 0, 0), Point(1, 1, 0), Point(1, 0, 1)), t2::NEGATIVE)
      << "replacing a point by its antipode [-1,0,0] flips the sign: check you use w, not x/w";
}

}  // namespace
