// Exercise 11, reference solution: chapter 11's one formula. The row of a site (ρ, wx, wy, w²),
// ρ = x² + y², divided by w² > 0, is the lifted drawn position, so the null vector (A, B, C, D)
// of the three rows, by signed minors, is the circle through the drawn positions, centre
// (−B/2A, −C/2A). A = w_a w_b w_c · orient(a, b, c), so [2A, −B, −C] is on the sites' side exactly
// when orient(a, b, c) > 0. All in integers (to_exact): no division, no rounding.
#include "vertex.hpp"

#include <t2/kernel/error.hpp>
#include <t2/kernel/lexicographic.hpp>
#include <t2/kernel/orient.hpp>

namespace ex11 {

namespace {

using t2::Integer;

Integer det3(const Integer& a, const Integer& b, const Integer& c, const Integer& d, const Integer& e,
             const Integer& f, const Integer& g, const Integer& h, const Integer& i) {
  return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
}

int side(const t2::Point& p) { return p.w() > 0 ? 1 : p.w() < 0 ? -1 : 0; }

}  // namespace

t2::ExactPoint voronoi_vertex(const t2::Point& a, const t2::Point& b, const t2::Point& c) {
  const t2::Point* v[3] = {&a, &b, &c};
  const t2::ExactPoint e[3] = {t2::to_exact(a), t2::to_exact(b), t2::to_exact(c)};
  const bool one_side = side(a) != 0 && side(a) == side(b) && side(b) == side(c);
  if (one_side && t2::orient(a, b, c) != t2::ZERO) {
    Integer P[3], X[3], Y[3], W[3];
    for (int i = 0; i < 3; ++i) {
      P[i] = e[i].x() * e[i].x() + e[i].y() * e[i].y();
      X[i] = e[i].w() * e[i].x();
      Y[i] = e[i].w() * e[i].y();
      W[i] = e[i].w() * e[i].w();
    }
    const Integer A = det3(X[0], Y[0], W[0], X[1], Y[1], W[1], X[2], Y[2], W[2]);
    const Integer B = -det3(P[0], Y[0], W[0], P[1], Y[1], W[1], P[2], Y[2], W[2]);
    const Integer C = det3(P[0], X[0], W[0], P[1], X[1], W[1], P[2], X[2], W[2]);
    return t2::ExactPoint(Integer(2 * A), Integer(-B), Integer(-C));
  }
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    if (side(*v[i]) == 0 || side(*v[i]) != side(*v[j])) continue;
    if (one_side) {  // collinear: not the pair with the third strictly between its ends
      const t2::Sign s = t2::compare_xy(*v[i], *v[k]);
      if (s != t2::ZERO && s == t2::compare_xy(*v[k], *v[j])) continue;
    }
    // The pole [0, l_x, l_y] of l = p × q: (p_y q_w − p_w q_y, p_w q_x − p_x q_w) is
    // w_p w_q (−d_y, d_x), d = Q − P of the drawn positions, and w_p w_q > 0 on either side.
    const t2::ExactPoint &p = e[i], &q = e[j];
    return t2::ExactPoint(Integer(0), Integer(p.y() * q.w() - p.w() * q.y()), Integer(p.w() * q.x() - p.x() * q.w()));
  }
  throw t2::Undefined("voronoi_vertex(): no two consecutive sites are proper on one side");
}

}  // namespace ex11
