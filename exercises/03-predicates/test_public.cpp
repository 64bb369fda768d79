// Exercise 03, public tests: run them with `t2 check 03`.
#include <gtest/gtest.h>

#include <t2/kernel/point.hpp>

#include "mid.hpp"

namespace {

using t2::ExactPoint;

// Same point of T²: proportional with a positive factor (checked with integers, exactly).
bool same(const ExactPoint& a, const ExactPoint& b) {
  return a.w() * b.x() == a.x() * b.w() && a.w() * b.y() == a.y() * b.w() && a.x() * b.y() == a.y() * b.x() &&
         a.w() * b.w() + a.x() * b.x() + a.y() * b.y() > 0;
}

TEST(Public, TwoFrontPoints) {
  const ExactPoint m = ex03::midpoint(ExactPoint(1, 0, 0), ExactPoint(1, 4, 2));
  EXPECT_TRUE(same(m, ExactPoint(1, 2, 1))) << "got " << t2::to_string(m) << ", expected [1,2,1] = (2,1)";
  const ExactPoint n = ex03::midpoint(ExactPoint(2, 2, 0), ExactPoint(3, 0, 3));
  EXPECT_TRUE(same(n, ExactPoint(2, 1, 1))) << "got " << t2::to_string(n)
      << ", expected (1/2, 1/2) = [2,1,1]. Hint: [2,2,0] is (1,0) and [3,0,3] is (0,1).";
}

TEST(Public, TheSamePointTwice) {
  const ExactPoint p(-3, 1, 2);
  EXPECT_TRUE(same(ex03::midpoint(p, p), p)) << "the midpoint of p and p is p, on the back side too";
}

TEST(Public, AntipodesHaveNoMidpoint) {
  EXPECT_THROW(ex03::midpoint(ExactPoint(1, 2, 3), ExactPoint(-1, -2, -3)), t2::Undefined)
      << "no segment joins p and ¬p (every line through p passes through ¬p)";
  EXPECT_TRUE(same(ex03::midpoint(ExactPoint(1, 2, 3), ExactPoint(-1, -2, -2)), ExactPoint(0, 0, 1)))
      << "but a point and a back point that is not its antipode have a midpoint, on Ω";
}

}  // namespace
