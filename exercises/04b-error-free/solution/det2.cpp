// Exercise 04b, reference solution. Error-free transformations (chapter 04, section 5):
// p = fl(a·d) and e = fma(a, d, −p) give a·d = p + e exactly (no underflow in the allowed
// range), likewise b·c = q + f, so a·d − b·c = p − q + e − f exactly: a sum of four doubles.
// Adding them one at a time into a nonoverlapping expansion with TwoSum (Shewchuk's
// Grow-Expansion) keeps the sum exact; the sign of a nonoverlapping expansion is the sign of
// its largest nonzero component, the last one.
#include "det2.hpp"

#include <cmath>

namespace ex04b {

namespace {

// x + y = a + b exactly, x = fl(a + b) (Knuth's TwoSum: no precondition on the magnitudes).
void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double bv = x - a, av = x - bv;
  y = (a - av) + (b - bv);
}

}  // namespace

t2::Sign det2_sign(double a, double b, double c, double d) {
  const double p = a * d, e = std::fma(a, d, -p);
  const double q = b * c, f = std::fma(b, c, -q);
  const double terms[4] = {e, -f, p, -q};
  double h[5];
  int n = 0;
  for (const double t : terms) {  // Grow-Expansion: h stays nonoverlapping, smallest first
    double carry = t;
    for (int i = 0; i < n; ++i) two_sum(carry, h[i], carry, h[i]);
    h[n++] = carry;
  }
  for (int i = n - 1; i >= 0; --i)
    if (h[i] != 0) return h[i] > 0 ? t2::POSITIVE : t2::NEGATIVE;
  return t2::ZERO;
}

}  // namespace ex04b
