#pragma once
/// @file filter.hpp
/// @brief Exact signs of polynomial predicates on `double` input: a floating-point filter with
/// a proven error bound and an exact GMP fallback.
///
/// A predicate is written once as a generic lambda over a number type `N` using only `+`, `-`
/// and `*`. `filtered_sign(f, a, b, ...)` first evaluates `f` on `Filtered` numbers, which carry
/// the rounded value `v`, a magnitude `mag` (the same polynomial evaluated on absolute values,
/// i.e. the sum of the absolute values of all its monomials) and the depth `k` of the longest
/// chain of rounded operations. By the standard analysis (Higham, *Accuracy and Stability of
/// Numerical Algorithms*, §3.1) the exact value differs from `v` by at most
/// γ_k · mag_exact, γ_k = k·u/(1 - k·u), u = 2⁻⁵³, as long as nothing overflows or
/// underflows. `mag` is itself rounded, so the bound used is (k + 2)·u·mag (valid for k ≤ 64).
/// Overflow is caught by testing that `v` and `mag` are finite; underflow by refusing every
/// product whose magnitude falls below 2⁻⁹⁶⁰. If the test `|v| > bound` fails, `f` is evaluated
/// again on GMP rationals, into which every double converts exactly: the sign is then exact.
///
/// There are no epsilons: the bound only decides *whether* the fast answer is certain.

#include <atomic>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <utility>

#include "t2/number.hpp"
#include "t2/sign.hpp"

namespace t2 {

/// A double with the bookkeeping of the filter (see the file comment).
struct Filtered {
  double v = 0;    ///< rounded value
  double mag = 0;  ///< rounded magnitude: the polynomial on absolute values
  int depth = 0;   ///< longest chain of rounded operations
  bool tiny = false;  ///< a product may have underflowed: the bound does not hold

  Filtered() = default;
  /// An exact leaf (an input coordinate).
  Filtered(double x) : v(x), mag(std::fabs(x)) {}  // NOLINT: implicit on purpose

  /// Sum: one more rounding.
  friend Filtered operator+(const Filtered& a, const Filtered& b) {
    return {a.v + b.v, a.mag + b.mag, std::max(a.depth, b.depth) + 1, a.tiny || b.tiny};
  }
  /// Difference: one more rounding.
  friend Filtered operator-(const Filtered& a, const Filtered& b) {
    return {a.v - b.v, a.mag + b.mag, std::max(a.depth, b.depth) + 1, a.tiny || b.tiny};
  }
  /// Negation: exact.
  friend Filtered operator-(const Filtered& a) { return {-a.v, a.mag, a.depth, a.tiny}; }
  /// Product: the roundings of both factors plus one; flags possible underflow.
  friend Filtered operator*(const Filtered& a, const Filtered& b) {
    const double m = a.mag * b.mag;
    const bool t = a.tiny || b.tiny || (a.mag != 0 && b.mag != 0 && m < 0x1p-960);
    return {a.v * b.v, m, a.depth + b.depth + 1, t};
  }

 private:
  Filtered(double v_, double m_, int d_, bool t_) : v(v_), mag(m_), depth(d_), tiny(t_) {}
};

/// How often the exact stage ran: counters for the benchmarks and the course's measurements.
struct FilterStats {
  std::atomic<std::uint64_t> calls{0};  ///< predicates evaluated on doubles
  std::atomic<std::uint64_t> exact{0};  ///< of which the filter failed and GMP decided
  /// Sets both counters to zero.
  void reset() {
    calls = 0;
    exact = 0;
  }
};

/// The process-wide counters of `filtered_sign`.
FilterStats& filter_stats();

/// The sign certified by the filter, or `std::nullopt`-like `2` when it is uncertain.
inline int certified_sign(const Filtered& r) {
  if (r.tiny || !std::isfinite(r.v) || !std::isfinite(r.mag) || r.depth > 64) return 2;
  const double u = 0x1p-53;
  const double bound = (r.depth + 2) * u * r.mag;
  if (r.v > bound) return 1;
  if (-r.v > bound) return -1;
  if (r.mag == 0) return 0;  // every monomial is exactly zero
  return 2;
}

/// A GMP number whose operators return plain values, so that a generic lambda returning
/// `a * b - c * d` never holds a dangling gmpxx expression template.
template <class G>
struct Exact {
  G v;  ///< the exact value
  /// Wraps a value.
  Exact(G x) : v(std::move(x)) {}  // NOLINT: implicit on purpose
  /// Sum.
  friend Exact operator+(const Exact& a, const Exact& b) { return G(a.v + b.v); }
  /// Difference.
  friend Exact operator-(const Exact& a, const Exact& b) { return G(a.v - b.v); }
  /// Negation.
  friend Exact operator-(const Exact& a) { return G(-a.v); }
  /// Product.
  friend Exact operator*(const Exact& a, const Exact& b) { return G(a.v * b.v); }
};

/// The exact sign of `f(args...)` for finite doubles (see the file comment).
template <class F, class... D>
Sign filtered_sign(F&& f, D... args) {
  auto& stats = filter_stats();
  stats.calls.fetch_add(1, std::memory_order_relaxed);
  const int s = certified_sign(f(Filtered(args)...));
  if (s != 2) return static_cast<Sign>(s);
  stats.exact.fetch_add(1, std::memory_order_relaxed);
  return sign_of(f(Exact<Rational>(to_rational(args))...).v);
}

/// The sign of `f(args...)` evaluated directly in exact arithmetic (integer coordinates).
template <class F>
Sign exact_sign(F&& f, const auto&... args) {
  return sign_of(f(Exact<Integer>(Integer(args))...).v);
}

/// The exact sign of the polynomial `f` (a generic lambda using `+`, `-`, `*`) at `args`:
/// filtered for `double` coordinates, computed directly for `Integer` coordinates.
template <class F, class... T>
Sign sign_of_poly(F&& f, const T&... args) {
  if constexpr ((std::is_same_v<T, double> && ...)) {
    return filtered_sign(f, args...);
  } else {
    return exact_sign(f, args...);
  }
}

}  // namespace t2
