// Wrong on purpose: (X0 + X1)/2 with X = x/w, written in homogeneous coordinates, i.e.
// [2 w0 w1, x0 w1 + x1 w0, y0 w1 + y1 w0]. Right for two front points only.
#include "mid.hpp"

namespace ex03 {

t2::ExactPoint midpoint(const t2::ExactPoint& p, const t2::ExactPoint& q) {
  return t2::ExactPoint(2 * p.w() * q.w(), p.x() * q.w() + q.x() * p.w(), p.y() * q.w() + q.y() * p.w());
}

}  // namespace ex03
