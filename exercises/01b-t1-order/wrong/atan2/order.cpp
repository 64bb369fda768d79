// Wrong on purpose: the angle in floating point. atan2 rounds, so two directions a few units in
// the last place apart get the same angle (ZERO) or angles in the wrong order.
#include "order.hpp"

#include <cmath>

namespace ex01b {

t2::Sign compare(double aw, double ax, double bw, double bx) {
  const double two_pi = 2 * std::acos(-1.0);
  double ta = std::atan2(ax, aw), tb = std::atan2(bx, bw);
  if (ta < 0) ta += two_pi;
  if (tb < 0) tb += two_pi;
  return ta < tb ? t2::NEGATIVE : (ta > tb ? t2::POSITIVE : t2::ZERO);
}

}  // namespace ex01b
