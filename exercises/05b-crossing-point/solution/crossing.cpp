// Exercise 05b, reference solution. The lines ab and cd are L = a × b and M = c × d; when they
// differ (L × M ≠ 0) they share exactly the antipodal pair ±x, x = L × M. A point y of the line
// ab is on the segment ab iff y = αa + βb with α, β ≥ 0, and Cramer's rule gives
// α |L|² = (y × b)·L and β |L|² = (a × y)·L. So: try y = x and y = ¬x, return the one on both
// segments, or throw. Everything in big integers: the answer is exact.
#include "crossing.hpp"

#include <t2/kernel/error.hpp>
#include <t2/kernel/number.hpp>

namespace ex05b {

namespace {

struct V {
  t2::Integer w, x, y;
};

V vec(const t2::Point& p) {
  const t2::ExactPoint e = t2::to_exact(p);
  return {e.w(), e.x(), e.y()};
}
V cross(const V& p, const V& q) {
  return {p.x * q.y - p.y * q.x, p.y * q.w - p.w * q.y, p.w * q.x - p.x * q.w};
}
t2::Integer dot(const V& p, const V& q) { return p.w * q.w + p.x * q.x + p.y * q.y; }
bool zero(const V& p) { return p.w == 0 && p.x == 0 && p.y == 0; }

// y (on the line of p and q) is on the closed segment pq.
bool on_segment(const V& p, const V& q, const V& y) {
  const V L = cross(p, q);
  return dot(cross(y, q), L) >= 0 && dot(cross(p, y), L) >= 0;
}

}  // namespace

t2::ExactPoint crossing(const t2::Point& a, const t2::Point& b, const t2::Point& c, const t2::Point& d) {
  const V A = vec(a), B = vec(b), C = vec(c), D = vec(d);
  const V x = cross(cross(A, B), cross(C, D));
  if (zero(x)) throw t2::Undefined("crossing(a, b, c, d): the four points are on one line");
  for (const V& y : {x, V{-x.w, -x.x, -x.y}})
    if (on_segment(A, B, y) && on_segment(C, D, y)) return t2::ExactPoint(y.w, y.x, y.y);
  throw t2::Undefined("crossing(a, b, c, d): the segments do not meet");
}

}  // namespace ex05b
