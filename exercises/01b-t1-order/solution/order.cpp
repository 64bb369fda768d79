// Exercise 01b, reference solution. The vector (w, x) lies in the upper half [0, π) when x > 0,
// or x = 0 and w > 0; in the lower half [π, 2π) otherwise. Points of different halves compare
// by their half. In the same half, b comes after a exactly when it is counter-clockwise from a,
// i.e. when the cross product aw·bx − ax·bw is positive; within one half that is an angle
// smaller than π, so the sign of the cross product orders them. Its sign is computed exactly
// with t2::sign_of_poly (a filter, then big integers when the doubles cannot tell).
#include "order.hpp"

#include <t2/kernel/filter.hpp>

namespace ex01b {

namespace {

int half(double w, double x) { return (x > 0 || (x == 0 && w > 0)) ? 0 : 1; }

}  // namespace

t2::Sign compare(double aw, double ax, double bw, double bx) {
  const int ha = half(aw, ax), hb = half(bw, bx);
  if (ha != hb) return ha < hb ? t2::NEGATIVE : t2::POSITIVE;
  const auto cross = [](const auto& p, const auto& q, const auto& r, const auto& s) { return p * s - q * r; };
  return -t2::sign_of_poly(cross, aw, ax, bw, bx);
}

}  // namespace ex01b
