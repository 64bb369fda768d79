// Wrong on purpose: the right halves and the right cross product, but the cross product is
// evaluated in doubles, so nearly equal directions get the sign of a rounding error or 0.
#include "order.hpp"

namespace ex01b {

t2::Sign compare(double aw, double ax, double bw, double bx) {
  const int ha = (ax > 0 || (ax == 0 && aw > 0)) ? 0 : 1, hb = (bx > 0 || (bx == 0 && bw > 0)) ? 0 : 1;
  if (ha != hb) return ha < hb ? t2::NEGATIVE : t2::POSITIVE;
  const double c = aw * bx - ax * bw;
  return c > 0 ? t2::NEGATIVE : (c < 0 ? t2::POSITIVE : t2::ZERO);
}

}  // namespace ex01b
