// Exercise 02, reference solution. The segment pq is the set of points αp + βq with α, β ≥ 0
// (not both zero). For r on the line of p and q, with n = p × q, Cramer's rule gives
// α |n|² = (r × q)·n and β |n|² = (p × r)·n, so r is on the segment iff both dot products are
// ≥ 0: two polynomials of degree 4, whose signs t2::sign_of_poly computes exactly. When p = q,
// p × q = 0 and the segment is the one point p.
#include "segments.hpp"

#include <t2/kernel/filter.hpp>
#include <t2/kernel/orient.hpp>

namespace ex02 {

Shape shape(const t2::Point& p, const t2::Point& q) {
  if (p == t2::antipode(q)) throw t2::Undefined("segment(p, q) is undefined when q = antipode(p)");
  if (p == q) return Shape::point;
  const int a = p.w() > 0 ? 1 : (p.w() < 0 ? -1 : 0), b = q.w() > 0 ? 1 : (q.w() < 0 ? -1 : 0);
  if (a == 0 && b == 0) return Shape::at_infinity;
  if (a == 0 || b == 0) return a + b > 0 ? Shape::ray_front : Shape::ray_back;
  if (a != b) return Shape::two_rays;
  return a > 0 ? Shape::front : Shape::back;
}

bool contains(const t2::Point& p, const t2::Point& q, const t2::Point& r) {
  if (p == q) return r == p;  // the one-point segment (p × q = 0: Cramer's rule says nothing)
  if (t2::orient(p, q, r) != t2::ZERO) return false;
  // (u × v)·(s × t) by the Binet–Cauchy identity: (u·s)(v·t) − (u·t)(v·s).
  const auto coef = [](const auto& u0, const auto& u1, const auto& u2, const auto& v0, const auto& v1,
                       const auto& v2, const auto& s0, const auto& s1, const auto& s2, const auto& t0,
                       const auto& t1, const auto& t2_) {
    const auto us = u0 * s0 + u1 * s1 + u2 * s2, vt = v0 * t0 + v1 * t1 + v2 * t2_;
    const auto ut = u0 * t0 + u1 * t1 + u2 * t2_, vs = v0 * s0 + v1 * s1 + v2 * s2;
    return us * vt - ut * vs;
  };
  // α: (r × q)·(p × q);  β: (p × r)·(p × q).
  const t2::Sign alpha = t2::sign_of_poly(coef, r.w(), r.x(), r.y(), q.w(), q.x(), q.y(), p.w(), p.x(),
                                          p.y(), q.w(), q.x(), q.y());
  const t2::Sign beta = t2::sign_of_poly(coef, p.w(), p.x(), p.y(), r.w(), r.x(), r.y(), p.w(), p.x(),
                                         p.y(), q.w(), q.x(), q.y());
  return alpha >= 0 && beta >= 0;
}

}  // namespace ex02
