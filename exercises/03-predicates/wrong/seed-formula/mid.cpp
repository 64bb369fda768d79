// Wrong on purpose: the seed's formula |w1| p0 + |w0| p1 taken literally. It is right wherever
// it yields a point, but for p = q on Ω it yields [0,0,0] (so the constructor throws) although
// the midpoint of a point with itself is that point.
#include "mid.hpp"

namespace ex03 {

t2::ExactPoint midpoint(const t2::ExactPoint& p, const t2::ExactPoint& q) {
  const t2::Integer a = abs(q.w()), b = abs(p.w());
  return t2::ExactPoint(a * p.w() + b * q.w(), a * p.x() + b * q.x(), a * p.y() + b * q.y());
}

}  // namespace ex03
