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

#include <array>
#include <cmath>
#include <cstddef>
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

//> poly-arguments
/// The homogeneous coordinates of a point of T² on the number type N of a filter stage: what
/// the polynomial of a predicate receives for each point (`p.w`, `p.x`, `p.y`).
template <class N>
struct Hom3 {
  N w;  ///< weight
  N x;  ///< first coordinate
  N y;  ///< second coordinate
};
/// The coefficients of a line ⟨W, X, Y⟩ of T² on the number type N of a filter stage.
template <class N>
struct Line3 {
  N W;  ///< coefficient of w
  N X;  ///< coefficient of x
  N Y;  ///< coefficient of y
};
/// The coordinates of a point [w, x] of T¹ on the number type N of a filter stage.
template <class N>
struct Hom2 {
  N w;  ///< weight
  N x;  ///< coordinate
};

/// How the filter reads one argument of a predicate: which coordinate type it has, and what
/// the polynomial receives. A number is a leaf of its own; point.hpp, line.hpp and t1.hpp
/// specialise this for points (Hom3), lines (Line3) and points of T¹ (Hom2).
template <class A>
struct Leaves {
  using Coordinate = A;  ///< the number type of the argument
  /// The argument on the stage's number type, each coordinate converted by `leaf`.
  template <class F>
  static auto map(const A& a, F&& leaf) {
    return leaf(a);
  }
  /// True when `test` holds for every coordinate.
  template <class F>
  static bool all(const A& a, F&& test) {
    return test(a);
  }
};
//< poly-arguments

/// A row of numbers (e.g. of a 3×3 matrix) is read as a std::array of the stage's number type.
template <class T, std::size_t K>
struct Leaves<std::array<T, K>> {
  using Coordinate = T;  ///< the number type of the entries
  /// The row on the stage's number type.
  template <class F>
  static auto map(const std::array<T, K>& r, F&& leaf) {
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
      return std::array<decltype(leaf(r[0])), K>{leaf(r[I])...};
    }(std::make_index_sequence<K>{});
  }
  /// True when `test` holds for every entry.
  template <class F>
  static bool all(const std::array<T, K>& r, F&& test) {
    for (const T& v : r)
      if (!test(v)) return false;
    return true;
  }
};

namespace detail {
/// The common coordinate type of the arguments of a predicate, checked at compile time.
template <class A, class... B>
struct CommonCoordinate {
  using type = typename Leaves<A>::Coordinate;  ///< double or Integer
  static_assert((std::is_same_v<type, typename Leaves<B>::Coordinate> && ...),
                "t2::sign_of_poly: every coordinate must have the same number type (double or t2::Integer); "
                "convert them first, e.g. 0 -> 0.0, or a Point to an ExactPoint with to_exact");
  static_assert(std::is_same_v<type, double> || std::is_same_v<type, Integer>,
                "t2::sign_of_poly: coordinates are double or t2::Integer");
};
/// Every argument on the stage's number type N (`leaf` converts one coordinate).
template <class F, class Leaf, class... A>
auto apply_leaves(F& f, Leaf&& leaf, const A&... args) {
  return f(Leaves<A>::map(args, leaf)...);
}
/// True when `test` holds for every coordinate of every argument.
template <class Test, class... A>
bool all_leaves(Test&& test, const A&... args) {
  return (Leaves<A>::all(args, test) && ...);
}
}  // namespace detail

/// The exact sign of `f(args...)` for arguments with finite `double` coordinates (see the file
/// comment).
template <class F, class... A>
Sign filtered_sign(F&& f, const A&... args) {
  detail::count_call();
  const Filtered r = detail::apply_leaves(f, [](double v) { return Filtered(v); }, args...);
  const int s = certified_sign(r, detail::all_leaves([](double v) { return detail::in_filter_range(v); }, args...));
  if (s != 2) return static_cast<Sign>(s);
  if (r.mag < 0x1p52 && detail::all_leaves([](double v) { return detail::small_integer(v); }, args...))
    return sign_of(r.v);  // no rounding
  detail::count_exact();
  return sign_of(detail::apply_leaves(f, [](double v) { return Dyadic(v); }, args...));
}

/// The sign of `f(args...)` evaluated directly in exact arithmetic (integer coordinates).
template <class F, class... A>
Sign exact_sign(F&& f, const A&... args) {
  return sign_of(detail::apply_leaves(f, [](const Integer& v) { return Exact<Integer>(v); }, args...).v);
}

namespace detail {
/// True when an integer converts to a double exactly and stays in the filter's range.
inline bool fits_filter(const Integer& v) { return mpz_sizeinbase(v.get_mpz_t(), 2) <= 52; }
}  // namespace detail

//> sign-of-poly
/// The exact sign of the polynomial `f` at `args`. `f` is a generic lambda using `+`, `-`, `*`
/// that receives each argument on the number type of the filter's stage: a point as a Hom3
/// (`p.w`, `p.x`, `p.y`), a line as a Line3 (`l.W`, `l.X`, `l.Y`), a point of T¹ as a Hom2, a
/// number as a number. For example the sign of the 2×2 minor wx of two points is
/// `sign_of_poly([](const auto& p, const auto& q) { return p.w * q.x - p.x * q.w; }, p, q)`.
/// Filtered for `double` coordinates; for `Integer` coordinates the same filter runs first when
/// every coordinate has at most 52 bits (they convert to doubles exactly, and the filter's
/// integer certificate often decides), and GMP integers decide the rest. Only calls on
/// `double` coordinates are counted in filter_stats(). Every coordinate of every argument has
/// the same type, `double` or `Integer`: a mix (0.5 and 0, a Point and an ExactPoint) does not
/// compile, since converting it would change the polynomial (tests/compile_fail). The kernel's
/// hot predicates (orient.hpp, incircle.hpp, orient3d.hpp, distance.hpp) have hand-written fast
/// paths instead.
template <class F, class... A>
Sign sign_of_poly(F&& f, const A&... args) {
  using T = typename detail::CommonCoordinate<A...>::type;
  if constexpr (std::is_same_v<T, double>) {
    return filtered_sign(f, args...);
  } else {
    if (detail::all_leaves([](const Integer& v) { return detail::fits_filter(v); }, args...)) {
      const Filtered r = detail::apply_leaves(f, [](const Integer& v) { return Filtered(v.get_d()); }, args...);
      const int s = certified_sign(r, true);  // 52-bit integers are in the filter's range
      if (s != 2) return static_cast<Sign>(s);
      if (r.mag < 0x1p52) return sign_of(r.v);  // integers, no rounding: exact
    }
    return exact_sign(f, args...);
  }
}
//< sign-of-poly

}  // namespace t2
