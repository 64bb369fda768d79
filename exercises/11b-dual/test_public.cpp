// Exercise 11b, public tests: run them with `t2 check 11b`. The expected diagrams are chapter
// 11's (section 7, `t2 voronoi` on data/examples/voronoi-square.t2 and voronoi-two.t2).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include <t2/kernel/number.hpp>
#include <t2/kernel/point.hpp>

#include "dual.hpp"

namespace {

using t2::Point;

// "" when `got` is a positive multiple of [w, x, y], else what is wrong.
std::string same(const t2::ExactPoint& got, long w, long x, long y) {
  const t2::Integer W(w), X(x), Y(y);
  if (got.w() * X != got.x() * W || got.w() * Y != got.y() * W || got.x() * Y != got.y() * X)
    return "not a multiple of the expected point (nor of its antipode)";
  if (sgn(got.w() * W + got.x() * X + got.y() * Y) <= 0) return "the antipode of the expected point";
  return "";
}

// The edges as sorted {min(a, b), max(a, b), min(s, t), max(s, t)}: which vertices, which cells.
std::vector<std::array<long, 4>> unordered(const std::vector<long>& E) {
  std::vector<std::array<long, 4>> r;
  for (std::size_t i = 0; i + 3 < E.size(); i += 4)
    r.push_back({std::min(E[i], E[i + 1]), std::max(E[i], E[i + 1]), std::min(E[i + 2], E[i + 3]),
                 std::max(E[i + 2], E[i + 3])});
  std::sort(r.begin(), r.end());
  return r;
}

TEST(Public, CocircularSquare) {
  // The corners of a square and one more site: the origin is in four cells, and the square comes
  // as two faces with that one vertex.
  const std::vector<Point> P = {Point::cartesian(2, 0), Point::cartesian(0, 2), Point::cartesian(-2, 0),
                                Point::cartesian(0, -2), Point::cartesian(4, 3)};
  const std::vector<long> F = {1, 2, 3, 1, 3, 0, 4, 1, 0, 4, 0, 3, 4, 3, 2, 1, 4, 2};
  const std::vector<t2::ExactPoint> V = ex11b::voronoi_vertices(P, F);
  ASSERT_EQ(V.size(), 5u) << "hint: faces 0 and 1 have one vertex, the origin: merge them (Lemma 2)";
  EXPECT_EQ(same(V[0], 1, 0, 0), "") << "hint: vertex 0 is the vertex of face 0";
  EXPECT_EQ(same(V[1], 10, 21, 21), "");
  EXPECT_EQ(same(V[2], -2, 21, -21), "") << "hint: a clockwise face: a farthest-point vertex, behind";
  EXPECT_EQ(same(V[3], -6, -7, -7), "");
  EXPECT_EQ(same(V[4], -2, -7, 7), "");
  const std::vector<std::array<long, 4>> want = {{0, 1, 0, 1}, {0, 2, 0, 3}, {0, 3, 2, 3}, {0, 4, 1, 2},
                                                 {1, 2, 0, 4}, {1, 4, 1, 4}, {2, 3, 3, 4}, {3, 4, 2, 4}};
  EXPECT_EQ(unordered(ex11b::voronoi_edges(P, F)), want) << "hint: no edge between faces 0 and 1";
}

TEST(Public, TwoSides) {
  // Three front and three back sites (seed 000, figure 5.22): two proper vertices, six poles.
  const std::vector<Point> P = {Point::cartesian(0, 0), Point::cartesian(3, 0), Point::cartesian(1, 3),
                                Point(-1, -1, -1),      Point(-1, -4, -2),      Point(-1, 0, -4)};
  const std::vector<long> F = {2, 0, 1, 5, 4, 3, 2, 1, 3, 3, 4, 2, 0, 2, 4, 4, 5, 0, 1, 0, 5, 5, 3, 1};
  const std::vector<t2::ExactPoint> V = ex11b::voronoi_vertices(P, F);
  ASSERT_EQ(V.size(), 8u);
  const long want_v[8][3] = {{6, 9, 7}, {-1, -2, -3}, {0, 3, 2}, {0, -1, 3},
                             {0, -3, 1}, {0, -1, -2}, {0, 0, -1}, {0, 3, 1}};
  for (int k = 0; k < 8; ++k)
    EXPECT_EQ(same(V[k], want_v[k][0], want_v[k][1], want_v[k][2]), "")
        << "vertex " << k << (k == 1 ? "; hint: three back sites counter-clockwise in T²: behind"
                                     : "; hint: a face with sites on both sides: a pole on Ω");
  const std::vector<std::array<long, 4>> want = {{0, 2, 1, 2}, {0, 4, 0, 2}, {0, 6, 0, 1}, {1, 3, 3, 4},
                                                 {1, 5, 4, 5}, {1, 7, 3, 5}, {2, 3, 2, 3}, {2, 7, 1, 3},
                                                 {3, 4, 2, 4}, {4, 5, 0, 4}, {5, 6, 0, 5}, {6, 7, 1, 5}};
  EXPECT_EQ(unordered(ex11b::voronoi_edges(P, F)), want);
}

}  // namespace
