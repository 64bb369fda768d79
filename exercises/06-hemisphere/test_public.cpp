// Exercise 06, public tests: run them with `t2 check 06`.
#include <gtest/gtest.h>

#include <t2/kernel/point.hpp>

#include "certificate.hpp"
#include "hemisphere.hpp"

namespace {

using ex06test::Expect;
using ex06test::judge;
using t2::Point;

TEST(Public, FrontPoints) {
  const std::vector<Point> P = {Point::cartesian(0, 0), Point::cartesian(4, 1), Point::cartesian(1, 3),
                                Point::cartesian(2, 2)};
  EXPECT_EQ(judge(P, Expect::hemisphere), "") << "hint: front points all lie in w > 0, the line [1, 0, 0]";
}

TEST(Public, AnAntipodalPair) {
  const std::vector<Point> P = {Point::cartesian(0, 0), Point::cartesian(2, 1), Point(-1, -2, -1)};
  EXPECT_EQ(judge(P, Expect::none), "") << "hint: p2 = [-1, -2, -1] is the antipode of p1 = (2, 1); p1 + p2 = 0";
}

TEST(Public, BothSides) {
  // (0, 0) and (1, 0) on the front, [-1, -2, 3] on the back (drawn at (2, -3)), [0, 1, 1] on Ω:
  // the hemisphere y + w > 0 holds all four, although they are on both sides.
  const std::vector<Point> P = {Point::cartesian(0, 0), Point::cartesian(1, 0), Point(-1, -2, 3), Point(0, 1, 1)};
  EXPECT_EQ(judge(P, Expect::hemisphere), "") << "hint: the front is not the only hemisphere";
}

}  // namespace
