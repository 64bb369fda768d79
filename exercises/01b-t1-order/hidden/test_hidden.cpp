// Exercise 01b, hidden tests. Oracle: the half of the circle by the signs of the coordinates,
// then the cross product in exact rationals.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <t2/kernel/number.hpp>

#include "order.hpp"

namespace {

int oracle(double aw, double ax, double bw, double bx) {
  auto upper = [](double w, double x) { return x > 0 || (x == 0 && w > 0); };
  if (upper(aw, ax) != upper(bw, bx)) return upper(aw, ax) ? -1 : 1;
  const t2::Rational c = t2::to_rational(aw) * t2::to_rational(bx) - t2::to_rational(ax) * t2::to_rational(bw);
  return -sgn(c);
}

void check(double aw, double ax, double bw, double bx) {
  ASSERT_EQ(static_cast<int>(ex01b::compare(aw, ax, bw, bx)), oracle(aw, ax, bw, bx))
      << "[" << aw << ", " << ax << "] vs [" << bw << ", " << bx << "]";
}

TEST(Hidden, TheBackCopyComesAfterPlusInfinity) {
  check(0, 1, -1, 5);    // +inf before the back copy
  check(-1, 5, -1, 0);   // the back copy runs from its -inf side to its +inf side
  check(-1, -5, 0, -1);  // then -inf
  check(0, -1, 1, -5);   // then the negative front numbers
  check(1, -5, 1, -1);
  check(-2, -6, -1, -3);  // one point
}

TEST(Hidden, AgreesWithOracle) {
  std::mt19937_64 rng(13);
  std::uniform_int_distribution<int> c(-4, 4);
  for (int i = 0; i < 4000; ++i) {
    const double aw = c(rng), ax = c(rng), bw = c(rng), bx = c(rng);
    if ((aw == 0 && ax == 0) || (bw == 0 && bx == 0)) continue;
    check(aw, ax, bw, bx);
  }
}

TEST(Hidden, NearlyEqualDirections) {
  // b is a rounded multiple of a, or a moved by a few units in the last place: the same point,
  // or one a tiny angle before or after it. Also on the back copy and near infinity.
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-1, 1), f(0.1, 10);
  std::uniform_int_distribution<int> ulps(-2, 2);
  for (int i = 0; i < 3000; ++i) {
    double aw = u(rng), ax = u(rng);
    if (i % 3 == 0) aw *= 1e-12;  // near ±inf
    const double s = i % 2 ? f(rng) : -f(rng);
    double bw = s * aw, bx = s * ax;  // rounded: the same direction or a neighbour of it (s < 0: nearly antipodal)
    for (int k = ulps(rng); k != 0; k += k > 0 ? -1 : 1) bx = std::nextafter(bx, k > 0 ? 100.0 : -100.0);
    check(aw, ax, bw, bx);
    check(aw, ax, -bw, -bx);  // ¬b, nearly a again when s < 0
  }
}

}  // namespace
