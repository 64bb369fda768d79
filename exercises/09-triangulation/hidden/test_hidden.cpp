// Exercise 09, hidden tests. Oracle: the exact certificate of certificate.hpp (counter-clockwise
// triangles, no overlap, every point a vertex, boundary edges on the hull, exact rational areas
// summing to the hull's, computed by an exact monotone chain). Inputs: random points, grids (many
// collinear points, also on the hull), weights other than 1, and the classroom example of
// points a few units in the last place apart.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <t2/kernel/point.hpp>

#include "certificate.hpp"
#include "triangulate.hpp"

namespace {

using t2::Point;

double unit(std::mt19937_64& g) { return double(g() >> 11) * 0x1p-53; }

TEST(Hidden, RandomPoints) {
  std::mt19937_64 g(9);
  for (int n : {3, 10, 100, 2000}) {
    std::vector<Point> P;
    for (int k = 0; k < n; ++k) P.push_back(Point::cartesian(unit(g) * 2 - 1, unit(g) * 2 - 1));
    EXPECT_EQ(ex09test::check(P, ex09::triangulate(P)), "") << n;
  }
}

TEST(Hidden, GridWithCollinearPoints) {
  std::vector<Point> P;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 9; ++j) P.push_back(Point::cartesian((i * 7) % 12, j));  // shuffled columns
  EXPECT_EQ(ex09test::check(P, ex09::triangulate(P)), "");
}

// Points with w != 1 (the same points of T², written differently).
TEST(Hidden, HomogeneousWeights) {
  const std::vector<Point> P = {Point(2, 0, 0), Point(4, 8, 0), Point(0.5, 1, 1), Point(3, 3, 6), Point(1, 1.5, 0.5)};
  EXPECT_EQ(ex09test::check(P, ex09::triangulate(P)), "");
}

// Kettner et al.'s classroom example: a grid of points a few units in the last place apart
// near (0.5, 0.5), with (12, 12) and (24, 24) on their diagonal; the orientation of a grid point
// and the two far ones is the sign of a tiny determinant, which doubles get wrong.
TEST(Hidden, NearlyCollinear) {
  std::vector<Point> P;
  const double ulp = std::nextafter(0.5, 1.0) - 0.5;
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 16; ++j) P.push_back(Point::cartesian(0.5 + i * ulp, 0.5 + j * ulp));
  P.push_back(Point::cartesian(12, 12));
  P.push_back(Point::cartesian(24, 24));
  P.push_back(Point::cartesian(24, 12));
  EXPECT_EQ(ex09test::check(P, ex09::triangulate(P)), "");
}

}  // namespace
