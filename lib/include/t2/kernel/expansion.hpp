#pragma once
/// @file expansion.hpp
/// @brief Floating-point expansions: exact sums and products of doubles as unevaluated sums of
/// doubles (Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric
/// Predicates", Discrete Comput. Geom. 18, 1997). The exact stage of the kernel's predicates.
///
/// **Error-free transformations.** With round-to-nearest-even and no overflow:
/// - `two_sum(a, b)` returns x = fl(a + b) and y with a + b = x + y *exactly* (Knuth: six
///   floating-point operations, no branch, no condition on the magnitudes);
/// - `two_prod(a, b)` returns x = fl(a·b) and y = fma(a, b, −x) with a·b = x + y exactly — the
///   fused multiply-add rounds once, and a·b − x is a double as long as it does not underflow.
///
/// **Expansions.** An expansion is a sum x₁ + x₂ + … + xₙ of nonzero doubles in increasing
/// magnitude, *nonoverlapping* (the lowest nonzero bit of each exceeds the highest bit of the one
/// before): its sign is the sign of its largest component xₙ, and xₙ alone approximates the sum
/// to within one unit in its last place. `sum` (Shewchuk's fast-expansion-sum with zero
/// elimination), `scale` (scale-expansion) and `operator*` (a sum of scales) keep that form, so
/// any polynomial of doubles evaluates exactly into an expansion. The capacity N of
/// `Expansion<N>` is the worst-case length, known at compile time (the sum of two has N + M
/// components at most, a product 2·N·M); the actual length is usually far smaller because zero
/// components are dropped.
///
/// **Range.** All of this is exact only when nothing overflows and no `two_prod` error term
/// underflows. Every component of the evaluation of a polynomial of degree k is an integer
/// multiple of 2^(k·L), where 2^L is the smallest nonzero bit of any input; when k·L ≥ −1074
/// (the smallest subnormal is 2⁻¹⁰⁷⁴) every error term is a double. The predicates check that
/// every nonzero input lies in a range chosen from their degree (`in_expansion_range`) and hand
/// other inputs to GMP. The compiler must not contract a·b + c into an fma in this file (it would
/// break `two_sum`): the kernel target builds its users with `-ffp-contract=off`.

#include <algorithm>
#include <cmath>

#include "t2/kernel/sign.hpp"

namespace t2::expansion {

//> two-sum
/// x + y = a + b exactly, x = fl(a + b) (Knuth's two-sum).
inline void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double bv = x - a;  // the part of b that made it into x
  const double av = x - bv;  // the part of a that made it into x
  y = (a - av) + (b - bv);   // what was rounded away, exactly
}
//< two-sum

/// x + y = a − b exactly, x = fl(a − b).
inline void two_diff(double a, double b, double& x, double& y) { two_sum(a, -b, x, y); }

/// x + y = a + b exactly when |a| ≥ |b| or a = 0 (Dekker's fast-two-sum: three operations).
inline void fast_two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  y = b - (x - a);
}

//> two-prod
/// x + y = a·b exactly, x = fl(a·b), if a·b − x does not underflow (file comment).
inline void two_prod(double a, double b, double& x, double& y) {
  x = a * b;
  y = std::fma(a, b, -x);  // one rounding of an exact value that is a double: exact
}
//< two-prod

/// h = e + f (Shewchuk's fast-expansion-sum-zeroelim): merges the components by magnitude and
/// carries the sum along with two-sum. Returns the length of h (capacity elen + flen).
inline int sum(int elen, const double* e, int flen, const double* f, double* h) {
  if (elen == 0) return static_cast<int>(std::copy(f, f + flen, h) - h);
  if (flen == 0) return static_cast<int>(std::copy(e, e + elen, h) - h);
  int ei = 0, fi = 0, hi = 0;
  double enow = e[0], fnow = f[0], q, qnew, hh;
  auto next_e = [&] { enow = ++ei < elen ? e[ei] : 0.0; };
  auto next_f = [&] { fnow = ++fi < flen ? f[fi] : 0.0; };
  if ((fnow > enow) == (fnow > -enow)) {  // |enow| < |fnow|: take the smaller first
    q = enow;
    next_e();
  } else {
    q = fnow;
    next_f();
  }
  if (ei < elen && fi < flen) {
    if ((fnow > enow) == (fnow > -enow)) {
      fast_two_sum(enow, q, qnew, hh);
      next_e();
    } else {
      fast_two_sum(fnow, q, qnew, hh);
      next_f();
    }
    q = qnew;
    if (hh != 0) h[hi++] = hh;
    while (ei < elen && fi < flen) {
      if ((fnow > enow) == (fnow > -enow)) {
        two_sum(q, enow, qnew, hh);
        next_e();
      } else {
        two_sum(q, fnow, qnew, hh);
        next_f();
      }
      q = qnew;
      if (hh != 0) h[hi++] = hh;
    }
  }
  while (ei < elen) {  // next_e and next_f advance ei and fi
    two_sum(q, enow, qnew, hh);
    next_e();
    q = qnew;
    if (hh != 0) h[hi++] = hh;
  }
  while (fi < flen) {
    two_sum(q, fnow, qnew, hh);
    next_f();
    q = qnew;
    if (hh != 0) h[hi++] = hh;
  }
  if (q != 0) h[hi++] = q;
  return hi;
}

/// h = b·e (Shewchuk's scale-expansion-zeroelim). Returns the length of h (capacity 2·elen).
inline int scale(int elen, const double* e, double b, double* h) {
  if (elen == 0 || b == 0) return 0;
  int hi = 0;
  double q, hh, p1, p0, s;
  two_prod(e[0], b, q, hh);
  if (hh != 0) h[hi++] = hh;
  for (int i = 1; i < elen; ++i) {
    two_prod(e[i], b, p1, p0);
    two_sum(q, p0, s, hh);
    if (hh != 0) h[hi++] = hh;
    fast_two_sum(p1, s, q, hh);
    if (hh != 0) h[hi++] = hh;
  }
  if (q != 0) h[hi++] = q;
  return hi;
}

/// An expansion of at most N components (see the file comment); zero has no component.
template <int N>
struct Expansion {
  double c[N];  ///< the components, smallest first; only the first n are meaningful
  int n = 0;    ///< the number of components

  Expansion() = default;
  /// The one-component expansion of a double.
  explicit Expansion(double a) requires(N >= 1) : n(a != 0) { c[0] = a; }
  /// Copies the meaningful components only.
  Expansion(const Expansion& o) : n(o.n) { std::copy(o.c, o.c + o.n, c); }
  /// Copies the meaningful components only.
  Expansion& operator=(const Expansion& o) {
    n = o.n;
    std::copy(o.c, o.c + o.n, c);
    return *this;
  }
  /// The sign of the exact value: the sign of the largest component.
  Sign sign() const { return n == 0 ? ZERO : (c[n - 1] > 0 ? POSITIVE : NEGATIVE); }
  /// The largest component; the others sum to less than its lowest nonzero bit.
  double approx() const { return n == 0 ? 0.0 : c[n - 1]; }
  /// The rounded sum of the components, smallest first.
  double estimate() const {
    double s = 0;
    for (int i = 0; i < n; ++i) s += c[i];
    return s;
  }
};

/// The exact difference a − b as a two-component expansion.
inline Expansion<2> diff(double a, double b) {
  Expansion<2> r;
  double x, y;
  two_diff(a, b, x, y);
  if (y != 0) r.c[r.n++] = y;
  if (x != 0) r.c[r.n++] = x;
  return r;
}

/// The exact product a·b as a two-component expansion (within the range of the file comment).
inline Expansion<2> prod(double a, double b) {
  Expansion<2> r;
  double x, y;
  two_prod(a, b, x, y);
  if (y != 0) r.c[r.n++] = y;
  if (x != 0) r.c[r.n++] = x;
  return r;
}

/// Exact sum.
template <int N, int M>
Expansion<N + M> operator+(const Expansion<N>& e, const Expansion<M>& f) {
  Expansion<N + M> h;
  h.n = sum(e.n, e.c, f.n, f.c, h.c);
  return h;
}

/// Exact negation.
template <int N>
Expansion<N> operator-(const Expansion<N>& e) {
  Expansion<N> h;
  h.n = e.n;
  for (int i = 0; i < e.n; ++i) h.c[i] = -e.c[i];
  return h;
}

/// Exact difference.
template <int N, int M>
Expansion<N + M> operator-(const Expansion<N>& e, const Expansion<M>& f) {
  return e + (-f);
}

/// Exact product: the sum of the scales of e by each component of f.
template <int N, int M>
Expansion<2 * N * M> operator*(const Expansion<N>& e, const Expansion<M>& f) {
  Expansion<2 * N * M> a, b;
  double part[2 * N];
  double *cur = a.c, *other = b.c;
  int n = 0;
  for (int i = 0; i < f.n; ++i) {
    const int k = scale(e.n, e.c, f.c[i], part);
    n = sum(n, cur, k, part, other);
    std::swap(cur, other);
  }
  if (cur != a.c) std::copy(cur, cur + n, a.c);
  a.n = n;
  return a;
}

/// Exact product by a one-component expansion: a single scale.
template <int N>
Expansion<2 * N> operator*(const Expansion<N>& e, const Expansion<1>& f) {
  Expansion<2 * N> h;
  h.n = f.n == 0 ? 0 : scale(e.n, e.c, f.c[0], h.c);
  return h;
}

/// A double-word number hi + lo, |lo| ≤ u|hi| (u = 2⁻⁵³): about 106 bits, for the adaptive
/// stages that need an accurate but not exact value. The operations are those of Joldes, Muller
/// and Popescu, "Tight and rigorous error bounds for basic building blocks of double-word
/// arithmetic" (ACM TOMS 44(2), 2017), with their proven relative error bounds, valid without
/// underflow or overflow: exact products of two doubles, sums within 3u²/(1 − 4u) (their
/// AccurateDWPlusDW), products within 5u² (DWTimesDW3, with fma).
struct DoubleWord {
  double hi = 0;  ///< the rounded value
  double lo = 0;  ///< the rest
};

/// a·b exactly, as a double word.
inline DoubleWord dw_prod(double a, double b) {
  DoubleWord r;
  two_prod(a, b, r.hi, r.lo);
  return r;
}

/// x + y within relative error 3u²/(1 − 4u) (AccurateDWPlusDW).
inline DoubleWord dw_add(DoubleWord x, DoubleWord y) {
  double sh, sl, th, tl, vh, vl;
  two_sum(x.hi, y.hi, sh, sl);
  two_sum(x.lo, y.lo, th, tl);
  fast_two_sum(sh, sl + th, vh, vl);
  DoubleWord z;
  fast_two_sum(vh, tl + vl, z.hi, z.lo);
  return z;
}

/// −x, exactly.
inline DoubleWord dw_neg(DoubleWord x) { return {-x.hi, -x.lo}; }

/// x·y within relative error 5u² (DWTimesDW3).
inline DoubleWord dw_mul(DoubleWord x, DoubleWord y) {
  double ch, cl1;
  two_prod(x.hi, y.hi, ch, cl1);
  const double tl1 = std::fma(x.hi, y.lo, x.lo * y.lo);
  const double cl2 = std::fma(x.lo, y.hi, tl1);
  DoubleWord z;
  fast_two_sum(ch, cl1 + cl2, z.hi, z.lo);
  return z;
}

/// 2^e as a constant (exact for −1022 ≤ e ≤ 1023).
constexpr double pow2(int e) {
  double r = 1;
  for (; e > 0; --e) r *= 2;
  for (; e < 0; ++e) r /= 2;
  return r;
}

/// True when x is 0 or 2^Lo ≤ |x| ≤ 2^Hi: then an expansion evaluation of a polynomial whose
/// bounds the caller derived from its degree neither overflows nor underflows.
template <int Lo, int Hi>
bool in_expansion_range(double x) {
  constexpr double lo = pow2(Lo), hi = pow2(Hi);
  const double a = std::fabs(x);
  return a == 0 || (a >= lo && a <= hi);
}

}  // namespace t2::expansion
