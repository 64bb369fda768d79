// Wrong on purpose: the Euclidean habit. Compares Cartesian coordinates x/w, y/w, so it cannot
// tell a back point from its antipode, and treats every point at infinity as "no point".
#include <cmath>

#include "classify.hpp"

namespace ex01 {

Where where(const t2::Point& p) {
  if (p.w() == 0) return Where::infinity;
  return p.w() > 0 ? Where::front : Where::back;
}

bool same_point(const t2::Point& p, const t2::Point& q) {
  if (p.w() == 0 || q.w() == 0) return false;
  return p.x() / p.w() == q.x() / q.w() && p.y() / p.w() == q.y() / q.w();
}

bool antipodal(const t2::Point& p, const t2::Point& q) {
  return same_point(p, t2::Point(-q.w(), -q.x(), -q.y()));
}

}  // namespace ex01
