// Exercise 03, hidden tests. Oracle: rational Cartesian coordinates, case by case.
#include <gtest/gtest.h>

#include <random>

#include <t2/kernel/error.hpp>
#include <t2/kernel/number.hpp>
#include <t2/kernel/point.hpp>

#include "mid.hpp"

namespace {

using t2::ExactPoint;
using t2::Integer;
using t2::Rational;

bool same(const ExactPoint& a, const ExactPoint& b) {
  return a.w() * b.x() == a.x() * b.w() && a.w() * b.y() == a.y() * b.w() && a.x() * b.y() == a.y() * b.x() &&
         a.w() * b.w() + a.x() * b.x() + a.y() * b.y() > 0;
}

Rational frac(const Integer& n, const Integer& d) {
  Rational r(n, d);
  r.canonicalize();
  return r;
}

// The expected midpoint of p and q (defined cases only), built from rational Cartesian points.
ExactPoint expected(const ExactPoint& p, const ExactPoint& q) {
  if (same(p, q)) return p;
  if (p.w() == 0) return p;
  if (q.w() == 0) return q;
  const Rational px = frac(p.x(), p.w()), py = frac(p.y(), p.w()), qx = frac(q.x(), q.w()), qy = frac(q.y(), q.w());
  if (sgn(p.w()) == sgn(q.w())) {
    Rational mx = (px + qx) / 2, my = (py + qy) / 2;
    mx.canonicalize();
    my.canonicalize();
    const Integer d = mx.get_den() * my.get_den() * sgn(p.w());
    return ExactPoint(d, Rational(mx * d).get_num(), Rational(my * d).get_num());
  }
  // Opposite sides: the point at infinity in the direction from the back point's Cartesian
  // position to the front point's (the front ray leaves the front point away from it).
  const Rational dx = p.w() > 0 ? px - qx : qx - px, dy = p.w() > 0 ? py - qy : qy - py;
  const Integer d = dx.get_den() * dy.get_den();
  return ExactPoint(0, Rational(dx * d).get_num(), Rational(dy * d).get_num());
}

void check(const ExactPoint& p, const ExactPoint& q) {
  const ExactPoint m = ex03::midpoint(p, q), e = expected(p, q);
  EXPECT_TRUE(same(m, e)) << "midpoint(" << t2::to_string(p) << ", " << t2::to_string(q) << ") = "
                          << t2::to_string(m) << ", expected " << t2::to_string(e);
}

TEST(Hidden, BothOnTheBackSide) {
  check(ExactPoint(-1, 0, 0), ExactPoint(-1, -4, -2));
  check(ExactPoint(-2, 2, 0), ExactPoint(-3, 0, 3));
}

TEST(Hidden, OppositeSidesMeetOnOmega) {
  check(ExactPoint(1, 0, 0), ExactPoint(-1, -1, 0));
  check(ExactPoint(-5, 1, 2), ExactPoint(3, 7, -1));
}

TEST(Hidden, OneEndAtInfinity) {
  check(ExactPoint(0, 1, 2), ExactPoint(-1, 5, 5));
  check(ExactPoint(4, 1, 2), ExactPoint(0, -3, 1));
}

TEST(Hidden, EqualPointsAtInfinity) { check(ExactPoint(0, 2, -1), ExactPoint(0, 4, -2)); }

TEST(Hidden, UndefinedCases) {
  EXPECT_THROW(ex03::midpoint(ExactPoint(-1, 2, 3), ExactPoint(2, -4, -6)), t2::Undefined);
  EXPECT_THROW(ex03::midpoint(ExactPoint(0, 1, 0), ExactPoint(0, 0, 1)), t2::Undefined);
  // ... and only then: nearly antipodal ends, and one point of Ω twice, have a midpoint.
  check(ExactPoint(-1, 2, 3), ExactPoint(2, -4, -5));
  check(ExactPoint(0, 1, 0), ExactPoint(0, 3, 0));
}

TEST(Hidden, RandomAgreesWithOracle) {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> c(-6, 6);
  for (int i = 0; i < 2000; ++i) {
    const int pw = c(rng), qw = c(rng);
    if (pw == 0 && qw == 0) continue;
    const ExactPoint p(pw, c(rng), c(rng) * 2 + 1), q(qw, c(rng) * 2 + 1, c(rng));
    if (same(p, t2::antipode(q))) continue;
    check(p, q);
    if (HasFailure()) return;
  }
}

}  // namespace
