// Exercise 08, public tests: run them with `t2 check 08`.
#include <gtest/gtest.h>

#include "certificate.hpp"
#include "horizon.hpp"

namespace {

using t2::Point3;

// The tetrahedron o, x, y, z of the unit axes, its triangles outward.
const std::vector<Point3> kTet = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
const std::vector<long> kTetFaces = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};

TEST(Public, OutsideOneFace) {
  // (1, 1, 1) sees only the slanted face (1, 2, 3): the answer has three old and three new triangles.
  std::vector<Point3> P = kTet;
  P.push_back({1, 1, 1});
  const std::vector<long> want = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 4, 2, 3, 4, 3, 1, 4};
  EXPECT_EQ(ex08test::check(P, kTetFaces, 4, ex08::insert_point(P, kTetFaces, 4), want), "")
      << "hint: p sees (a, b, c) when t2::orient3d(P[a], P[b], P[c], P[p]) > 0; the horizon is the three edges "
         "of that face";
}

TEST(Public, Inside) {
  std::vector<Point3> P = kTet;
  P.push_back({0.125, 0.125, 0.125});
  EXPECT_EQ(ex08test::check(P, kTetFaces, 4, ex08::insert_point(P, kTetFaces, 4), kTetFaces), "")
      << "hint: a point that sees no triangle leaves the surface as it is";
}

TEST(Public, OutsideTwoFaces) {
  // (-1, -1, 0.25) sees the faces in the planes x = 0 and y = 0; their common edge 0 -> 3 is not
  // on the horizon.
  std::vector<Point3> P = kTet;
  P.push_back({-1, -1, 0.25});
  const std::vector<long> want = {0, 2, 1, 1, 2, 3, 0, 1, 4, 1, 3, 4, 3, 2, 4, 2, 0, 4};
  EXPECT_EQ(ex08test::check(P, kTetFaces, 4, ex08::insert_point(P, kTetFaces, 4), want), "")
      << "hint: an edge between two seen triangles is not a horizon edge";
}

}  // namespace
