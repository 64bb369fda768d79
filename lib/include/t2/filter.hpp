#pragma once
/// @file filter.hpp
/// @brief Exact signs of polynomial predicates on `double` input: a floating-point filter with
/// a proven error bound and an exact GMP fallback.
///
/// A predicate is written once as a generic lambda over a number type `N` using only `+`, `-`
/// and `*`. `filtered_sign(f, a, b, ...)` first evaluates `f` on `Filtered` numbers, which carry
/// the rounded value `v`, a magnitude `mag` (the same expression evaluated on absolute values
/// with every `-` read as `+`), the depth `k` of the longest chain of rounded operations and
/// the degree of the polynomial. By the standard analysis (Higham, *Accuracy and Stability of
/// Numerical Algorithms*, §3.1) the exact value differs from `v` by at most
/// γ_k · mag, γ_k = k·u/(1 - k·u), u = 2⁻⁵³, as long as nothing overflows or underflows.
/// `mag` is itself rounded, and one more u·mag covers underflow (below), so the bound used is
/// (k + 3)·u·mag (valid for k ≤ 64).
///
/// Overflow and underflow are tamed up front: the filter is trusted only when every nonzero
/// input lies in [2⁻¹²⁰, 2¹²⁰] and the degree is at most 8. Then every `mag` of a node is 0 or
/// in [2⁻⁹⁶⁰, 2⁹⁶⁰]: nothing overflows, and a product that underflows (a tiny value left by
/// cancellation) errs by at most 2⁻¹⁰⁷⁵ ≤ 2⁻¹¹⁵·mag of its node, which is far below u·mag for any
/// predicate of fewer than 2⁶⁰ operations. Other inputs go to GMP.
///
/// When the bound cannot decide, one more certificate is tried before GMP: if every input is
/// an integer and `mag` < 2⁵², no operation rounded at all, so `v` is exact — even when it is
/// zero. Integer grids and their exactly collinear triples never reach GMP. Otherwise `f` is
/// evaluated again exactly, on `Dyadic` numbers (a GMP integer times a power of two), into
/// which every double converts exactly; unlike GMP rationals they never compute a gcd.
///
/// There are no epsilons: the bound only decides *whether* the fast answer is certain.

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
  double mag = 0;  ///< rounded magnitude: the expression on absolute values
  int depth = 0;   ///< longest chain of rounded operations
  int degree = 0;  ///< degree of the polynomial in the inputs

  Filtered() = default;
  /// An exact leaf (an input coordinate).
  Filtered(double x) : v(x), mag(std::fabs(x)), degree(1) {}  // NOLINT: implicit on purpose

  /// Sum: one more rounding.
  friend Filtered operator+(const Filtered& a, const Filtered& b) {
    return {a.v + b.v, a.mag + b.mag, std::max(a.depth, b.depth) + 1, std::max(a.degree, b.degree)};
  }
  /// Difference: one more rounding.
  friend Filtered operator-(const Filtered& a, const Filtered& b) {
    return {a.v - b.v, a.mag + b.mag, std::max(a.depth, b.depth) + 1, std::max(a.degree, b.degree)};
  }
  /// Negation: exact.
  friend Filtered operator-(const Filtered& a) { return {-a.v, a.mag, a.depth, a.degree}; }
  /// Product: the roundings of both factors plus one.
  friend Filtered operator*(const Filtered& a, const Filtered& b) {
    return {a.v * b.v, a.mag * b.mag, a.depth + b.depth + 1, a.degree + b.degree};
  }

 private:
  Filtered(double v_, double m_, int k_, int d_) : v(v_), mag(m_), depth(k_), degree(d_) {}
};

/// How often the exact stage ran: counters for the benchmarks and the course's measurements.
/// They count only in programs built with `T2_FILTER_STATS` defined (see `count_call`).
struct FilterStats {
  std::uint64_t calls = 0;  ///< predicates evaluated on doubles
  std::uint64_t exact = 0;  ///< of which the fast path could not decide and an exact stage ran
  /// Sets both counters to zero.
  void reset() { calls = exact = 0; }
};

/// The counters of the predicates in the calling thread (per thread, so counting costs no
/// atomic operation). They stay zero unless `filter_stats_enabled`.
inline FilterStats& filter_stats() {
  thread_local FilterStats stats;
  return stats;
}

//> filter-stats
/// True when this translation unit counts (built with the compile definition T2_FILTER_STATS).
///
/// The counting code is in the headers. To count every call of a program, configure with the
/// CMake option `T2_FILTER_STATS=ON`: the library and every target are then built with it. A
/// program that calls the predicates itself can instead define it on its own target
/// (`target_compile_definitions(prog PRIVATE T2_FILTER_STATS)`, or `#define` before the first
/// include, as chapter 04 does): then its own calls count, and calls made inside the compiled
/// library (lib/src, e.g. the triangulation) do not. Strictly, such a mix gives one inline
/// predicate two definitions in one program; they differ only in counting, so every answer is
/// the same whichever the linker keeps, but the counts are then a lower bound.
#ifdef T2_FILTER_STATS
inline constexpr bool filter_stats_enabled = true;
#else
inline constexpr bool filter_stats_enabled = false;
#endif

namespace detail {
/// Counts one predicate call (compiled out without T2_FILTER_STATS).
inline void count_call() {
  if constexpr (filter_stats_enabled) ++filter_stats().calls;
}
/// Counts one call that needed an exact stage (compiled out without T2_FILTER_STATS).
inline void count_exact() {
  if constexpr (filter_stats_enabled) ++filter_stats().exact;
}
}  // namespace detail
//< filter-stats

namespace detail {
/// True when x is 0 or 2⁻¹²⁰ ≤ |x| ≤ 2¹²⁰ (see the file comment).
inline bool in_filter_range(double x) {
  const double a = std::fabs(x);
  return a == 0 || (a >= 0x1p-120 && a <= 0x1p120);
}
/// True when x is an integer of magnitude below 2⁵².
inline bool small_integer(double x) {
  return std::fabs(x) < 0x1p52 && x == double(static_cast<std::int64_t>(x));
}
}  // namespace detail

/// The sign (-1, 0, +1) that the filter certifies for `r`, or 2 when it cannot decide.
/// `in_range` says whether every input passed detail::in_filter_range.
inline int certified_sign(const Filtered& r, bool in_range) {
  if (!in_range || r.degree > 8 || r.depth > 64) return 2;
  const double bound = (r.depth + 3) * 0x1p-53 * r.mag;
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

/// An exact dyadic rational m·2^e: every finite double is one, and sums and products of them
/// are too. The exact stage of the filter computes with these.
struct Dyadic {
  Integer m;   ///< mantissa
  long e = 0;  ///< binary exponent

  /// The exact value of a finite double.
  explicit Dyadic(double x);
  /// m·2^e.
  Dyadic(Integer m_, long e_) : m(std::move(m_)), e(e_) {}
  /// Sum (aligns the exponents by shifting the mantissa with the larger one).
  friend Dyadic operator+(const Dyadic& a, const Dyadic& b) { return add(a, b, false); }
  /// Difference.
  friend Dyadic operator-(const Dyadic& a, const Dyadic& b) { return add(a, b, true); }
  /// Negation.
  friend Dyadic operator-(const Dyadic& a) { return Dyadic(Integer(-a.m), a.e); }
  /// Product.
  friend Dyadic operator*(const Dyadic& a, const Dyadic& b) { return Dyadic(Integer(a.m * b.m), a.e + b.e); }

 private:
  static Dyadic add(const Dyadic& a, const Dyadic& b, bool negate_b);
};

/// The sign of a dyadic number.
inline Sign sign_of(const Dyadic& d) { return static_cast<Sign>(sgn(d.m)); }

/// The exact sign of `f(args...)` for finite doubles (see the file comment).
template <class F, class... D>
Sign filtered_sign(F&& f, D... args) {
  detail::count_call();
  const Filtered r = f(Filtered(args)...);
  const int s = certified_sign(r, (detail::in_filter_range(args) && ...));
  if (s != 2) return static_cast<Sign>(s);
  if ((detail::small_integer(args) && ...) && r.mag < 0x1p52) return sign_of(r.v);  // no rounding
  detail::count_exact();
  return sign_of(f(Dyadic(args)...));
}

/// The sign of `f(args...)` evaluated directly in exact arithmetic (integer coordinates).
template <class F>
Sign exact_sign(F&& f, const auto&... args) {
  return sign_of(f(Exact<Integer>(Integer(args))...).v);
}

namespace detail {
/// True when an integer converts to a double exactly and stays in the filter's range.
inline bool fits_filter(const Integer& v) { return mpz_sizeinbase(v.get_mpz_t(), 2) <= 52; }
}  // namespace detail

/// The exact sign of the polynomial `f` (a generic lambda using `+`, `-`, `*`) at `args`:
/// filtered for `double` coordinates; for `Integer` coordinates the same filter runs first when
/// every coordinate has at most 52 bits (they convert to doubles exactly, and the filter's
/// integer certificate often decides), and GMP integers decide the rest. Only calls on
/// `double` coordinates are counted in filter_stats(). Every coordinate has the same type,
/// `double` or `Integer`: a mix (say 0.5 and 0) does not compile, since converting it would
/// change the polynomial (tests/compile_fail). The kernel's own predicates (orient.hpp,
/// incircle.hpp, orient3d.hpp) take points and have hand-written fast paths instead.
template <class F, class T, class... U>
Sign sign_of_poly(F&& f, const T& first, const U&... rest) {
  static_assert((std::is_same_v<T, U> && ...),
                "t2::sign_of_poly: every coordinate must have the same number type (double or t2::Integer); "
                "convert them first, e.g. 0 -> 0.0");
  static_assert(std::is_same_v<T, double> || std::is_same_v<T, Integer>,
                "t2::sign_of_poly: coordinates are double or t2::Integer");
  if constexpr (std::is_same_v<T, double>) {
    return filtered_sign(f, first, rest...);
  } else {
    if (detail::fits_filter(first) && (detail::fits_filter(rest) && ...)) {
      const Filtered r = f(Filtered(first.get_d()), Filtered(rest.get_d())...);
      const bool in_range = detail::in_filter_range(first.get_d()) && (detail::in_filter_range(rest.get_d()) && ...);
      const int s = certified_sign(r, in_range);
      if (s != 2) return static_cast<Sign>(s);
      if (r.mag < 0x1p52) return sign_of(r.v);  // integers, no rounding: exact
    }
    return exact_sign(f, first, rest...);
  }
}

}  // namespace t2
