// Exercise 05b, public tests: run them with `t2 check 05b`.
#include <gtest/gtest.h>

#include <t2/kernel/error.hpp>
#include <t2/kernel/point.hpp>

#include "crossing.hpp"

namespace {

using t2::Point;

bool same(const t2::ExactPoint& p, long w, long x, long y) {
  // p is a positive multiple of [w, x, y].
  return p.x() * w == p.w() * x && p.y() * w == p.w() * y && p.x() * y == p.y() * x &&
         p.w() * w + p.x() * x + p.y() * y > 0;
}

TEST(Public, TwoFrontSegments) {
  const auto p = ex05b::crossing(Point(1, 0, 0), Point(1, 2, 2), Point(1, 0, 2), Point(1, 2, 0));
  EXPECT_TRUE(same(p, 1, 1, 1)) << "the diagonals of the square (0,0)-(2,2) cross at (1, 1); got "
                                << t2::to_string(p);
  EXPECT_THROW(ex05b::crossing(Point(1, 0, 0), Point(1, 1, 0), Point(1, 0, 1), Point(1, 1, 1)), t2::Undefined)
      << "parallel segments on the front do not meet (their lines meet on Ω)";
}

TEST(Public, TheMeetHasTwoPoints) {
  // The lines y = x and y = -x + 2 meet at (1, 1) and at its antipode: which one is on both?
  const auto p = ex05b::crossing(Point(-1, 0, 0), Point(-1, -2, -2), Point(-1, 0, -2), Point(-1, -2, 0));
  EXPECT_TRUE(same(p, -1, -1, -1))
      << "both segments are on the back: they cross at the back point drawn at (1, 1). Hint: the "
         "cross product of the two lines is one of ±x; test which is on both segments. Got "
      << t2::to_string(p);
}

}  // namespace
