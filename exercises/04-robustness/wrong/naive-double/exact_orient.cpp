// Wrong on purpose: the determinant in double precision. Rounding gives wrong signs near
// degenerate input, and huge coordinates overflow to inf - inf = NaN.
#include "exact_orient.hpp"

namespace ex04 {

t2::Sign orient_exact(const t2::Point& p, const t2::Point& q, const t2::Point& r) {
  const double d = p.w() * (q.x() * r.y() - q.y() * r.x()) - p.x() * (q.w() * r.y() - q.y() * r.w()) +
                   p.y() * (q.w() * r.x() - q.x() * r.w());
  return d > 0 ? t2::POSITIVE : (d < 0 ? t2::NEGATIVE : t2::ZERO);
}

}  // namespace ex04
