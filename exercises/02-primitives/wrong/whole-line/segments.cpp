// Wrong on purpose: shape is right, but contains() only tests that r is on the line of p and
// q, forgetting that a segment is the part of the line between them.
#include "segments.hpp"

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
  return t2::orient(p, q, r) == t2::ZERO;
}

}  // namespace ex02
