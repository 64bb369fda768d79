// Wrong on purpose: the tolerance habit. |det| < 1e-9 counts as "collinear", which is wrong
// for small but honest triangles, and still rounds for the nearly collinear ones.
#include <cmath>

#include "exact_orient.hpp"

namespace ex04 {

t2::Sign orient_exact(const t2::Point& p, const t2::Point& q, const t2::Point& r) {
  const double d = p.w() * (q.x() * r.y() - q.y() * r.x()) - p.x() * (q.w() * r.y() - q.y() * r.w()) +
                   p.y() * (q.w() * r.x() - q.x() * r.w());
  if (std::fabs(d) < 1e-9) return t2::ZERO;
  return d > 0 ? t2::POSITIVE : t2::NEGATIVE;
}

}  // namespace ex04
