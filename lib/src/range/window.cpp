// Exact bounds of a query window (window.hpp).
#include "window.hpp"

#include <cmath>
#include <limits>

namespace t2::range {
namespace {

// The largest double ≤ q (−inf when there is none, i.e. q < −DBL_MAX).
double floor_double(const Rational& q) {
  const double big = std::numeric_limits<double>::max(), inf = std::numeric_limits<double>::infinity();
  double d = q.get_d();  // truncated towards zero: within one step of the answer
  if (std::isinf(d)) d = std::copysign(big, d);
  while (cmp(to_rational(d), q) > 0) {
    if (d == -big) return -inf;
    d = std::nextafter(d, -inf);
  }
  for (double up = std::nextafter(d, inf); !std::isinf(up) && cmp(to_rational(up), q) <= 0; up = std::nextafter(d, inf))
    d = up;
  return d;
}

// The value X / W as a double when it is one: W = 2^e and X of at most 53 significant bits, as
// every bound of a rectangle with double corners is (to_exact scales by powers of two). Spares
// the rationals of floor_double, which a query of a few microseconds would feel.
bool dyadic(const Integer& X, const Integer& W, double& out) {
  const mp_bitcnt_t e = mpz_scan1(W.get_mpz_t(), 0);
  if (mpz_sizeinbase(W.get_mpz_t(), 2) != e + 1) return false;  // W is no power of two
  if (sgn(X) == 0) return out = 0, true;
  if (mpz_sizeinbase(X.get_mpz_t(), 2) - mpz_scan1(X.get_mpz_t(), 0) > 53 || e > 1000) return false;
  const double x = mpz_get_d(X.get_mpz_t());  // exact: 53 significant bits at most
  out = std::ldexp(x, -static_cast<int>(e));
  return std::ldexp(out, static_cast<int>(e)) == x;  // no underflow
}

}  // namespace

Bound::Bound(const ExactT1& v) : v_(v) {
  const double inf = std::numeric_limits<double>::infinity();
  if (v.w() == 0) {
    floor_ = ceil_ = v.x() > 0 ? inf : -inf;
    return;
  }
  if (dyadic(v.x(), v.w(), floor_)) {
    ceil_ = floor_;
    return;
  }
  Rational q(v.x(), v.w());
  q.canonicalize();
  floor_ = floor_double(q);
  ceil_ = -floor_double(-q);
}

// bound ≤ x/w: decided by the neighbours ⌈B⌉ ≤ x/w (yes) or x/w < ⌊B⌋ (no), else exactly.
bool Bound::slow_at_most(double x, double w) const {
  if (v_.w() == 0) return v_.x() < 0;
  const T1 p(w, x);
  if (!std::isinf(ceil_) && compare(T1(1, ceil_), p) <= 0) return true;
  if (!std::isinf(floor_) && compare(p, T1(1, floor_)) < 0) return false;
  return compare(v_, to_exact(p)) <= 0;
}

// x/w ≤ bound: yes when x/w ≤ ⌊B⌋, no when x/w > ⌈B⌉, else exactly.
bool Bound::slow_at_least(double x, double w) const {
  if (v_.w() == 0) return v_.x() > 0;
  const T1 p(w, x);
  if (!std::isinf(floor_) && compare(p, T1(1, floor_)) <= 0) return true;
  if (!std::isinf(ceil_) && compare(T1(1, ceil_), p) < 0) return false;
  return compare(to_exact(p), v_) <= 0;
}

Window::Window(const ExactBBox& b)
    : side(b.side() == Side::front ? 0 : 1),
      lo{Bound(b.xmin()), Bound(b.ymin())},
      hi{Bound(b.xmax()), Bound(b.ymax())} {}

}  // namespace t2::range
