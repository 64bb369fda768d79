// Exercise 02b, hidden tests. Oracle, in exact rationals and by another route: the points
// r(t) = (1 − t)p + t·q, t ∈ [0, 1], sweep the segment (they are the cone αp + βq up to a
// positive factor); l·r(t) is linear in t, so the kept part is an interval [t0, t1] of [0, 1].
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include <t2/kernel/number.hpp>
#include <t2/kernel/point.hpp>

#include "clip.hpp"

namespace {

using t2::Point;
using t2::Rational;
using R3 = std::array<Rational, 3>;

R3 vec(const Point& p) { return {t2::to_rational(p.w()), t2::to_rational(p.x()), t2::to_rational(p.y())}; }
R3 at(const R3& p, const R3& q, const Rational& t) {
  return {(1 - t) * p[0] + t * q[0], (1 - t) * p[1] + t * q[1], (1 - t) * p[2] + t * q[2]};
}
bool same(const R3& a, const R3& b) {
  return a[0] * b[1] == a[1] * b[0] && a[0] * b[2] == a[2] * b[0] && a[1] * b[2] == a[2] * b[1] &&
         a[0] * b[0] + a[1] * b[1] + a[2] * b[2] > 0;
}

std::vector<R3> oracle(const Point& p, const Point& q, double W, double X, double Y) {
  const R3 P = vec(p), Q = vec(q), L = vec(Point(W, X, Y));
  const Rational s = L[0] * P[0] + L[1] * P[1] + L[2] * P[2], t = L[0] * Q[0] + L[1] * Q[1] + L[2] * Q[2];
  // l·r(τ) = s + τ(t − s) ≥ 0 on [0, 1].
  Rational t0 = 0, t1 = 1;
  if (t != s) {
    const Rational root = s / (s - t);
    if (t > s) t0 = std::max(t0, root);
    else t1 = std::min(t1, root);
  } else if (s < 0) {
    return {};
  }
  if (t0 > t1) return {};
  const R3 a = at(P, Q, t0), b = at(P, Q, t1);
  if (same(a, b)) return {a};
  return {a, b};
}

void check(const Point& p, const Point& q, double W, double X, double Y) {
  const auto want = oracle(p, q, W, X, Y);
  const auto got = ex02b::clip(p, q, W, X, Y);
  ASSERT_EQ(got.size(), want.size()) << t2::to_string(p) << " " << t2::to_string(q) << " <" << W << ", " << X
                                     << ", " << Y << ">";
  for (std::size_t i = 0; i < got.size(); ++i) {
    const R3 g = {Rational(got[i].w()), Rational(got[i].x()), Rational(got[i].y())};
    EXPECT_TRUE(same(g, want[i])) << t2::to_string(p) << " " << t2::to_string(q) << " end " << i << " is "
                                  << t2::to_string(got[i]);
  }
}

bool antipodal(const Point& p, const Point& q) { return same(vec(p), vec(Point(-q.w(), -q.x(), -q.y()))); }

void random_cases(int seed, int n, int wmin) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> c(-4, 4), w(wmin, 3);
  for (int i = 0; i < n; ++i) {
    const double pw = w(rng), px = c(rng), py = c(rng), qw = w(rng), qx = c(rng), qy = c(rng);
    const double W = c(rng), X = c(rng), Y = c(rng);
    if ((pw == 0 && px == 0 && py == 0) || (qw == 0 && qx == 0 && qy == 0) || (W == 0 && X == 0 && Y == 0)) continue;
    const Point p(pw, px, py), q(qw, qx, qy);
    if (antipodal(p, q)) continue;
    check(p, q, W, X, Y);
    if (::testing::Test::HasFailure()) return;
  }
}

TEST(Hidden, FrontSegmentsAgreeWithOracle) { random_cases(3, 3000, 1); }

TEST(Hidden, EndsOnBothSides) {
  // Chapter 01's perspective: after the map, a is in front, b behind the eye; keep the front.
  check(Point(-1, -1, -1), Point(2, -1, 2), 1, 0, 0);
  random_cases(5, 3000, -3);
}

TEST(Hidden, OnePointAndTouching) {
  check(Point(2, 2, 2), Point(1, 1, 1), 1, 0, 0);
  check(Point(-2, 2, 2), Point(-1, 1, 1), 1, 0, 0);
  check(Point(0, 1, 0), Point(-1, 0, 3), 1, 0, 0);  // touches Ω at p only
  check(Point(-1, 0, 3), Point(0, 1, 1), 1, 0, 0);
  check(Point(1, 0, 0), Point(1, 2, 0), 0, 0, 1);   // along the line y = 0: all of it
}

TEST(Hidden, NearlyOnTheLine) {
  // The ends are rounded points of the line x + y = 1.3, moved a few ulps: on the line, just on
  // its positive or just on its negative side.
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-5, 5);
  std::uniform_int_distribution<int> ulps(-3, 3);
  for (int i = 0; i < 1000; ++i) {
    const double x = u(rng);
    double y = 1.3 - x;
    for (int k = ulps(rng); k != 0; k += k > 0 ? -1 : 1) y = std::nextafter(y, k > 0 ? 10.0 : -10.0);
    const Point p(1, x, y), q(i % 2 ? 1.0 : -1.0, u(rng), u(rng));
    if (antipodal(p, q)) continue;
    check(p, q, -1.3, 1, 1);
    check(q, p, -1.3, 1, 1);
  }
}

}  // namespace
