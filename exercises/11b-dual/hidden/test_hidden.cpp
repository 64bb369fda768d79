// Exercise 11b, hidden tests. The complex is built by brute force in exact rationals from the
// definition of the diagram (complex.hpp: candidate centres and poles, their nearest sites in
// T², polygons fanned from a random corner, faces shuffled and rotated); the answer is checked
// vertex by vertex with exercise 11's oracle (oracle.hpp) and edge by edge against the complex's
// adjacency. Small inputs only: the brute force is O(n⁴) and the dual is linear, so a large
// input would time nothing the chapter teaches.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include <t2/kernel/point.hpp>

#include "complex.hpp"
#include "dual.hpp"

namespace {

using t2::Point;

double unit(std::mt19937_64& g) { return double(g() >> 11) * 0x1p-53; }

// A proper site with weight w and drawn position (x, y).
Point site(double w, double x, double y) { return Point(w, x * w, y * w); }

// Builds the complex of P, then checks the student's dual of it.
void expect_dual(const std::vector<Point>& P, std::mt19937_64& g) {
  std::string error;
  const std::vector<long> F = ex11btest::brute_complex(P, g, error);
  ASSERT_EQ(error, "");
  EXPECT_EQ(ex11btest::check(P, F, ex11b::voronoi_vertices(P, F), ex11b::voronoi_edges(P, F)), "");
}

TEST(Hidden, FrontSites) {
  // Front only: the back half is the farthest-point diagram (clockwise faces, back vertices).
  std::mt19937_64 g(1101);
  for (int k = 0; k < 4; ++k) {
    std::vector<Point> P;
    for (int i = 0; i < 9 + k; ++i) P.push_back(Point::cartesian(unit(g), unit(g)));
    expect_dual(P, g);
  }
}

TEST(Hidden, BackSites) {
  // Back only, weights w != -1: every vertex comes out of the side rule on back sites.
  std::mt19937_64 g(1102);
  for (int k = 0; k < 4; ++k) {
    std::vector<Point> P;
    for (int i = 0; i < 9 + k; ++i) P.push_back(site(i % 3 == 0 ? -3 : i % 3 == 1 ? -0.5 : -1, unit(g), unit(g)));
    expect_dual(P, g);
  }
}

TEST(Hidden, BothSides) {
  // Sites on both sides: each side its nearest-point diagram, Ω cut by poles.
  std::mt19937_64 g(1103);
  for (int k = 0; k < 4; ++k) {
    std::vector<Point> P;
    for (int i = 0; i < 5 + k; ++i) P.push_back(site(i % 2 ? 2 : 1, unit(g), unit(g)));
    for (int i = 0; i < 4 + k; ++i) P.push_back(site(i % 2 ? -2 : -1, unit(g), unit(g)));
    expect_dual(P, g);
  }
}

// Twelve integer points on the circle of radius 5, with `inner` a square of radius √2 inside: a
// front vertex in four cells, a back vertex in twelve (the whole hull is cocircular), and the
// isosceles trapezoids of the symmetric set, cocircular too. Without the square, one front and
// one back vertex, antipodes, each in all twelve cells: adjacent faces across the hull have
// in_circle zero and opposite turns (Lemma 2).
std::vector<Point> circle_set(double w, bool inner) {
  std::vector<Point> P;
  for (const auto& [x, y] : {std::pair{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3}, {-5, 0}, {-4, -3}, {-3, -4},
                             {0, -5}, {3, -4}, {4, -3}, {1, 1}, {-1, 1}, {-1, -1}, {1, -1}})
    if (inner || x * x + y * y == 25) P.push_back(site(w, x, y));
  return P;
}

TEST(Hidden, Cocircular) {
  std::mt19937_64 g(1104);
  expect_dual(circle_set(1, true), g);
  expect_dual(circle_set(-2, true), g);
  expect_dual(circle_set(1, false), g);
  expect_dual(circle_set(-0.5, false), g);
  std::vector<Point> P = circle_set(1, true);  // and back sites: no back vertex of the front circle
  for (int i = 0; i < 4; ++i) P.push_back(site(-1, unit(g), unit(g)));
  expect_dual(P, g);
}

TEST(Hidden, MergedOnOmega) {
  // A vertex on Ω in four cells: a horizontal bottom hull edge of the front sites and a
  // horizontal top hull edge of the back sites (drawn) have one pole [0, 0, -1]; its polygon is
  // cut into two faces with sites on both sides, to be merged by their exact poles.
  std::mt19937_64 g(1105);
  for (int k = 0; k < 3; ++k) {
    std::vector<Point> P = {Point::cartesian(0, 0), Point::cartesian(1, 0), site(-2, 0.25, 1), site(-1, 0.75, 1)};
    for (int i = 0; i < 3 + k; ++i) P.push_back(site(1, unit(g), 0.125 + unit(g)));
    for (int i = 0; i < 3 + k; ++i) P.push_back(site(i % 2 ? -1 : -3, unit(g), unit(g) * 0.875));
    expect_dual(P, g);
  }
  // And four front sites on a line (chapter 11, section 3, case 4): two flat polygons a1 a2 a3 a4
  // and a4 a3 a2 a1, fanned; two vertices on Ω, four edges. Written by hand: the brute force
  // finds no vertex of proper sites all on one line.
  const std::vector<Point> L = {Point::cartesian(0, 0), Point::cartesian(3, 3), Point::cartesian(1, 1),
                                Point::cartesian(4, 4)};
  const std::vector<long> F = {0, 2, 1, 0, 1, 3, 3, 1, 2, 3, 2, 0};
  EXPECT_EQ(ex11btest::check(L, F, ex11b::voronoi_vertices(L, F), ex11b::voronoi_edges(L, F)), "");
  // The same drawn on the back side, with another fan.
  const std::vector<Point> B = {site(-2, 0, 0), site(-1, 3, 3), site(-3, 1, 1), site(-1, 4, 4)};
  const std::vector<long> G = {2, 1, 3, 2, 3, 0, 1, 2, 0, 0, 3, 1};
  EXPECT_EQ(ex11btest::check(B, G, ex11b::voronoi_vertices(B, G), ex11b::voronoi_edges(B, G)), "");
}

}  // namespace
