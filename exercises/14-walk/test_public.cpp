// Exercise 14, public tests: run them with `t2 check 14`.
#include <gtest/gtest.h>

#include <ostream>

#include <t2/kernel/point.hpp>

#include "walk.hpp"

namespace ex14 {
// How a failed test prints an answer: as `t2 locate` does.
inline void PrintTo(const Location& l, std::ostream* os) {
  const char* kind[] = {"face", "edge", "vertex", "outside"};
  *os << kind[int(l.kind) & 3];
  if (l.kind != Location::Kind::outside) *os << " " << l.face;
  if (l.kind == Location::Kind::edge || l.kind == Location::Kind::vertex) *os << " " << l.k;
}
}  // namespace ex14

namespace {

using ex14::Location;
using t2::Point;
using K = Location::Kind;

// The square [0, 2]² cut by its diagonal from (0, 0) to (2, 2), on the front side.
const std::vector<Point> kSquare = {Point::cartesian(0, 0), Point::cartesian(2, 0), Point::cartesian(2, 2),
                                    Point::cartesian(0, 2)};

TEST(Public, FrontSquare) {
  const std::vector<ex14::Triangle> T = {{0, 1, 2}, {0, 2, 3}};
  const std::vector<Point> Q = {Point::cartesian(1.5, 0.5), Point::cartesian(0.5, 1.5), Point::cartesian(1, 1),
                                Point::cartesian(0, 0),     Point::cartesian(2, 2),     Point::cartesian(0, 2),
                                Point::cartesian(3, 3),     Point(-1, -1, -1)};
  const std::vector<Location> want = {{K::face, 0, 0},   {K::face, 1, 0},   {K::edge, 0, 2}, {K::vertex, 0, 0},
                                      {K::vertex, 0, 2}, {K::vertex, 1, 2}, {K::outside, -1, 0},
                                      {K::outside, -1, 0}};
  EXPECT_EQ(ex14::locate_all(kSquare, T, Q), want)
      << "hint: the diagonal is edge 2 of face 0 and edge 0 of face 1: answer the least face; [-1, -1, -1] is "
         "drawn at (1, 1) but lies on the back side, where there is no face";
}

TEST(Public, BackSquare) {
  // The same square drawn on the back side: the antipodes, listed counter-clockwise in T²
  // (Δ(¬a, ¬b, ¬c) = −Δ(a, b, c), so the drawn order is reversed).
  std::vector<Point> P;
  for (const Point& p : kSquare) P.push_back(t2::antipode(p));
  const std::vector<ex14::Triangle> T = {{0, 2, 1}, {0, 3, 2}};
  const std::vector<Point> Q = {Point(-1, -1.5, -0.5), Point::cartesian(1.5, 0.5), Point(-2, -2, -2),
                                Point(-1, -2, -1)};
  const std::vector<Location> want = {{K::face, 0, 0}, {K::outside, -1, 0}, {K::edge, 0, 0}, {K::edge, 0, 1}};
  EXPECT_EQ(ex14::locate_all(P, T, Q), want) << "hint: a back point [w, x, y], w < 0, is drawn at (x/w, y/w)";
}

TEST(Public, Octahedron) {
  // ±[1,0,0] (the origin and its antipode), ±[0,1,0], ±[0,0,1] (on Ω): eight faces, one per
  // choice of signs, that cover T²; faces 0-3 are the front quadrants, 4-7 the back ones.
  const std::vector<Point> P = {Point(1, 0, 0), Point(-1, 0, 0), Point(0, 1, 0),
                                Point(0, -1, 0), Point(0, 0, 1), Point(0, 0, -1)};
  const std::vector<ex14::Triangle> T = {{0, 2, 4}, {0, 5, 2}, {0, 4, 3}, {0, 3, 5},
                                         {1, 4, 2}, {1, 2, 5}, {1, 3, 4}, {1, 5, 3}};
  const std::vector<Point> Q = {Point(1, 0.5, 0.5), Point(1, -1, 2), Point(-1, 3, -4), Point(0, 1, 1),
                                Point(0, 3, 0),     Point(-2, 0, 0), Point(1, 0, 3)};
  const std::vector<Location> want = {{K::face, 0, 0},   {K::face, 2, 0},   {K::face, 5, 0}, {K::edge, 0, 1},
                                      {K::vertex, 0, 1}, {K::vertex, 4, 0}, {K::edge, 0, 2}};
  EXPECT_EQ(ex14::locate_all(P, T, Q), want)
      << "hint: [0, 1, 1] is on Ω, on the edge shared by the front face 0 and the back face 4; [0, 3, 0] is the "
         "point [0, 1, 0], a vertex of faces 0, 1, 4, 5";
}

}  // namespace
