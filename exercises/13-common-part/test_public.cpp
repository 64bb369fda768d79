// Exercise 13, public tests: run them with `t2 check 13`.
#include <gtest/gtest.h>

#include <t2/kernel/point.hpp>

#include "common.hpp"

namespace {

using t2::ExactPoint;
using t2::Point;

TEST(Public, FrontCrossing) {
  const auto r = ex13::common(Point::cartesian(0, 0), Point::cartesian(2, 2), Point::cartesian(0, 2), Point::cartesian(2, 0));
  ASSERT_EQ(r.size(), 1u) << "hint: two segments of different lines meet in at most one point";
  EXPECT_EQ(r[0], ExactPoint(1, 1, 1)) << "hint: the lines of ab and cd meet at ±(a × b) × (c × d); which sign is on both?";
  EXPECT_TRUE(ex13::common(Point::cartesian(0, 0), Point::cartesian(1, 1), Point::cartesian(3, 0), Point::cartesian(3, 1)).empty())
      << "hint: the lines meet at (3, 3), beyond both segments";
}

TEST(Public, Overlap) {
  const auto r = ex13::common(Point::cartesian(0, 0), Point::cartesian(4, 0), Point::cartesian(6, 0), Point::cartesian(2, 0));
  ASSERT_EQ(r.size(), 2u) << "hint: collinear segments can share a piece: return its two ends";
  EXPECT_TRUE((r[0] == ExactPoint(1, 2, 0) && r[1] == ExactPoint(1, 4, 0)) ||
              (r[1] == ExactPoint(1, 2, 0) && r[0] == ExactPoint(1, 4, 0)))
      << "hint: the piece is from (2, 0) to (4, 0)";
}

TEST(Public, BackSide) {
  // The back segments [-1, 0, 0] to [-1, -2, -2] and [-1, 0, -2] to [-1, -2, 0]: drawn as an X
  // around (1, 1), they cross at the back point [-1, -1, -1].
  const auto r = ex13::common(Point(-1, 0, 0), Point(-1, -2, -2), Point(-1, 0, -2), Point(-1, -2, 0));
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0], ExactPoint(-1, -1, -1)) << "hint: keep the sign: the crossing of two back segments is a back point";
  EXPECT_TRUE(ex13::common(Point::cartesian(0, 0), Point::cartesian(2, 2), Point(-1, 0, -2), Point(-1, -2, 0)).empty())
      << "hint: a front segment and a back segment never meet, even when their drawings cross";
}

}  // namespace
