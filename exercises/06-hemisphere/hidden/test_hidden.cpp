// Exercise 06, hidden tests. Oracle: the exact certificates of certificate.hpp (a line positive
// on every point, or a vanishing non-negative combination of 2 to 4 of them, checked in big
// integers; by Gordan's theorem only one can exist, so a checked answer is right whatever
// algorithm found it). Inputs: images of front sets under integer projective maps of positive
// determinant (on both sides and on Ω, still in an open hemisphere), sets with an antipode
// added, sets that only touch a closed hemisphere (a line's points all round it, Ω all round,
// the antipode of a point inside a triangle), and points a few units in the last place off a
// line.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include <t2/kernel/orient.hpp>
#include <t2/kernel/point.hpp>

#include "certificate.hpp"
#include "hemisphere.hpp"

namespace {

using ex06test::Expect;
using ex06test::judge;
using t2::Point;

using M3 = std::array<std::array<double, 3>, 3>;

// A random integer matrix with entries in [-3, 3] and a positive determinant.
M3 positive_map(std::mt19937_64& g) {
  std::uniform_int_distribution<int> d(-3, 3);
  for (;;) {
    M3 m;
    for (auto& r : m)
      for (auto& e : r) e = d(g);
    const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                       m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    if (det > 0) return m;
  }
}

// M p, exact: small integers.
Point apply(const M3& m, const Point& p) {
  auto row = [&](int i) { return m[i][0] * p.w() + m[i][1] * p.x() + m[i][2] * p.y(); };
  return Point(row(0), row(1), row(2));
}

std::vector<Point> front_set(std::mt19937_64& g, int n, int range) {
  std::uniform_int_distribution<int> d(-range, range);
  std::vector<Point> P;
  for (int k = 0; k < n; ++k) P.push_back(Point::cartesian(d(g), d(g)));
  return P;
}

// αp + βq + γr, exact: small integers.
Point comb(double al, const Point& p, double be, const Point& q, double ga, const Point& r) {
  return Point(al * p.w() + be * q.w() + ga * r.w(), al * p.x() + be * q.x() + ga * r.x(),
               al * p.y() + be * q.y() + ga * r.y());
}

std::vector<Point> image(const M3& m, const std::vector<Point>& P) {
  std::vector<Point> Q;
  for (const Point& p : P) Q.push_back(apply(m, p));
  return Q;
}

TEST(Hidden, BothSidesAndInfinity) {
  std::mt19937_64 g(6);
  int mixed = 0, at_infinity = 0;
  for (int round = 0; round < 60; ++round) {
    const std::vector<Point> Q = image(positive_map(g), front_set(g, 5 + round * 5, 6));
    bool front = false, back = false;
    for (const Point& q : Q) {
      front = front || q.w() > 0;
      back = back || q.w() < 0;
      at_infinity += q.w() == 0;
    }
    mixed += front && back;
    EXPECT_EQ(judge(Q, Expect::hemisphere), "") << "round " << round;
  }
  EXPECT_GT(mixed, 20);
  EXPECT_GT(at_infinity, 20);
  // Points of Ω only, spread over less than half of it, with a back point.
  EXPECT_EQ(judge({Point(0, 1, 0), Point(0, 1, 5), Point(0, -1, 5), Point(0, 0, 1), Point(-1, 0, 7)}, Expect::hemisphere),
            "");
}

TEST(Hidden, AntipodalPairs) {
  std::mt19937_64 g(66);
  EXPECT_EQ(judge({Point(0, 1, 2), Point(0, -2, -4)}, Expect::none), "") << "two opposite points of Ω";
  EXPECT_EQ(judge({Point(-3, 1, 2), Point(6, -2, -4)}, Expect::none), "") << "a back point and its antipode";
  for (int round = 0; round < 40; ++round) {
    std::vector<Point> Q = image(positive_map(g), front_set(g, 10 + round, 6));
    const Point& p = Q[g() % Q.size()];
    const double s = (round % 2) ? -2.0 : -0.5;  // a negative multiple: the antipode, scaled
    Q.insert(Q.begin() + static_cast<long>(g() % Q.size()), Point(s * p.w(), s * p.x(), s * p.y()));
    EXPECT_EQ(judge(Q, Expect::none), "") << "round " << round;
  }
}

TEST(Hidden, ClosedHemisphereOnly) {
  std::mt19937_64 g(666);
  // Three directions all round Ω, and front points.
  EXPECT_EQ(judge({Point::cartesian(1, 1), Point(0, 1, 0), Point(0, -1, 2), Point::cartesian(3, -2), Point(0, -1, -2)},
                  Expect::none),
            "");
  for (int round = 0; round < 40; ++round) {
    const M3 m = positive_map(g);
    std::uniform_int_distribution<int> c(1, 4);
    const std::vector<Point> F = front_set(g, 3, 8);
    std::vector<Point> S;
    if (round % 2 == 0) {
      // Points a, b of a line, the antipode of a point between them, and points on one side of
      // the line: all in the closed half-plane, none in an open hemisphere.
      const Point &a = F[0], &b = F[1];
      const double al = c(g), be = c(g);
      S = {a, b, t2::antipode(comb(al, a, be, b, 0, b))};
      const double lw = a.x() * b.y() - a.y() * b.x(), lx = a.y() * b.w() - a.w() * b.y(),
                   ly = a.w() * b.x() - a.x() * b.w();  // the line a × b
      for (const Point& p : front_set(g, 20, 8))
        if (lw * p.w() + lx * p.x() + ly * p.y() > 0) S.push_back(p);
    } else {
      // The antipode of a point inside a triangle, among points of the triangle.
      if (t2::orient(F[0], F[1], F[2]) == t2::ZERO) continue;
      const double al = c(g), be = c(g), ga = c(g);
      S = {F[0], F[1], F[2], t2::antipode(comb(al, F[0], be, F[1], ga, F[2]))};
      for (int k = 0; k < 10; ++k) S.push_back(comb(c(g), F[0], c(g), F[1], c(g), F[2]));
    }
    std::shuffle(S.begin(), S.end(), g);
    EXPECT_EQ(judge(image(m, S), Expect::none), "") << "round " << round;
  }
}

// A front segment ab far from the origin (on a grid of 1/64, so that its midpoint is a double),
// and the back point drawn at the midpoint moved by up to two units in the last place: on the
// segment exactly (no hemisphere) or a few ulps off it (a thin triangle, which has one). Only
// exact signs tell: the determinant in doubles is all rounding error here.
TEST(Hidden, NearlyDegenerate) {
  std::mt19937_64 g(6666);
  std::uniform_int_distribution<int> u(-640, 640);
  int none = 0, some = 0;
  for (int round = 0; round < 400; ++round) {
    const double ax = 1000 + u(g) / 64.0, ay = 2000 + u(g) / 64.0, bx = 1000 + u(g) / 64.0, by = 2000 + u(g) / 64.0;
    if (ax == bx && ay == by) continue;
    const double mx = (ax + bx) / 2;
    double my = (ay + by) / 2;
    for (int k = static_cast<int>(g() % 5) - 2; k != 0; k += k > 0 ? -1 : 1) my = std::nextafter(my, k > 0 ? 9e9 : -9e9);
    const std::vector<Point> T = {Point::cartesian(ax, ay), Point::cartesian(bx, by), Point(-1, -mx, -my)};
    const bool on = t2::orient(T[0], T[1], T[2]) == t2::ZERO;
    none += on;
    some += !on;
    EXPECT_EQ(judge(T, on ? Expect::none : Expect::hemisphere), "") << "round " << round;
  }
  EXPECT_GT(none, 20);
  EXPECT_GT(some, 20);
}

}  // namespace
