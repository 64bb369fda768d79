// Exercise 07c, public tests: run them with `t2 check 07c`.
#include <gtest/gtest.h>

#include <algorithm>

#include <t2/kernel/point.hpp>

#include "hull.hpp"

namespace {

using t2::Point;

// True when `got` is `want` from some start (the answer may start anywhere).
bool same_cycle(const std::vector<long>& want, std::vector<long> got) {
  if (got.size() != want.size()) return false;
  for (std::size_t k = 0; k < got.size(); ++k, std::rotate(got.begin(), got.begin() + 1, got.end()))
    if (got == want) return true;
  return want.empty();
}

// A house with its roof pushed in: (0,0), (4,0), (4,4), (2,1), (0,4). Vertex 3 is in a pocket.
const std::vector<Point> house = {Point(1, 0, 0), Point(1, 4, 0), Point(1, 4, 4), Point(1, 2, 1), Point(1, 0, 4)};

TEST(Public, FrontCounterClockwise) {
  EXPECT_TRUE(same_cycle({0, 1, 2, 4}, ex07c::hull(house))) << "hint: the strict hull vertices, counter-clockwise";
}

TEST(Public, FrontClockwise) {
  const std::vector<Point> P(house.rbegin(), house.rend());  // indices 4, 3, 2, 1, 0 of `house`
  EXPECT_TRUE(same_cycle({4, 3, 2, 0}, ex07c::hull(P)))
      << "hint: either orientation comes in; the answer is counter-clockwise all the same";
}

TEST(Public, BackSide) {
  std::vector<Point> P;
  for (const Point& p : house) P.push_back(Point(-2, -2 * p.x(), -2 * p.y()));  // the antipodes, scaled by 2
  EXPECT_TRUE(same_cycle({4, 2, 1, 0}, ex07c::hull(P)))
      << "hint: the antipodal map reverses every turn: counter-clockwise in T² is clockwise as drawn";
}

TEST(Public, VertexOnAHullEdge) {
  const std::vector<Point> P = {Point(1, 0, 0), Point(1, 2, 0), Point(1, 4, 0), Point(1, 4, 4), Point(1, 0, 4)};
  EXPECT_TRUE(same_cycle({0, 2, 3, 4}, ex07c::hull(P))) << "hint: strict vertices only: (2, 0) lies inside an edge";
}

}  // namespace
