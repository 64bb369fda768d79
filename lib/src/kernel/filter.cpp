#include "t2/kernel/filter.hpp"

#include <cmath>

namespace t2 {

Dyadic::Dyadic(double x) {
  int exp = 0;
  const double f = std::frexp(x, &exp);  // x = f·2^exp, 0.5 <= |f| < 1 (or f = 0)
  m = static_cast<long>(std::ldexp(f, 53));
  e = exp - 53;
}

Dyadic Dyadic::add(const Dyadic& a, const Dyadic& b, bool negate_b) {
  if (b.m == 0) return a;
  if (a.m == 0) return negate_b ? -b : b;
  Integer r;
  long e;
  if (a.e >= b.e) {  // a·2^(a.e-b.e) ± b, at exponent b.e
    mpz_mul_2exp(r.get_mpz_t(), a.m.get_mpz_t(), static_cast<unsigned long>(a.e - b.e));
    if (negate_b) r -= b.m; else r += b.m;
    e = b.e;
  } else {  // a ± b·2^(b.e-a.e), at exponent a.e
    mpz_mul_2exp(r.get_mpz_t(), b.m.get_mpz_t(), static_cast<unsigned long>(b.e - a.e));
    if (negate_b) r = a.m - r; else r += a.m;
    e = a.e;
  }
  return Dyadic(std::move(r), e);
}

}  // namespace t2
