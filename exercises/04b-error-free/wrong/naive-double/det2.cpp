// Wrong on purpose: a·d − b·c in doubles. Two products that round to the same double give 0,
// and a rounding error larger than the true difference gives the wrong sign.
#include "det2.hpp"

namespace ex04b {

t2::Sign det2_sign(double a, double b, double c, double d) {
  const double v = a * d - b * c;
  return v > 0 ? t2::POSITIVE : (v < 0 ? t2::NEGATIVE : t2::ZERO);
}

}  // namespace ex04b
