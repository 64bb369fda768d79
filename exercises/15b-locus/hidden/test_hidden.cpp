// Exercise 15b, hidden tests. Oracle: bbox.hpp's `contains` on big-integer rectangles, point by
// point (brute force), on every rectangle of the small tests and on every 250th of the large
// one. Inputs: quadrants, half-strips and half-planes reaching Ω on both sides, back rectangles
// over back and front points drawn alike, extents of every sign (zero, negative, infinite), and
// 6000 points with 50000 rectangles, where counting point by point takes far longer than the
// time limit.
#include <gtest/gtest.h>

#include <random>

#include <t2/kernel/bbox.hpp>
#include <t2/kernel/isorect.hpp>
#include <t2/kernel/point.hpp>

#include "locus.hpp"

namespace {

using t2::IsoRect;
using t2::Point;
using t2::T1;

// contains() on big integers: with doubles, a + Δ would be rounded.
long brute(const std::vector<t2::ExactPoint>& P, const IsoRect& q) {
  const t2::ExactIsoRect e(t2::to_exact(q.a()), t2::to_exact(q.dx()), t2::to_exact(q.dy()));
  long n = 0;
  for (const auto& p : P) n += t2::contains(e, p);
  return n;
}

std::vector<long> brute(const std::vector<Point>& P, const std::vector<IsoRect>& R) {
  std::vector<t2::ExactPoint> E;
  for (const auto& p : P) E.push_back(t2::to_exact(p));
  std::vector<long> r;
  for (const auto& q : R) r.push_back(brute(E, q));
  return r;
}

// Points on both sides and on Ω at small integer drawn coordinates (many on the sides of the
// rectangles), with weights ≠ 1.
std::vector<Point> points(std::mt19937_64& g, int n) {
  std::vector<Point> P;
  const double w[] = {-3, -1, 0, 1, 2, 3};
  while (int(P.size()) < n) {
    const double s = w[g() % 6], x = double(g() % 11) - 5, y = double(g() % 11) - 5;
    if (s == 0 && x == 0 && y == 0) continue;
    P.push_back(Point(s, s == 0 ? x : s * x, s == 0 ? y : s * y));
  }
  return P;
}

T1 extent(std::mt19937_64& g, bool infinite) {
  if (infinite) return T1(0, g() % 2 ? 1 : -1);
  return T1(g() % 2 ? 1 : 2, double(g() % 9) - 4);
}

IsoRect rect(std::mt19937_64& g, int infinite) {  // infinite: bit 0 Δx, bit 1 Δy
  const double s = g() % 2 ? 1 : -2;
  return IsoRect(Point(s, s * (double(g() % 9) - 4), s * (double(g() % 9) - 4)), extent(g, infinite & 1),
                 extent(g, infinite & 2));
}

TEST(Hidden, QuadrantsReachOmega) {
  std::mt19937_64 g(1501);
  const auto P = points(g, 300);
  std::vector<IsoRect> R;
  for (int k = 0; k < 200; ++k) R.push_back(rect(g, 1 + k % 3));
  EXPECT_EQ(ex15b::count(P, R), brute(P, R));
}

TEST(Hidden, BackRectangles) {
  std::vector<Point> P;
  for (int x = -3; x <= 3; ++x)
    for (int y = -3; y <= 3; ++y) {
      P.push_back(Point::cartesian(x, y));
      if ((x + y) % 2 == 0) P.push_back(Point(-1, -x, -y));  // drawn at (x, y) too
    }
  std::vector<IsoRect> R;
  for (int k = -3; k <= 2; ++k) {
    R.push_back(IsoRect(Point(-1, -k, -k), T1(1, 2), T1(1, 1)));
    R.push_back(IsoRect(Point(-2, -2 * k, 0), T1(1, 1), T1(1, -3)));
    R.push_back(IsoRect(Point::cartesian(k, k), T1(1, 2), T1(1, 1)));
  }
  EXPECT_EQ(ex15b::count(P, R), brute(P, R));
}

TEST(Hidden, ExtentsOfEverySign) {
  std::mt19937_64 g(1502);
  auto P = points(g, 200);
  P.push_back(P[0]);  // repeated points count twice
  P.push_back(Point(5, 5 * P[1].x(), 5 * P[1].y()));
  std::vector<IsoRect> R;
  for (int k = 0; k < 300; ++k) R.push_back(rect(g, k % 4));
  R.push_back(IsoRect(Point(-1, 0, 0), T1(0, -1), T1(0, 1)));
  R.push_back(IsoRect(Point(3, 0, 3), T1(1, 0), T1(1, 0)));  // one point
  EXPECT_EQ(ex15b::count(P, R), brute(P, R));
}

TEST(Hidden, ManyQueries) {
  // 6000 points on both sides and on Ω with weights 3 and -7 (drawn coordinates are not
  // doubles), 50000 rectangles; counting point by point is 3·10⁸ points against rectangles.
  std::mt19937_64 g(1503);
  std::vector<Point> P;
  for (int k = 0; k < 6000; ++k) {
    const double s = k % 2 ? 3 : -7, x = double(g() % 100000), y = double(g() % 100000);
    P.push_back(k % 50 == 0 ? Point::at_infinity(x - 50000.5, y - 50000) : Point(s, s > 0 ? x : -x, s > 0 ? y : -y));
  }
  std::vector<IsoRect> R;
  for (int k = 0; k < 50000; ++k) {
    const double s = k % 2 ? 1 : -1;
    const auto d = [&](int inf) { return inf ? T1(0, g() % 2 ? 1 : -1) : T1(1, double(g() % 30000) / 3); };
    R.push_back(IsoRect(Point(s, s * double(g() % 40000) / 3, s * double(g() % 40000) / 7), d(k % 7 == 0),
                        d(k % 11 == 0)));
  }
  const auto got = ex15b::count(P, R);
  ASSERT_EQ(got.size(), R.size());
  std::vector<t2::ExactPoint> E;
  for (const auto& p : P) E.push_back(t2::to_exact(p));
  for (std::size_t k = 0; k < R.size(); k += 250) EXPECT_EQ(got[k], brute(E, R[k]));
}

}  // namespace
