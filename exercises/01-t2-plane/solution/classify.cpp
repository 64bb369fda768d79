// Exercise 01, reference solution. p = q in T² iff the three 2×2 minors of (p, q) vanish (the
// triples are parallel) and their dot product is positive (same direction, not opposite).
// Each sign is computed exactly with t2::sign_of_poly, so nothing is rounded.
#include "classify.hpp"

#include <t2/kernel/filter.hpp>

namespace ex01 {

Where where(const t2::Point& p) {
  if (p.w() > 0) return Where::front;
  if (p.w() < 0) return Where::back;
  return Where::infinity;
}

namespace {
// +1: q = αp with α > 0; -1: α < 0; 0: not parallel.
int parallel(const t2::Point& p, const t2::Point& q) {
  const auto minor = [](const auto& a, const auto& b, const auto& c, const auto& d) { return a * d - b * c; };
  if (t2::sign_of_poly(minor, p.w(), p.x(), q.w(), q.x()) != t2::ZERO) return 0;
  if (t2::sign_of_poly(minor, p.w(), p.y(), q.w(), q.y()) != t2::ZERO) return 0;
  if (t2::sign_of_poly(minor, p.x(), p.y(), q.x(), q.y()) != t2::ZERO) return 0;
  const auto dot = [](const auto& a, const auto& b, const auto& c, const auto& d, const auto& e,
                      const auto& f) { return a * d + b * e + c * f; };
  return t2::sign_of_poly(dot, p.w(), p.x(), p.y(), q.w(), q.x(), q.y());
}
}  // namespace

bool same_point(const t2::Point& p, const t2::Point& q) { return parallel(p, q) > 0; }
bool antipodal(const t2::Point& p, const t2::Point& q) { return parallel(p, q) < 0; }

}  // namespace ex01
