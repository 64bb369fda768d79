// Exercise 09c, public tests: run them with `t2 check 09c`.
#include <gtest/gtest.h>

#include <t2/kernel/error.hpp>

#include "certificate.hpp"
#include "insert.hpp"

namespace {

using t2::Point;
using ex09c::Kind;
constexpr long I = ex09c::kInfinite;

// Figure 5.18: the triangle 0 (0, 0), 1 (2, 0), 2 (3, 4) with its three infinite triangles.
const std::vector<long> kT = {0, 1, 2, 1, 0, I, 2, 1, I, 0, 2, I};

std::vector<Point> points(Point q) {
  return {Point::cartesian(0, 0), Point::cartesian(2, 0), Point::cartesian(3, 4), q};
}

TEST(Public, OutsideTheHullAsIn09b) {
  const auto P = points(Point::cartesian(4, 0));
  const std::vector<long> want = {0, 1, 2, 1, 0, I, 2, 1, 3, 3, 1, I, 2, 3, I, 0, 2, I};
  EXPECT_EQ(ex09ctest::check(P, kT, 3, ex09c::insert(P, kT, 3), want), "")
      << "hint: ¬q = (-4, 0) is outside the hull, so the hull survives: 09b's rule";
}

TEST(Public, TheAntipodeOfAHullVertex) {
  // [-1, 0, 0] is ¬(0, 0): no hull edge has it strictly to its left, and it is the antipode of
  // the vertex 0. It replaces v∞; (1, 0, 3) and (0, 2, 3) are lunes (0 and 3 are antipodes).
  const auto P = points(Point(-1, 0, 0));
  const std::vector<long> want = {0, 1, 2, 1, 0, 3, 2, 1, 3, 0, 2, 3};
  EXPECT_EQ(ex09ctest::check(P, kT, 3, ex09c::insert(P, kT, 3), want), "")
      << "hint: compare q with every hull edge; orient(a, b, ¬q) = -orient(a, b, q)";
  const std::vector<Kind> k = {Kind::front, Kind::lune, Kind::band, Kind::lune};
  EXPECT_TRUE(ex09c::kinds(P, want) == k) << "hint: orient = 0 with an antipodal pair is a lune; a proper face with "
                                             "vertices on both sides and none on Ω is a band face";
}

TEST(Public, TheAntipodeInsideAHullEdge) {
  // ¬q = (1, 0) lies inside the hull edge 0 -> 1: no triangulation exists. But ¬q = (2, 1),
  // strictly inside the hull, destroys it: q replaces v∞ in every infinite triangle.
  const auto P = points(Point(-1, -1, 0));
  EXPECT_THROW(ex09c::insert(P, kT, 3), t2::Undefined) << "hint: ¬q inside a hull edge, at no vertex";
  const auto Q = points(Point(-1, -2, -1));
  const std::vector<long> want = {0, 1, 2, 1, 0, 3, 2, 1, 3, 0, 2, 3};
  EXPECT_EQ(ex09ctest::check(Q, kT, 3, ex09c::insert(Q, kT, 3), want), "")
      << "hint: ¬q strictly inside the hull: every hull edge sees q";
}

}  // namespace
