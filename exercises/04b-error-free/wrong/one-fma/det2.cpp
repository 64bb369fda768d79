// Wrong on purpose: one fused multiply-add, fma(a, d, −fl(b·c)), keeps a·d exact but rounds
// b·c first: when a·d = b·c exactly it returns the rounding error of b·c instead of 0, and when
// they differ by less than that error its sign may be wrong.
#include "det2.hpp"

#include <cmath>

namespace ex04b {

t2::Sign det2_sign(double a, double b, double c, double d) {
  const double v = std::fma(a, d, -(b * c));
  return v > 0 ? t2::POSITIVE : (v < 0 ? t2::NEGATIVE : t2::ZERO);
}

}  // namespace ex04b
