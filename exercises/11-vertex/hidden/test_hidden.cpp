// Exercise 11, hidden tests. Oracle: exact rationals on the drawn positions (oracle.hpp), the
// circumcentre by Cramer's rule and the pole as a left normal; an answer is right when it is a
// positive multiple of the oracle's point. Inputs: random doubles (whose degree-6 determinants
// round in doubles), both orientations, back sites and weights w != ±1, pairs with a site on Ω
// or of the other side, collinear triples, and undefined triples.
#include <gtest/gtest.h>

#include <random>

#include <t2/kernel/error.hpp>
#include <t2/kernel/point.hpp>

#include "oracle.hpp"
#include "vertex.hpp"

namespace {

using t2::Point;

double unit(std::mt19937_64& g) { return double(g() >> 11) * 0x1p-53; }

// A proper site with weight w and drawn position (x, y).
Point site(double w, double x, double y) { return Point(w, x * w, y * w); }

void expect_vertex(const Point& a, const Point& b, const Point& c) {
  EXPECT_EQ(ex11test::check(a, b, c, ex11::voronoi_vertex(a, b, c)), "");
}

TEST(Hidden, FrontTriples) {
  std::mt19937_64 g(11);
  for (int k = 0; k < 40; ++k) {
    const Point a = Point::cartesian(unit(g), unit(g)), b = Point::cartesian(unit(g), unit(g)),
                c = Point::cartesian(unit(g), unit(g));
    expect_vertex(a, b, c);
    expect_vertex(c, b, a);
  }
}

TEST(Hidden, BackAndWeights) {
  std::mt19937_64 g(1111);
  for (int k = 0; k < 40; ++k) {
    const double s = k % 2 ? -1 : 1;
    const Point a = site(s * 3, unit(g), unit(g)), b = site(s * 0.5, unit(g), unit(g)), c = site(s, unit(g), unit(g));
    expect_vertex(a, b, c);
    expect_vertex(b, a, c);
  }
  // Exact small integers: a doubles evaluation is exact here, only the side can be wrong.
  expect_vertex(Point(-1, 0, 0), Point(-1, -4, 0), Point(-1, -2, -5));
  expect_vertex(Point(-2, 0, 0), Point(-2, -2, -10), Point(-1, -4, 0));
}

TEST(Hidden, PolesOnOmega) {
  std::mt19937_64 g(111111);
  for (int k = 0; k < 20; ++k) {
    const double s = k % 2 ? -1 : 1;
    const Point p = site(s * (1 + unit(g)), unit(g), unit(g)), q = site(s * 2, unit(g), unit(g));
    expect_vertex(p, q, Point(0, unit(g) - 0.5, unit(g) - 0.5));  // a site on Ω
    expect_vertex(q, p, site(-s, unit(g), unit(g)));             // a site of the other side
  }
  // Three collinear sites of one side: the pair that does not hold the third between its ends.
  expect_vertex(Point::cartesian(0, 0), Point::cartesian(1, 1), Point::cartesian(3, 3));
  expect_vertex(Point::cartesian(0, 0), Point::cartesian(3, 3), Point::cartesian(1, 1));
  expect_vertex(site(-2, 0, 1), site(-1, 2, 0), site(-3, 1, 0.5));
}

TEST(Hidden, Undefined) {
  const Point f = Point::cartesian(1, 2), b = site(-1, 3, -1), z = Point(0, -1, 2), y = Point(0, 2, 5);
  EXPECT_THROW(ex11::voronoi_vertex(f, b, z), t2::Undefined);
  EXPECT_THROW(ex11::voronoi_vertex(z, f, y), t2::Undefined);
  EXPECT_THROW(ex11::voronoi_vertex(b, z, f), t2::Undefined);
  // Defined: two back sites, consecutive in the cycle.
  const Point c = site(-4, 0.25, 7);
  expect_vertex(b, c, f);
  expect_vertex(z, b, c);
}

}  // namespace
