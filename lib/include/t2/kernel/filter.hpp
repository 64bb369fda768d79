#pragma once
/// @file filter.hpp
/// @brief Exact signs of polynomial predicates on `double` input: an error bound derived once
/// per predicate, at compile time, from the shape of its polynomial; exact stages of
/// floating-point expansions, GMP only outside their range.
///
/// A predicate is written once as a generic lambda over a number type `N` using only `+`, `-`
/// and `*` (`sign_of_poly`). The hot predicates (orient_double.hpp, incircle_double.hpp,
/// distance_double.hpp) have hand-tuned fast paths; every other predicate goes through this file.
///
/// **The theorem.** Notation of orient_double.hpp: u = 2⁻⁵³, γ_k = k·u/(1 − k·u). Read the
/// lambda as a tree and multiply it out without cancelling anything: it becomes a sum of `count`
/// monomials with coefficient ±1. If every monomial meets at most k roundings on its way to the
/// result (a sum adds one to each of its operands, a product adds one to the sum of its
/// factors'), the rounded value v differs from the exact value P by at most γ_k·Σ|m| (Higham,
/// *Accuracy and Stability of Numerical Algorithms*, §3.1), when nothing overflows or underflows.
/// The predicates of T² are homogeneous: scaling one point by t > 0 scales P by t^d. If every
/// monomial has the same degree dᵢ in the coordinates of argument i (*multi-homogeneous*), and
/// Mᵢ is the largest |coordinate| of argument i, then each |m| ≤ Π Mᵢ^dᵢ, so
///
///     |v − P| ≤ γ_k · count · Π Mᵢ^dᵢ.
///
/// If the degrees per argument differ between monomials but the total degree D is the same in
/// all (e.g. s² + c² − den² with three numbers as arguments), the same holds with one M, the
/// largest |coordinate| of all, and M^D.
///
/// **Derived once.** `count`, k, the dᵢ and D depend only on the lambda, not on the input: the
/// filter evaluates the lambda once, at compile time, on `PolyShape` leaves, which carry exactly
/// these numbers (`derive_bound`), so the lambda must have no captures (`bound_of`). A lambda
/// that is not homogeneous gets no bound and does not compile. For example side(l, p) =
/// W·w + X·x + Y·y (line.hpp) has count 3, k = 3 (a product and two sums), d = (1, 1):
/// |v − P| ≤ 9u/(1 − 3u)·M_l·M_p.
///
/// **The bound that runs.** C = count·k·u·(1 + 2⁻⁴⁰), and the code computes fl(C·fl(Π Mᵢ^dᵢ)) with
/// D roundings, so the computed bound is at least C(1 − u)^D·Π Mᵢ^dᵢ ≥ count·γ_k·Π Mᵢ^dᵢ·(1 + 2⁻⁴²)
/// as long as k + D ≤ 2¹⁰ (then (1 + 2⁻⁴⁰)(1 − u)^D(1 − ku) ≥ 1 + 2⁻⁴²). The fast path is the
/// lambda on plain doubles, the maxima and this product: `v > bound` proves P > 0 and
/// `−v > bound` proves P < 0. An argument whose maximum is 0 while dᵢ > 0 makes every monomial
/// zero: P = 0, exactly.
///
/// **Range.** The bound is trusted only when every Mᵢ (with dᵢ > 0) lies in [2⁻ᴿ, 2ᴿ], R =
/// ⌊900/D⌋ (one M for a total-degree bound). Then no intermediate value exceeds count·2⁹⁰⁰: no
/// overflow (count ≤ 2⁶⁰ is required). An operation that underflows errs by at most 2⁻¹⁰⁷⁵
/// (absolutely; a sum or difference that underflows is exact), and that error reaches the result
/// multiplied by the rest of its monomials, which are at most count·Π Mᵢ^dᵢ divided by the
/// maxima of the node's own factors, at least 2^(−R·D) ≥ 2⁻⁹⁰⁰: with at most 2⁶⁰ operations (ops,
/// counted too) all underflows together err by at most 2⁻¹¹⁵·count·Π Mᵢ^dᵢ, which the margin
/// 2⁻⁴²·count·γ_k covers.
///
/// **A second, semi-static bound.** Π Mᵢ^dᵢ is loose when the coordinates of one argument differ
/// widely (a far point [1, 2⁶⁰, 2⁶⁰] has M = 2⁶⁰ although its w is 1). When the static bound
/// cannot decide, the lambda is evaluated once more on pairs (value, magnitude): the magnitude is
/// the same tree on absolute values with every − read as +, i.e. Σ|m| itself, rounded by at most
/// k roundings of positive terms, so fl(Σ|m|) ≥ (1 − u)^k·Σ|m|, and fl(C₂·fl(Σ|m|)) with C₂ =
/// k·u·(1 + 2⁻⁴⁰) is at least γ_k·Σ|m|·(1 + 2⁻⁴²) for k ≤ 2⁹. This stage runs only when every
/// nonzero |coordinate| lies in [2⁻ᴿ, 2ᴿ]: then a node's magnitude is 0 (and its value exactly
/// 0) or at least 2⁻⁹⁰⁰, so an underflow's 2⁻¹⁰⁷⁵ is at most 2⁻¹⁷⁵ of the magnitude of its node,
/// and of Σ|m| once multiplied by the rest of its monomials: far below the margin.
///
/// **Exact stages.** When the bounds cannot decide: if every coordinate is an integer below 2⁵²
/// in magnitude and count·Π Mᵢ^dᵢ ≤ 2⁵², no operation rounded (every node is an integer below
/// its own count·Π Mᵢ^dᵢ, since Mᵢ ≥ 1), so v is exact, zero included: integer grids and their
/// exactly collinear triples end here. Else the lambda is evaluated on floating-point expansions
/// (expansion.hpp), exact when every nonzero |coordinate| lies in [2^(52 − ⌊1074/D⌋), 2ᴿ] (every
/// component is then a multiple of 2⁻¹⁰⁷⁴ and below 2¹⁰²³) and the expansion's capacity stays
/// small; else on dyadic GMP numbers (a GMP integer times a power of two), into which every
/// double converts exactly.
///
/// **Big integers.** On `Integer` coordinates (exact constructions) whose bits do not all fit a
/// double, the semi-static bound runs on x̃ = mpz_get_d(x), x truncated towards zero: x̃ = x(1 + δ)
/// with −2u < δ ≤ 0, and (1 − u)³ < 1 − 2u, so δ is a product of three factors 1 + δⱼ, |δⱼ| ≤ u:
/// three roundings more on every leaf of a monomial, k + 3D in all. With C₃ = (k + 3D)·u·(1 + 2⁻⁴⁰)
/// (k + 3D ≤ 2⁹), fl(C₃·fl(Σ|m̃|)) ≥ γ_{k+3D}·Σ|m| as for C₂, since Σ|m̃| ≥ (1 − 2u)^D·Σ|m|. No
/// underflow: x̃ is an integer (x has no bits below 1), and so is every rounded sum, difference
/// and product of integers, so a nonzero node has magnitude ≥ 1. Overflow makes a magnitude node
/// +∞ (each magnitude node bounds |its value node|, rounding being monotone), so the bound is +∞
/// or NaN and decides nothing. A magnitude of 0 means a zero factor in every monomial: P = 0.
///
/// There are no epsilons: the bound only decides *whether* the fast answer is certain.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

#include "t2/kernel/expansion.hpp"
#include "t2/kernel/number.hpp"
#include "t2/kernel/detail/poly_shape.hpp"
#include "t2/kernel/sign.hpp"

namespace t2 {

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
  /// The argument's shape with every coordinate `leaf`: what derive_bound passes.
  template <class N>
  static constexpr N shape(const N& leaf) {
    return leaf;
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
  /// The row's shape with every entry `leaf`.
  template <class N>
  static constexpr std::array<N, K> shape(const N& leaf) {
    std::array<N, K> r{};
    for (N& v : r) v = leaf;
    return r;
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

namespace detail {
/// Derives the bound of `f` on arguments of types A... by evaluating it on PolyShape leaves.
template <class... A, class F>
constexpr StaticBound derive_bound(const F& f) {
  static_assert(sizeof...(A) <= kMaxPolyArgs, "t2::sign_of_poly: at most 32 arguments");
  const PolyShape s = [&]<std::size_t... I>(std::index_sequence<I...>) {
    return f(Leaves<A>::shape(PolyShape::leaf(I))...);
  }(std::index_sequence_for<A...>{});
  StaticBound b;
  b.degree = s.degree;
  b.per_argument = s.per_argument;
  b.total = s.total;
  b.count = s.count;
  b.range = expansion::pow2(s.total > 0 ? 900 / s.total : 0);
  if (s.homogeneous && s.total > 0 && s.count <= 0x1p60 && s.ops <= 0x1p60 && s.depth + s.total <= 512) {
    b.c = s.count * s.depth * 0x1p-53 * (1 + 0x1p-40);
    b.c2 = s.depth * 0x1p-53 * (1 + 0x1p-40);
    if (s.depth + 3 * s.total <= 512) b.c3 = (s.depth + 3 * s.total) * 0x1p-53 * (1 + 0x1p-40);
  }
  return b;
}

/// True when F is the type of a lambda without captures (or another stateless callable): no
/// member that a call could read, and a default constructor, so that `F{}` is the polynomial
/// of every object of type F.
template <class F>
inline constexpr bool stateless_polynomial = std::is_empty_v<F> && std::is_default_constructible_v<F>;

/// The bound of `f`: a compile-time constant, one per type F, derived from `F{}`. It is the
/// bound of every object of type F only because F is stateless: a lambda with captures (`[&]`,
/// `[=]`, `[k]`) could compute a different polynomial for each captured value while sharing
/// one cached bound (issue 23: a lambda whose polynomial depended on a captured
/// variable: tried as a new user would, 14,168 of 200,000 signs wrong), so it does not compile
/// (tests/compile_fail/capturing_lambda.cpp).
template <class... A, class F>
const StaticBound& bound_of(const F&) {
  static_assert(stateless_polynomial<F>,
                "t2::sign_of_poly: the polynomial must be a lambda without captures ([], not [&], [=] or [k]): "
                "its error bound is derived once per lambda type, so it must not depend on captured values; "
                "pass what it needs as arguments, or call helper lambdas declared static constexpr");
  static constexpr StaticBound b = derive_bound<A...>(F{});
  static_assert(b.c < HUGE_VAL, "t2::sign_of_poly: the polynomial must be homogeneous (file comment)");
  return b;
}

/// The largest |coordinate| of one argument, each read as a double by `read`.
template <class A, class Read>
double max_abs(const A& a, Read read) {
  double m = 0;
  Leaves<A>::all(a, [&](const auto& v) {
    m = std::max(m, std::fabs(read(v)));
    return true;
  });
  return m;
}

/// What the fast path found: a certified sign (or 2), the rounded value and Π Mᵢ^dᵢ.
struct StaticFiltered {
  int sign;      ///< -1, 0, +1, or 2 when not certified
  double value;  ///< the polynomial in doubles
  double scale;  ///< Π Mᵢ^dᵢ (or M^D); 0 when a maximum is out of range
};

/// The fast path of the file comment, on the coordinates read as doubles by `read` (exactly).
template <class F, class Read, class... A>
StaticFiltered static_filter(const StaticBound& b, F& f, Read read, const A&... args) {
  const double v = apply_leaves(f, read, args...);
  const double m[] = {max_abs(args, read)...};
  double scale = 1;
  if (b.per_argument) {
    for (std::size_t i = 0; i < sizeof...(A); ++i) {
      if (b.degree[i] == 0) continue;
      if (m[i] == 0) return {0, v, 0};  // every monomial has a zero factor
      if (!(m[i] >= 1 / b.range && m[i] <= b.range)) return {2, v, 0};
      for (int d = 0; d < b.degree[i]; ++d) scale *= m[i];
    }
  } else {
    double mm = 0;
    for (const double x : m) mm = std::max(mm, x);
    if (mm == 0) return {0, v, 0};
    if (!(mm >= 1 / b.range && mm <= b.range)) return {2, v, 0};
    for (int d = 0; d < b.total; ++d) scale *= mm;
  }
  const double bound = b.c * scale;
  const int sign = (v > bound) - (-v > bound);
  return {sign != 0 ? sign : 2, v, scale};
}

/// True when x is an integer of magnitude below 2⁵².
inline bool small_integer(double x) { return std::fabs(x) < 0x1p52 && x == double(static_cast<std::int64_t>(x)); }

/// The integer certificate of the file comment, given that every coordinate is an integer below
/// 2⁵²: no operation of the fast path rounded.
inline bool rounded_nothing(const StaticBound& b, const StaticFiltered& r) {
  return r.scale > 0 && b.count * r.scale <= 0x1p52;
}

/// A double with the magnitude of its expression, for the semi-static bound (file comment).
struct Magnitude {
  double v = 0;  ///< the rounded value
  double m = 0;  ///< the rounded expression on absolute values, every − read as +
  /// Sum.
  friend Magnitude operator+(const Magnitude& a, const Magnitude& b) { return {a.v + b.v, a.m + b.m}; }
  /// Difference.
  friend Magnitude operator-(const Magnitude& a, const Magnitude& b) { return {a.v - b.v, a.m + b.m}; }
  /// Negation.
  friend Magnitude operator-(const Magnitude& a) { return {-a.v, a.m}; }
  /// Product.
  friend Magnitude operator*(const Magnitude& a, const Magnitude& b) { return {a.v * b.v, a.m * b.m}; }
};

/// The capacity of an expansion type, 0 for other types.
template <class E>
inline constexpr int expansion_capacity = 0;
/// The capacity of an expansion type.
template <int N>
inline constexpr int expansion_capacity<expansion::Expansion<N>> = N;

/// The exact stages of the file comment, after the fast path could not decide.
template <class F, class... A>
[[gnu::noinline]] Sign static_filter_exact(const StaticBound& b, F& f, const StaticFiltered& r, const A&... args) {
  if (rounded_nothing(b, r) && all_leaves([](double v) { return small_integer(v); }, args...))
    return sign_of(r.value);
  const double lo = 1 / b.range, hi = b.range;
  const auto in_range = [&](double v) { return v == 0 || (std::fabs(v) >= lo && std::fabs(v) <= hi); };
  if (b.c2 < HUGE_VAL && all_leaves(in_range, args...)) {  // the semi-static bound
    const Magnitude e = apply_leaves(f, [](double x) { return Magnitude{x, std::fabs(x)}; }, args...);
    const double bound = b.c2 * e.m;
    const int sign = (e.v > bound) - (-e.v > bound);
    if (sign != 0) return static_cast<Sign>(sign);
  }
  using E = decltype(apply_leaves(f, [](double x) { return expansion::Expansion<1>(x); }, args...));
  if constexpr (expansion_capacity<E> > 0 && expansion_capacity<E> <= 2048) {
    const double elo = std::ldexp(1.0, 52 - 1074 / std::max(b.total, 1));
    if (all_leaves([&](double v) { return v == 0 || (std::fabs(v) >= elo && std::fabs(v) <= hi); }, args...))
      return apply_leaves(f, [](double x) { return expansion::Expansion<1>(x); }, args...).sign();
  }
  return sign_of(apply_leaves(f, [](double v) { return Dyadic(v); }, args...));
}

/// The exact sign of `f(args...)` for arguments with finite `double` coordinates (file comment).
template <class F, class... A>
Sign static_filter_sign(F& f, const A&... args) {
  count_call();
  const StaticBound& b = bound_of<A...>(f);
  const StaticFiltered r = static_filter(b, f, [](double x) { return x; }, args...);
  if (r.sign != 2) [[likely]] return static_cast<Sign>(r.sign);
  count_exact();
  return static_filter_exact(b, f, r, args...);
}

/// The semi-static bound on big integers read as the doubles below them (file comment, "Big
/// integers"): the certified sign, or 2.
template <class F, class... A>
int big_integer_filter(const StaticBound& b, F& f, const A&... args) {
  const auto read = [](const Integer& x) {
    const double d = mpz_get_d(x.get_mpz_t());  // truncated towards zero: an integer
    return Magnitude{d, std::fabs(d)};
  };
  const Magnitude e = apply_leaves(f, read, args...);
  if (e.m == 0) return 0;  // every monomial has a zero factor
  const double bound = b.c3 * e.m;
  const int sign = (e.v > bound) - (-e.v > bound);  // false for an infinite or NaN bound
  return sign != 0 ? sign : 2;
}
}  // namespace detail

/// The sign of `f(args...)` evaluated directly in exact arithmetic (integer coordinates).
template <class F, class... A>
Sign exact_sign(F&& f, const A&... args) {
  return sign_of(detail::apply_leaves(f, [](const Integer& v) { return Exact<Integer>(v); }, args...).v);
}

namespace detail {
/// True when an integer converts to a double exactly and lies below 2⁵².
inline bool fits_filter(const Integer& v) { return mpz_sizeinbase(v.get_mpz_t(), 2) <= 52; }
}  // namespace detail

//> sign-of-poly
/// The exact sign of the polynomial `f` at `args`. `f` is a generic lambda using `+`, `-`, `*`
/// that receives each argument on the number type of the filter's stage: a point as a Hom3
/// (`p.w`, `p.x`, `p.y`), a line as a Line3 (`l.W`, `l.X`, `l.Y`), a point of T¹ as a Hom2, a
/// number as a number. For example the sign of the 2×2 minor wx of two points is
/// `sign_of_poly([](const auto& p, const auto& q) { return p.w * q.x - p.x * q.w; }, p, q)`.
/// Filtered for `double` coordinates with the bound derived from the shape of `f` (file
/// comment; `f` must be homogeneous); for `Integer` coordinates the same filter runs first when
/// every coordinate has at most 52 bits (they convert to doubles exactly, and the filter's
/// integer certificate often decides), else the semi-static bound on the doubles just below the
/// coordinates (file comment, "Big integers"), and GMP integers decide the rest. Only calls on
/// `double` coordinates are counted in filter_stats(). Every coordinate of every argument has
/// the same type, `double` or `Integer`: a mix (0.5 and 0, a Point and an ExactPoint) does not
/// compile, since converting it would change the polynomial (tests/compile_fail). The kernel's
/// hot predicates (orient.hpp, incircle.hpp, orient3d.hpp, distance.hpp) have hand-written fast
/// paths instead.
template <class F, class... A>
Sign sign_of_poly(F&& f, const A&... args) {
  using T = typename detail::CommonCoordinate<A...>::type;
  if constexpr (std::is_same_v<T, double>) {
    return detail::static_filter_sign(f, args...);
  } else {
    const auto& b = detail::bound_of<A...>(f);
    if (detail::all_leaves([](const Integer& v) { return detail::fits_filter(v); }, args...)) {
      const auto r = detail::static_filter(b, f, [](const Integer& v) { return v.get_d(); }, args...);
      if (r.sign != 2) return static_cast<Sign>(r.sign);
      if (detail::rounded_nothing(b, r)) return sign_of(r.value);  // integers: exact
    } else if (const int s = detail::big_integer_filter(b, f, args...); s != 2) {
      return static_cast<Sign>(s);
    }
    return exact_sign(f, args...);
  }
}
//< sign-of-poly

}  // namespace t2
