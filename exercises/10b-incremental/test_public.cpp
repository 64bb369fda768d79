// Exercise 10b, public tests: run them with `t2 check 10b`.
#include <gtest/gtest.h>

#include <t2/kernel/error.hpp>
#include <t2/kernel/point.hpp>

#include "certificate.hpp"
#include "incremental.hpp"

namespace {

using t2::Point;

TEST(Public, Square) {
  // A square and a point above its top: the point is outside the hull when inserted last.
  const std::vector<Point> P = {Point::cartesian(0, 0), Point::cartesian(4, 0), Point::cartesian(4, 4),
                                Point::cartesian(0, 4), Point::cartesian(1, 1), Point::cartesian(2, 7)};
  EXPECT_EQ(ex10btest::check(P, ex10b::delaunay(P)), "")
      << "hint: insert each point (in a face, on an edge or outside the hull), then flip the edges opposite it "
         "while t2::in_circle > 0";
}

TEST(Public, Random) {
  std::vector<Point> P;
  unsigned s = 1;
  for (int k = 0; k < 60; ++k) {
    s = s * 1103515245u + 12345u;
    const double x = (s >> 8) % 1000;
    s = s * 1103515245u + 12345u;
    P.push_back(Point::cartesian(x / 7, double((s >> 8) % 1000) / 3));
  }
  EXPECT_EQ(ex10btest::check(P, ex10b::delaunay(P)), "")
      << "hint: after a flip, the two edges it brings opposite the new point may be illegal too";
}

TEST(Public, Collinear) {
  const std::vector<Point> P = {Point::cartesian(0, 0), Point::cartesian(1, 1), Point::cartesian(3, 3)};
  EXPECT_THROW(ex10b::delaunay(P), t2::Undefined) << "hint: three points on one line have no triangle";
  const std::vector<Point> Q = {Point::cartesian(0, 0), Point::cartesian(1, 1), Point::cartesian(3, 2)};
  EXPECT_EQ(ex10btest::check(Q, ex10b::delaunay(Q)), "") << "three points off one line: one triangle";
}

}  // namespace
