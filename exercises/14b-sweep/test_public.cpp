// Exercise 14b, public tests: run them with `t2 check 14b`.
#include <gtest/gtest.h>

#include <ostream>

#include <t2/kernel/point.hpp>

#include "locate.hpp"

namespace ex14b {
// How a failed test prints an answer: as `t2 locate` does.
inline void PrintTo(const Location& l, std::ostream* os) {
  const char* kind[] = {"face", "edge", "vertex", "outside"};
  *os << kind[int(l.kind) & 3];
  if (l.kind != Location::Kind::outside) *os << " " << l.face;
  if (l.kind == Location::Kind::edge || l.kind == Location::Kind::vertex) *os << " " << l.k;
}
}  // namespace ex14b

namespace {

using ex14b::Location;
using t2::Point;
using K = Location::Kind;

TEST(Public, StripInAnyOrder) {
  // Four unit squares in a row, [0, 4] × [0, 1], each cut by its diagonal from (i, 0) to
  // (i + 1, 1): faces 2i (below the diagonal) and 2i + 1 (above). Points 0-4 at the bottom,
  // 5-9 at the top; point 10 is no vertex of the map.
  std::vector<Point> P;
  for (int i = 0; i <= 4; ++i) P.push_back(Point::cartesian(i, 0));
  for (int i = 0; i <= 4; ++i) P.push_back(Point::cartesian(i, 1));
  P.push_back(Point::cartesian(9, 9));
  std::vector<ex14b::Triangle> T;
  for (int i = 0; i < 4; ++i) {
    T.push_back({i, i + 1, i + 6});
    T.push_back({i, i + 6, i + 5});
  }
  const std::vector<Point> Q = {Point::cartesian(3.75, 0.25), Point::cartesian(0.25, 0.75), Point::cartesian(9, 9),
                                Point::cartesian(2, 1),       Point::cartesian(1.5, 0.5),   Point::cartesian(2, 0.5),
                                Point::cartesian(5, 0.5),     Point::cartesian(2.5, 0)};
  const std::vector<Location> want = {{K::face, 6, 0},   {K::face, 1, 0},   {K::outside, -1, 0}, {K::vertex, 2, 2},
                                      {K::edge, 2, 2},   {K::edge, 2, 1},   {K::outside, -1, 0}, {K::edge, 4, 0}};
  EXPECT_EQ(ex14b::locate_all(P, T, Q), want)
      << "hint: the queries come in any order; (2, 1) is vertex 7, of faces 2, 3 and 5: the least is 2, where it "
         "is slot 2; (9, 9) is a point of P but of no face: outside";
}

TEST(Public, OctahedronWithAHole) {
  // ±[1,0,0], ±[0,1,0], ±[0,0,1]: eight faces, one per choice of signs, that cover T²; the
  // back face 7 (w ≤ 0, x ≤ 0, y ≤ 0) is left out: a hole.
  const std::vector<Point> P = {Point(1, 0, 0), Point(-1, 0, 0), Point(0, 1, 0),
                                Point(0, -1, 0), Point(0, 0, 1), Point(0, 0, -1)};
  const std::vector<ex14b::Triangle> T = {{0, 2, 4}, {0, 5, 2}, {0, 4, 3}, {0, 3, 5},
                                          {1, 4, 2}, {1, 2, 5}, {1, 3, 4}};
  const std::vector<Point> Q = {Point(-1, -1, -1), Point(-1, 3, -4), Point(0, 1, 1), Point(0, -1, -1),
                                Point(-2, 0, 0),   Point(1, 0.5, 0.5), Point(1, -2, -1), Point(-1, -1, 0)};
  const std::vector<Location> want = {{K::outside, -1, 0}, {K::face, 5, 0},   {K::edge, 0, 1}, {K::edge, 3, 1},
                                      {K::vertex, 4, 0},   {K::face, 0, 0},   {K::face, 3, 0}, {K::edge, 6, 0}};
  EXPECT_EQ(ex14b::locate_all(P, T, Q), want)
      << "hint: [-1, -1, -1] is in the hole (w, x, y < 0): outside; [0, 1, 1] and [0, -1, -1] are on Ω, on the "
         "edges that faces 0 and 4, and faces 3 and 7 (the hole), share; [-2, 0, 0] is the vertex ¬[1, 0, 0]";
}

}  // namespace
