// Exercise 03b, public tests: run them with `t2 check 03b`.
#include <gtest/gtest.h>

#include <t2/kernel/point.hpp>

#include "angles.hpp"

namespace {

using t2::Point;

TEST(Public, RightAngleAgainstHalfOfIt) {
  const Point o(1, 0, 0), x(1, 1, 0), y(1, 0, 1), d(1, 1, 1);
  EXPECT_EQ(ex03b::compare_angles(x, o, y, x, o, d), t2::POSITIVE) << "90° > 45°";
  EXPECT_EQ(ex03b::compare_angles(x, o, d, d, o, y), t2::ZERO) << "45° = 45°";
}

TEST(Public, WeightsAreNotCoordinates) {
  const Point o(1, 0, 0), x(1, 1, 0);
  EXPECT_EQ(ex03b::compare_angles(x, o, Point(2, 2, 2), x, o, Point(1, 1, 1)), t2::ZERO)
      << "[2, 2, 2] is the point (1, 1), like [1, 1, 1]. Hint: the vector from b to a is "
         "w_b·(x_a, y_a) − w_a·(x_b, y_b), up to a positive factor.";
}

}  // namespace
