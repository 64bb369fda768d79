// Exercise 13b, public tests: run them with `t2 check 13b`.
#include <gtest/gtest.h>

#include <t2/kernel/point.hpp>

#include "meeting.hpp"

namespace {

using t2::Point;

Point at(double x, double y) { return Point::cartesian(x, y); }

TEST(Public, TwoCrossAmongThree) {
  const std::vector<Point> a = {at(0, 0), at(10, 10), at(0, 4)}, b = {at(4, 4), at(12, 10), at(4, 0)};
  const std::vector<long> want = {0, 2};
  EXPECT_EQ(ex13b::meeting_pair(a, b), want) << "hint: segments 0 and 2 cross at (2, 2); answer {i, j} with i < j";
}

TEST(Public, NoneMeet) {
  const std::vector<Point> a = {at(0, 0), at(0, 1), at(5, -3)}, b = {at(4, 0), at(4, 1), at(5, -1)};
  EXPECT_TRUE(ex13b::meeting_pair(a, b).empty()) << "hint: two parallel segments and a vertical one apart from them";
}

TEST(Public, SharedEndpoint) {
  const std::vector<Point> a = {at(0, 0), at(2, 2)}, b = {at(2, 2), at(4, 0)};
  const std::vector<long> want = {0, 1};
  EXPECT_EQ(ex13b::meeting_pair(a, b), want)
      << "hint: closed segments: a shared endpoint is a common point (at one event, insert before you remove)";
}

TEST(Public, FrontAndBack) {
  // The back segment from [-1, 0, -4] to [-1, -4, 0] is drawn from (0, 4) to (4, 0).
  const std::vector<Point> a = {at(0, 0), Point(-1, 0, -4)}, b = {at(4, 4), Point(-1, -4, 0)};
  EXPECT_TRUE(ex13b::meeting_pair(a, b).empty())
      << "hint: a front and a back segment never meet unless one reaches Ω; their drawings crossing means nothing";
}

}  // namespace
