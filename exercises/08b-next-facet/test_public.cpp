// Exercise 08b, public tests: run them with `t2 check 08b`.
#include <gtest/gtest.h>

#include "facet.hpp"

namespace {

using t2::Point3;

// The cube [0, 2]³, corner k = (2 bit0, 2 bit1, 2 bit2) of k.
std::vector<Point3> cube() {
  std::vector<Point3> P;
  for (int k = 0; k < 8; ++k) P.push_back({double(2 * (k & 1)), double(k & 2), double((k & 4) / 2)});
  return P;
}

TEST(Public, Tetrahedron) {
  // o, x, y, z: across the edge 0 -> 2 of the bottom (0, 2, 1) lies the face in the plane x = 0.
  const std::vector<Point3> P = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  EXPECT_EQ(ex08b::next_facet(P, {0, 2, 1}, 0), (std::vector<long>{2, 0, 3}))
      << "hint: turn the plane of f about a b: p <- q whenever t2::orient3d(P[b], P[a], P[p], P[q]) > 0";
}

TEST(Public, CubeSquare) {
  // Across the edge 0 -> 2 of the bottom square lies the square in the plane x = 0.
  EXPECT_EQ(ex08b::next_facet(cube(), {0, 2, 3, 1}, 0), (std::vector<long>{2, 0, 4, 6}))
      << "hint: the new facet holds every point of its plane (orient3d == 0), not only a triangle";
}

TEST(Public, CubeWithPointsOnTheSquare) {
  // The same, with the midpoint of the edge 0 4 (index 8), the centre of the square (9) and a
  // second copy of corner 6 (10): none of them is a vertex of the facet.
  std::vector<Point3> P = cube();
  P.push_back({0, 0, 1});
  P.push_back({0, 1, 1});
  P.push_back({0, 2, 2});
  EXPECT_EQ(ex08b::next_facet(P, {0, 2, 3, 1}, 0), (std::vector<long>{2, 0, 4, 6}))
      << "hint: strict vertices only (drop points inside edges), and of equal points the smallest index";
}

}  // namespace
