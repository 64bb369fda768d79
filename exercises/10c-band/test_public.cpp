// Exercise 10c, public tests: run them with `t2 check 10c`.
#include <gtest/gtest.h>

#include <t2/kernel/error.hpp>

#include "band.hpp"
#include "certificate.hpp"

namespace {

using t2::Point;

// The front triangle 0 (0, 0), 1 (4, 0), 2 (0, 4) and three back sites drawn at 3 (1, 1),
// 4 (2, 1), 5 (1, 2) (site 5 with the weight -2).
const std::vector<Point> kP = {Point(1, 0, 0),   Point(1, 4, 0),   Point(1, 0, 4),
                               Point(-1, -1, -1), Point(-1, -2, -1), Point(-2, -2, -4)};

TEST(Public, OwnersOfAPointOfOmega) {
  EXPECT_EQ(ex10c::owners(kP, Point(0, 2, 1)), (std::vector<long>{1, 3}))
      << "hint: in front the largest u · A; behind the smallest u · B̄, B̄ = (x/w, y/w): the back side is "
         "drawn mirrored, and its sites reach [0, u] running off in the direction -u";
  EXPECT_EQ(ex10c::owners(kP, Point(0, -1, 2)), (std::vector<long>{2, 4})) << "hint: u = (-1, 2)";
  EXPECT_THROW(ex10c::owners(kP, Point(0, 0, 1)), t2::Undefined)
      << "hint: 3 (1, 1) and 4 (2, 1) are equally far in the direction -u = (0, -1): a break";
}

TEST(Public, TheBandOfTwoTriangles) {
  // Front hull 0 -> 1 -> 2; back hull, as drawn, 3 -> 4 -> 5. The back owner of 0 -> 1 is the
  // back site drawn farthest to its left (up): 5. That of 1 -> 2 (left is towards (-1, -1)): 3.
  const std::vector<long> want = {1, 0, 5, 2, 1, 3, 0, 2, 4, 3, 4, 2, 4, 5, 0, 5, 3, 1};
  EXPECT_EQ(ex10ctest::check(6, ex10c::band(kP), want), "")
      << "hint: one face (a2, a1, b) per front hull edge a1 -> a2 and one (b1, b2, a) per back hull edge b1 -> b2 "
         "(counter-clockwise as drawn)";
}

TEST(Public, AFlatFace) {
  // The back sites drawn at (2, 0) and (1, -3): the back owner of the front hull edge 0 -> 1
  // (the x axis) is drawn on it, at no end of it: no band exists.
  std::vector<Point> P = {Point(1, 0, 0), Point(1, 4, 0), Point(1, 0, 4), Point(-1, -2, 0), Point(-1, -1, 3)};
  EXPECT_THROW(ex10c::band(P), t2::Undefined) << "hint: a face with orient 0 and no antipodal pair";
  // Drawn at (4, 0) instead, it is ¬1: the flat face (1, 0, 3) is the band face of an antipodal pair.
  P[3] = Point(-2, -8, 0);
  const std::vector<long> want = {1, 0, 3, 2, 1, 4, 0, 2, 3, 4, 3, 2, 3, 4, 1};
  EXPECT_EQ(ex10ctest::check(5, ex10c::band(P), want), "")
      << "hint: a flat face whose third vertex is drawn at an end of its edge is kept (chapter 10, section 8)";
}

}  // namespace
