// Exercise 12, public tests: run them with `t2 check 12`.
#include <gtest/gtest.h>

#include <t2/kernel/error.hpp>
#include <t2/kernel/point.hpp>

#include "graph.hpp"
#include "nearest.hpp"

namespace {

using t2::Point;

TEST(Public, FrontSites) {
  // Five front sites and their Delaunay edges; 0 and 4 are both at distance 1 from 2: the
  // smaller index wins.
  const std::vector<Point> P = {Point::cartesian(0, 0), Point::cartesian(5, 0), Point::cartesian(1, 0),
                                Point::cartesian(3, 3), Point::cartesian(2, 0)};
  const std::vector<long> E = ex12test::brute_graph(P);
  EXPECT_EQ(ex12::nearest_neighbours(P, E), (std::vector<long>{2, 4, 0, 4, 2}))
      << "hint: Lemma 3: the nearest is a neighbour in E; ties go to the smaller index";
}

TEST(Public, TwoSides) {
  // Two front sites and two back sites: each has its nearest on its own side.
  const std::vector<Point> P = {Point::cartesian(0, 0), Point(1, 1, 0), Point(-1, 0, 0), Point(-2, 0, -2)};
  const std::vector<long> E = ex12test::brute_graph(P);
  EXPECT_EQ(ex12::nearest_neighbours(P, E), (std::vector<long>{1, 0, 3, 2}))
      << "hint: the back sites [-1, 0, 0] and [-2, 0, -2] are drawn at (0, 0) and (0, 1)";
}

TEST(Public, OneDirection) {
  // Front sites and one direction of Ω: the direction's nearest is the front site furthest
  // towards it (the sweep rule); the front sites' nearest are on the front.
  const std::vector<Point> P = {Point::cartesian(0, 0), Point::cartesian(1, 0), Point::cartesian(0, 3),
                                Point(0, 1, 1)};
  const std::vector<long> E = ex12test::brute_graph(P);
  EXPECT_EQ(ex12::nearest_neighbours(P, E), (std::vector<long>{1, 0, 0, 2}))
      << "hint: seen from [0, 1, 1], compare proper sites by the sweep rule (t2::compare_distance does)";
}

TEST(Public, UndefinedWithBothSides) {
  // One front site, one back site, one direction: the direction's nearest is undefined.
  const std::vector<Point> P = {Point::cartesian(0, 0), Point(-1, 0, 0), Point(0, 1, 0)};
  EXPECT_THROW(ex12::nearest_neighbours(P, {}), t2::Undefined)
      << "hint: from [0, 1, 0] a front and a back site cannot be compared, and no other direction settles it";
  // A second direction 45° from the first settles it: the two directions are each other's nearest.
  const std::vector<Point> Q = {Point::cartesian(1, 0), Point(-1, 0, 0), Point(0, 1, 0), Point(0, 1, 1)};
  EXPECT_EQ(ex12::nearest_neighbours(Q, {}), (std::vector<long>{2, 2, 3, 2}))
      << "hint: a direction under 90° is nearer than any proper site (t2::compare_distance), and a proper site "
         "alone on its side has its nearest on Ω, by the angle at the origin";
}

}  // namespace
