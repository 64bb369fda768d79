// Wrong on purpose: the Euclidean segment. Treats w = 0 as the front (no rays), never notices
// antipodes, and tests "between" on Cartesian coordinates, so the segment through infinity
// (two rays) looks like the finite segment between the two Cartesian points.
#include <algorithm>

#include "segments.hpp"

#include <t2/kernel/orient.hpp>

namespace ex02 {

Shape shape(const t2::Point& p, const t2::Point& q) {
  const bool a = p.w() >= 0, b = q.w() >= 0;
  if (a != b) return Shape::two_rays;
  return a ? Shape::front : Shape::back;
}

bool contains(const t2::Point& p, const t2::Point& q, const t2::Point& r) {
  if (p.w() == 0 || q.w() == 0 || r.w() == 0) return false;
  if (t2::orient(t2::Point(1, p.x() / p.w(), p.y() / p.w()), t2::Point(1, q.x() / q.w(), q.y() / q.w()),
                 t2::Point(1, r.x() / r.w(), r.y() / r.w())) != t2::ZERO)
    return false;
  const double px = p.x() / p.w(), qx = q.x() / q.w(), rx = r.x() / r.w();
  const double py = p.y() / p.w(), qy = q.y() / q.w(), ry = r.y() / r.w();
  return std::min(px, qx) <= rx && rx <= std::max(px, qx) && std::min(py, qy) <= ry && ry <= std::max(py, qy);
}

}  // namespace ex02
