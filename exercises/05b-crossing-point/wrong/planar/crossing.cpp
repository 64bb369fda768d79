// Wrong on purpose: the right algorithm on the planar drawing. Every point is replaced by the
// front point drawn at the same place (a back point by its antipode), so a segment from the
// front to the back is taken for the finite segment between the two drawn points, and points
// at infinity are refused.
#include "crossing.hpp"

#include <t2/kernel/error.hpp>
#include <t2/kernel/number.hpp>

namespace ex05b {

namespace {

struct V {
  t2::Integer w, x, y;
};
V vec(const t2::Point& p) {
  if (p.w() == 0) throw t2::Undefined("a point at infinity is not in the plane");
  const t2::ExactPoint e = t2::to_exact(p.w() > 0 ? p : t2::Point(-p.w(), -p.x(), -p.y()));
  return {e.w(), e.x(), e.y()};
}
V cross(const V& p, const V& q) { return {p.x * q.y - p.y * q.x, p.y * q.w - p.w * q.y, p.w * q.x - p.x * q.w}; }
t2::Integer dot(const V& p, const V& q) { return p.w * q.w + p.x * q.x + p.y * q.y; }
bool on_segment(const V& p, const V& q, const V& y) {
  const V L = cross(p, q);
  return dot(cross(y, q), L) >= 0 && dot(cross(p, y), L) >= 0;
}

}  // namespace

t2::ExactPoint crossing(const t2::Point& a, const t2::Point& b, const t2::Point& c, const t2::Point& d) {
  const V A = vec(a), B = vec(b), C = vec(c), D = vec(d);
  const V x = cross(cross(A, B), cross(C, D));
  if (x.w == 0 && x.x == 0 && x.y == 0) throw t2::Undefined("one line");
  for (const V& y : {x, V{-x.w, -x.x, -x.y}})
    if (on_segment(A, B, y) && on_segment(C, D, y)) return t2::ExactPoint(y.w, y.x, y.y);
  throw t2::Undefined("the segments do not meet");
}

}  // namespace ex05b
