// Exercise 15, hidden tests. Oracle: a brute-force count on exact rationals written here, one
// point at a time, independent of Lemma 1. Inputs: a grid with points on every side of the
// rectangles; front and back points drawn at the same places; weights w ≠ 1 with corners at the
// double nearest a point's drawn coordinate; random points on both sides and on Ω.
#include <gtest/gtest.h>

#include <random>

#include <t2/kernel/error.hpp>
#include <t2/kernel/number.hpp>
#include <t2/kernel/point.hpp>

#include "dominance.hpp"

namespace {

using t2::Point;
using t2::Rational;

Rational drawn_x(const Point& p) { return Rational(p.x()) / Rational(p.w()); }
Rational drawn_y(const Point& p) { return Rational(p.y()) / Rational(p.w()); }
bool same_side(const Point& p, const Point& q) { return (p.w() > 0 && q.w() > 0) || (p.w() < 0 && q.w() < 0); }

long oracle_q(const std::vector<Point>& P, const Point& q, bool sx, bool sy) {
  long n = 0;
  for (const auto& p : P) {
    if (!same_side(p, q)) continue;
    const int cx = cmp(drawn_x(p), drawn_x(q)), cy = cmp(drawn_y(p), drawn_y(q));
    n += (sx ? cx < 0 : cx <= 0) && (sy ? cy < 0 : cy <= 0);
  }
  return n;
}

long oracle_n(const std::vector<Point>& P, const Point& lo, const Point& hi) {
  long n = 0;
  for (const auto& p : P)
    n += same_side(p, lo) && drawn_x(lo) <= drawn_x(p) && drawn_x(p) <= drawn_x(hi) && drawn_y(lo) <= drawn_y(p) &&
         drawn_y(p) <= drawn_y(hi);
  return n;
}

// Every dominance count at the corners and the rectangle's count, against the oracle.
void check(const std::vector<Point>& P, const Point& lo, const Point& hi) {
  EXPECT_EQ(ex15::count(P, lo, hi), oracle_n(P, lo, hi));
  for (const Point& q : {lo, hi})
    for (int f = 0; f < 4; ++f) EXPECT_EQ(ex15::dominance(P, q, f & 1, f & 2), oracle_q(P, q, f & 1, f & 2));
}

TEST(Hidden, GridOnTheSides) {
  std::vector<Point> P;
  for (int x = 0; x < 8; ++x)
    for (int y = 0; y < 8; ++y)
      if ((x * 5 + y * 3) % 4 != 0) P.push_back(Point::cartesian(x, y));
  check(P, Point::cartesian(2, 3), Point::cartesian(5, 6));
  check(P, Point::cartesian(0, 0), Point::cartesian(7, 7));
  check(P, Point::cartesian(3, 1), Point::cartesian(3, 6));  // a segment
  check(P, Point::cartesian(4, 4), Point::cartesian(4, 4));  // a point
}

TEST(Hidden, BackSide) {
  std::vector<Point> P;
  for (int k = 0; k < 12; ++k) {
    P.push_back(Point::cartesian(k % 5, k % 3));
    P.push_back(Point(-2, -2.0 * (k % 4), -2.0 * (k % 3)));  // drawn at (k % 4, k % 3)
  }
  check(P, Point(-1, -1, 0), Point(-1, -3, -2));
  check(P, Point::cartesian(1, 0), Point::cartesian(3, 2));
  check(P, Point(-4, 0, 0), Point(-4, -8, -4));
}

TEST(Hidden, Weights) {
  // Points drawn at thirds and sevenths; corners at the doubles nearest those values, which
  // differ from them by less than a unit in the last place.
  std::vector<Point> P;
  for (int k = 1; k < 7; ++k) {
    P.push_back(Point(3, k, 2 * k));
    P.push_back(Point(7, k, 3 * k));
    P.push_back(Point(-3, -k, -k));
  }
  check(P, Point::cartesian(1.0 / 3, 1.0 / 3), Point::cartesian(4.0 / 3, 8.0 / 3));
  check(P, Point::cartesian(1.0 / 7, 0), Point::cartesian(5.0 / 7, 15.0 / 7));
  check(P, Point(-1, -1.0 / 3, -1.0 / 3), Point(-1, -5.0 / 3, -5.0 / 3));
}

TEST(Hidden, RandomBothSidesAndOmega) {
  std::mt19937_64 g(1515);
  std::vector<Point> P;
  const double w[] = {-3, -2, -1, 0, 1, 2, 3};
  for (int k = 0; k < 400; ++k) {
    const double s = w[g() % 7], x = double(g() % 13) - 6, y = double(g() % 13) - 6;
    P.push_back(s == 0 ? Point::at_infinity(x == 0 ? 1 : x, y) : Point(s, s * x, s * y));
  }
  for (int k = 0; k < 40; ++k) {
    const double s = (k % 2 ? 1.0 : -1.0) * double(1 + g() % 3);
    const double x0 = double(g() % 9) - 4, y0 = double(g() % 9) - 4, dx = double(g() % 5), dy = double(g() % 5);
    // Corners drawn at (x0, y0) and (x0 + dx, y0 + dy) on the side of s.
    check(P, Point(s, s * x0, s * y0), Point(s, s * (x0 + dx), s * (y0 + dy)));
  }
}

TEST(Hidden, UndefinedCorners) {
  const std::vector<Point> P = {Point::cartesian(1, 1), Point(-1, -1, -1), Point::at_infinity(1, 1)};
  EXPECT_THROW(ex15::count(P, Point::cartesian(0, 0), Point(-1, -2, -2)), t2::Undefined);
  EXPECT_THROW(ex15::count(P, Point::cartesian(0, 0), Point::at_infinity(1, 1)), t2::Undefined);
  EXPECT_THROW(ex15::dominance(P, Point::at_infinity(0, -1), true, true), t2::Undefined);
  EXPECT_EQ(ex15::count(P, Point(-1, 0, 0), Point(-1, -2, -2)), 1);
  EXPECT_EQ(ex15::dominance(P, Point::cartesian(2, 2), false, false), 1);
}

}  // namespace
