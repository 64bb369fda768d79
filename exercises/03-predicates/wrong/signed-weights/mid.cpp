// Wrong on purpose: w_q p + w_p q, forgetting the absolute values: two back points give a
// front point, and a front and a back point give a proper point instead of one on Ω.
#include "mid.hpp"

namespace ex03 {

t2::ExactPoint midpoint(const t2::ExactPoint& p, const t2::ExactPoint& q) {
  if (p == q) return p;
  return t2::ExactPoint(q.w() * p.w() + p.w() * q.w(), q.w() * p.x() + p.w() * q.x(), q.w() * p.y() + p.w() * q.y());
}

}  // namespace ex03
