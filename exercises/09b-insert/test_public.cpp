// Exercise 09b, public tests: run them with `t2 check 09b`.
#include <gtest/gtest.h>

#include "certificate.hpp"
#include "insert.hpp"

namespace {

using t2::Point;
constexpr long I = ex09b::kInfinite;

// The triangle 0 (0, 0), 1 (4, 0), 2 (0, 4) with its three infinite triangles.
const std::vector<long> kT = {0, 1, 2, 1, 0, I, 2, 1, I, 0, 2, I};

std::vector<Point> points(Point q) {
  return {Point::cartesian(0, 0), Point::cartesian(4, 0), Point::cartesian(0, 4), q};
}

TEST(Public, InsideAFace) {
  const auto P = points(Point::cartesian(1, 1));
  const std::vector<long> want = {0, 1, 3, 1, 2, 3, 2, 0, 3, 1, 0, I, 2, 1, I, 0, 2, I};
  EXPECT_EQ(ex09btest::check(P, kT, 3, ex09b::insert(P, kT, 3), want), "")
      << "hint: (a, b, c) becomes (a, b, q), (b, c, q), (c, a, q)";
}

TEST(Public, OutsideOneEdge) {
  // (4, 4) is strictly left of the infinite triangle (2, 1, inf)'s edge 2 -> 1: it sees the hull
  // edge 1 -> 2 only.
  const auto P = points(Point::cartesian(4, 4));
  const std::vector<long> want = {0, 1, 2, 1, 0, I, 2, 1, 3, 3, 1, I, 2, 3, I, 0, 2, I};
  EXPECT_EQ(ex09btest::check(P, kT, 3, ex09b::insert(P, kT, 3), want), "")
      << "hint: an infinite triangle (a, b, inf) that sees q becomes (a, b, q); then close the hull around q";
}

TEST(Public, HomogeneousCoordinates) {
  // [2, 2, 2] is the point (1, 1): inside, as in InsideAFace.
  const auto P = points(Point(2, 2, 2));
  const std::vector<long> want = {0, 1, 3, 1, 2, 3, 2, 0, 3, 1, 0, I, 2, 1, I, 0, 2, I};
  EXPECT_EQ(ex09btest::check(P, kT, 3, ex09b::insert(P, kT, 3), want), "")
      << "hint: a point is [w, x, y]; t2::orient works on all three coordinates";
}

}  // namespace
