// Wrong on purpose: T¹ read as the real line. It compares the numbers x/w (with ±∞ for w = 0)
// and never notices the back copy: the back 3 = [-1, -3] is taken for the front 3.
#include "order.hpp"

#include <cmath>

namespace ex01b {

t2::Sign compare(double aw, double ax, double bw, double bx) {
  const double a = aw == 0 ? (ax > 0 ? INFINITY : -INFINITY) : ax / aw;
  const double b = bw == 0 ? (bx > 0 ? INFINITY : -INFINITY) : bx / bw;
  return a < b ? t2::NEGATIVE : (a > b ? t2::POSITIVE : t2::ZERO);
}

}  // namespace ex01b
