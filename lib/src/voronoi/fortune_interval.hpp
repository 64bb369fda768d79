#pragma once
// Interval arithmetic in doubles for the filters of Fortune's sweep (fortune.cpp): a certified
// enclosure [lo, hi] of a real number, so that a sign is decided in doubles when 0 is outside it,
// and by the exact rational predicates otherwise. Private to lib/src/voronoi.
//
// Proof. Round-to-nearest gives, for the exact result z of +, −, ×, √ or of a rational's
// conversion (mpq_get_d truncates), |fl(z) − z| ≤ 2⁻⁵²|z| + 2⁻¹⁰²² (the second term for
// results below the normal range, which may also be flushed to 0). With |z| ≤ |fl(z)|(1 + 2⁻⁵¹), the widening
// pad(f) = |f|·2⁻⁴⁹ + 2⁻¹⁰⁰⁰ is at least 4·(2⁻⁵²|z| + 2⁻¹⁰²²), so f − pad(f) ≤ z ≤ f + pad(f) even
// after the rounding of that subtraction and addition (each moves the bound by at most
// 2⁻⁵³·|f ± pad| + 2⁻¹⁰⁷⁴, less than the slack of pad). Each operation is applied to the
// bounds of its operands (monotone in each: the four products of the bounds for ×, the bounds
// of the radicand for √, the reversed bounds for 1/x on an interval without 0), so every interval contains its exact value. An infinite or NaN bound
// makes the interval useless: `sign` reports it as undecided.

#include <algorithm>
#include <cmath>

#include "t2/kernel/number.hpp"

namespace t2::detail {

/// A certified enclosure of a real number (file comment).
struct Interval {
  double lo, hi;  ///< lo ≤ the number ≤ hi

  static double pad(double f) { return std::fabs(f) * 0x1p-49 + 0x1p-1000; }
  /// The enclosure of a computed f of exact value z with |f − z| ≤ 2⁻⁵²|z| + 2⁻¹⁰²².
  static Interval around(double f) { return {f - pad(f), f + pad(f)}; }
  /// The enclosure of a rational.
  static Interval of(const Rational& q) { return around(q.get_d()); }

  friend Interval operator+(const Interval& a, const Interval& b) {
    const double l = a.lo + b.lo, h = a.hi + b.hi;
    return {l - pad(l), h + pad(h)};
  }
  friend Interval operator-(const Interval& a, const Interval& b) {
    const double l = a.lo - b.hi, h = a.hi - b.lo;
    return {l - pad(l), h + pad(h)};
  }
  friend Interval operator*(const Interval& a, const Interval& b) {
    const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    const double l = std::min({p[0], p[1], p[2], p[3]}), h = std::max({p[0], p[1], p[2], p[3]});
    return {l - pad(l), h + pad(h)};
  }
  /// 1/a for an interval without 0 (else the whole line: undecided).
  friend Interval recip(const Interval& a) {
    if (!(a.lo > 0 || a.hi < 0)) return {-HUGE_VAL, HUGE_VAL};
    const double l = 1 / a.hi, h = 1 / a.lo;
    return {l - pad(l), h + pad(h)};
  }
  /// √ of the non-negative part (the callers' radicands are ≥ 0).
  friend Interval sqrt(const Interval& a) {
    const double l = std::sqrt(std::max(a.lo, 0.0)), h = std::sqrt(std::max(a.hi, 0.0));
    return {std::max(l - pad(l), 0.0), h + pad(h)};
  }
  /// The same interval when both bounds are finite, else the whole line (−∞, +∞), whose
  /// bounds decide no comparison (`lo > other.hi` and `hi < other.lo` are then false).
  Interval settled() const {
    if (std::isfinite(lo) && std::isfinite(hi)) return *this;
    return {-HUGE_VAL, HUGE_VAL};
  }
  /// The sign when 0 is outside the interval, else 2 (undecided; also for a bound not finite).
  int sign() const {
    if (!std::isfinite(lo) || !std::isfinite(hi)) return 2;
    return lo > 0 ? 1 : hi < 0 ? -1 : 2;
  }
};

}  // namespace t2::detail
