// Exercise 15, public tests: run them with `t2 check 15`.
#include <gtest/gtest.h>

#include <t2/kernel/error.hpp>
#include <t2/kernel/point.hpp>

#include "dominance.hpp"

namespace {

using t2::Point;

// The five points of the chapter's grid figure are not these; these sit on a rectangle's sides.
const std::vector<Point> kP = {Point::cartesian(0, 0), Point::cartesian(1, 1), Point::cartesian(2, 1),
                               Point::cartesian(1, 3), Point::cartesian(3, 2)};

TEST(Public, Dominance) {
  EXPECT_EQ(ex15::dominance(kP, Point::cartesian(2, 2), false, false), 3) << "hint: x <= 2 and y <= 2";
  EXPECT_EQ(ex15::dominance(kP, Point::cartesian(2, 2), true, false), 2) << "hint: strict in x: (2, 1) is out";
  EXPECT_EQ(ex15::dominance(kP, Point::cartesian(2, 1), false, true), 1) << "hint: strict in y: only (0, 0)";
}

TEST(Public, ClosedRectangle) {
  EXPECT_EQ(ex15::count(kP, Point::cartesian(1, 1), Point::cartesian(3, 2)), 3)
      << "hint: closed: (1, 1), (2, 1) and (3, 2) are on the sides; Lemma 1 needs strict counts at the lower left";
}

TEST(Public, BackPoints) {
  const std::vector<Point> P = {Point::cartesian(1, 1), Point(-1, -1, -1), Point(-2, -2, -2), Point::at_infinity(1, 1)};
  EXPECT_EQ(ex15::count(P, Point(-1, 0, 0), Point(-1, -2, -2)), 2)
      << "hint: the back rectangle [0, 2] x [0, 2] holds the two back points drawn at (1, 1), not the front one";
  EXPECT_THROW(ex15::dominance(P, Point::at_infinity(1, 0), false, false), t2::Undefined) << "hint: a corner on Ω";
}

}  // namespace
