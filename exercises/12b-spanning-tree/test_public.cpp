// Exercise 12b, public tests: run them with `t2 check 12b`.
#include <gtest/gtest.h>

#include <t2/kernel/point.hpp>

#include "graph.hpp"
#include "tree.hpp"

namespace {

using t2::Point;

TEST(Public, FrontSites) {
  const std::vector<Point> P = {Point::cartesian(0, 0), Point::cartesian(4, 0), Point::cartesian(1, 1),
                                Point::cartesian(3, 3), Point::cartesian(0, 5)};
  const std::vector<long> E = ex12btest::brute_graph(P);
  const std::vector<long> min = {0, 2, 2, 3, 1, 2, 3, 4};  // lengths 1.41, 2.83, 3.16, 3.61
  EXPECT_EQ(ex12btest::check(P, ex12b::spanning_tree(P, E), min), "")
      << "hint: Kruskal on the pairs of E, sorted with t2::compare_pair_distance, and a union-find";
}

TEST(Public, ADirection) {
  // Two front sites, two back sites and a direction: the sides are joined through the direction
  // by two edges at +infinity.
  const std::vector<Point> P = {Point::cartesian(0, 0), Point::cartesian(1, 0), Point(-1, 0, 0), Point(-1, 0, 2),
                                Point(0, 1, 1)};
  const std::vector<long> E = ex12btest::brute_graph(P);
  const std::vector<long> min = {0, 1, 2, 3, 0, 4, 2, 4};  // two finite edges, two at +infinity
  EXPECT_EQ(ex12btest::check(P, ex12b::spanning_tree(P, E), min), "")
      << "hint: E has no pair with a site on Omega: every such pair weighs +infinity, after all the finite ones";
}

TEST(Public, TwoSites) {
  const std::vector<Point> P = {Point::cartesian(0, 0), Point(-1, 3, 4)};
  EXPECT_EQ(ex12btest::check(P, ex12b::spanning_tree(P, {}), {0, 1}), "")
      << "hint: a front site and a back site are joined beyond infinity";
}

}  // namespace
