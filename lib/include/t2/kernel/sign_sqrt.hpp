#pragma once
/// @file sign_sqrt.hpp
/// @brief The exact sign of A + B√C for polynomials A, B, C of a predicate's arguments
/// (`sign_of_root_sum`), and the sign of α√q − β√p from signs (`sign_of_root_difference`).
///
/// Fortune's sweep compares a site with a breakpoint of two parabolas, and the largest empty
/// circle compares radii: quantities x = (A + B√C)/E whose A, B, C, E are polynomials in the input
/// coordinates. Their signs are decided here without computing a square root exactly. A, B, C
/// are written as for `sign_of_poly` (filter.hpp): lambdas without captures using `+`, `-`, `*`,
/// on the same arguments (points, lines, numbers, with `double` or `Integer` coordinates).
///
/// **The rule.** Let C ≥ 0 (C < 0 throws `Undefined`: √C is not a real number). Then √C ≥ 0, so
/// sign(B√C) = sign(B) unless C = 0, and
///  - C = 0 or B = 0: sign(A);  A = 0: sign(B);  sign A = sign B: that sign;
///  - otherwise A and B√C have opposite signs, and |A| ≷ |B|√C ⟺ A² ≷ B²C (both sides ≥ 0):
///    sign(A + B√C) = sign(A)·sign(A² − B²C).
/// This is `sign_of_root_difference(sign A, −sign B, sign(A² − B²C))` with q = 1, p = C. The
/// exact stage evaluates the signs it needs with `sign_of_poly`, A² − B²C as one polynomial, so
/// A² and B²C must have the same degree in each argument (or the same total degree): that is
/// what makes A + B√C homogeneous, and it is checked at compile time.
///
/// **The filter** (`double` coordinates). Notation of filter.hpp: u = 2⁻⁵³. The fast path of
/// filter.hpp evaluates A, B, C in doubles, to a, b, c, and proves |A − a| ≤ e_A for the bound
/// e_A it computes (the constant of A's StaticBound times fl(Π Mᵢ^dᵢ); likewise e_B, e_C) when
/// the maxima are in its range; it certifies sign(A) when |a| > e_A, and A = 0 when a maximum
/// with dᵢ > 0 is 0 (then e_A = 0).
/// When C is certified positive and A, B certified with opposite signs, the filter compares
/// squares of one-sided bounds. With x = fl(|a| − e_A), y = fl(|b| + e_B), z = fl(c + e_C):
///
///     |A| ≥ |a| − e_A ≥ x/(1 + u),   |B| ≤ y/(1 − u),   C ≤ z/(1 − u),
///
/// since a sum or difference of two doubles has relative error at most u (it is exact when it
/// underflows). Let L = fl(x·x), U = fl(fl(y·y)·z). A product whose rounded value is normal and
/// finite has relative error at most u (rounding is monotone and 2⁻¹⁰²² is a double, so a
/// rounded value above 2⁻¹⁰²² comes from an exact value above it). Then
///
///     A² ≥ x²/(1 + u)² ≥ L/(1 + u)³,      B²C ≤ y²z/(1 − u)³ ≤ U/(1 − u)⁵.
///
/// The code tests L > V with V = fl(U·K), K = 1 + 2⁻⁴⁹ = 1 + 16u: V ≥ U·K·(1 − u), and
/// K(1 − u) = 1 + 15u − 16u² ≥ (1 + u)³/(1 − u)⁵ (the right side is below 1 + 8u + 40u² for
/// u ≤ 2⁻⁵⁰), so L > V proves A² > B²C: the sign of A. Symmetrically, with x' = fl(|a| + e_A),
/// y' = fl(|b| − e_B), z' = fl(c − e_C) (all > 0), L' = fl(x'·x') ≥ A²(1 − u)³ and
/// U' = fl(fl(y'·y')·z') ≤ B²C(1 + u)⁴, and U' > fl(L'·K) proves B²C > A² since K(1 − u) ≥
/// (1 + u)⁴/(1 − u)³ as well: the sign of B. The code checks that every product these bounds use
/// (L, fl(y·y), U, V; L', fl(y'·y'), U', fl(L'·K)) is normal and finite, else it does not
/// decide (an infinite x, y or z makes its products infinite). A² = B²C is never certified: a
/// zero goes to the exact stage, as does every sign the fast path of A, B or C could not certify.
///
/// On `Integer` coordinates there is no separate fast path: each `sign_of_poly` of the rule runs
/// filter.hpp's filters for big integers.

#include <cfloat>
#include <cmath>
#include <string>
#include <type_traits>

#include "t2/kernel/error.hpp"
#include "t2/kernel/filter.hpp"
#include "t2/kernel/sign.hpp"

namespace t2 {

/// sign(α·√q − β·√p) for q, p > 0, from sa = sign α, sb = sign β and s2 = sign(α²q − β²p):
/// terms α√q and β√p of different signs decide at once; terms of one sign compare by their
/// squares (face_disk.hpp compares two directions with it; `sign_of_root_sum` is q = 1).
inline Sign sign_of_root_difference(Sign sa, Sign sb, Sign s2) {
  if (sa != sb) return sa > sb ? POSITIVE : NEGATIVE;
  return sa * s2;
}

namespace detail {
/// A² − B²·C for the polynomials FA, FB, FC (lambdas without captures): itself a polynomial
/// without captures, whose sign filter.hpp decides.
template <class FA, class FB, class FC>
struct RootSumSquares {
  /// The polynomial at the arguments, on the stage's number type.
  template <class... N>
  constexpr auto operator()(const N&... x) const {
    const auto a = FA{}(x...);
    const auto b = FB{}(x...);
    return a * a - b * b * FC{}(x...);
  }
};

/// A sign known to the filter, or 2 when it still has to be computed.
inline constexpr int kUnknownSign = 2;

/// The rule of the file comment, with the signs the filter already certified (or kUnknownSign);
/// every other sign is computed by sign_of_poly.
template <class FA, class FB, class FC, class... Args>
Sign root_sum_rule(int sa, int sb, int sc, const Args&... args) {
  if (sc == kUnknownSign) sc = sign_of_poly(FC{}, args...);
  if (sc < 0) throw Undefined("sign_of_root_sum: C < 0, so the square root of C is not a real number");
  if (sa == kUnknownSign) sa = sign_of_poly(FA{}, args...);
  if (sc == 0) return static_cast<Sign>(sa);
  if (sb == kUnknownSign) sb = sign_of_poly(FB{}, args...);
  if (sa == 0) return static_cast<Sign>(sb);
  if (sb == 0 || sa == sb) return static_cast<Sign>(sa);
  return sign_of_root_difference(static_cast<Sign>(sa), -static_cast<Sign>(sb),
                                 sign_of_poly(RootSumSquares<FA, FB, FC>{}, args...));
}

/// A value of the fast path with its certified error bound (file comment).
struct Bounded {
  int sign;      ///< -1, 0, +1, or kUnknownSign
  double value;  ///< the polynomial in doubles
  double error;  ///< e: |value − exact| ≤ e; NaN when the maxima were out of range
};

/// The fast path of filter.hpp on one polynomial, with the bound it proved.
template <class... Args, class F>
Bounded bounded(const F& f, const Args&... args) {
  const StaticBound& b = bound_of<Args...>(f);
  F g{};
  const StaticFiltered r = static_filter(b, g, [](double x) { return x; }, args...);
  if (r.scale == 0) return {r.sign, r.value, r.sign == 0 ? 0.0 : NAN};  // P = 0, or out of range
  return {r.sign, r.value, b.c * r.scale};  // the bound static_filter compared with
}

/// True when a rounded product is normal and finite (file comment).
inline bool normal_product(double v) { return v > DBL_MIN && v <= DBL_MAX; }

/// |A| against |B|√C for certified a, b of opposite signs and c > e_C (file comment): POSITIVE
/// when |A| > |B|√C is proved, NEGATIVE when |A| < |B|√C is, else ZERO (not decided).
inline Sign compare_root_sum(const Bounded& a, const Bounded& b, const Bounded& c) {
  constexpr double K = 1 + 0x1p-49;
  const double x = std::fabs(a.value) - a.error, y = std::fabs(b.value) + b.error, z = c.value + c.error;
  const double L = x * x, Y = y * y, U = Y * z, V = U * K;
  if (normal_product(L) && normal_product(Y) && normal_product(U) && normal_product(V) && L > V) return POSITIVE;
  const double x2 = std::fabs(a.value) + a.error, y2 = std::fabs(b.value) - b.error, z2 = c.value - c.error;
  const double L2 = x2 * x2, Y2 = y2 * y2, U2 = Y2 * z2, V2 = L2 * K;
  if (normal_product(L2) && normal_product(Y2) && normal_product(U2) && normal_product(V2) && U2 > V2) return NEGATIVE;
  return ZERO;
}

/// The filter of the file comment: the certified sign of A + B√C, or kUnknownSign; the signs
/// of A, B, C it certified on the way go to `known` for the exact stage.
template <class FA, class FB, class FC, class... Args>
int root_sum_filter(int (&known)[3], const Args&... args) {
  const Bounded a = bounded<Args...>(FA{}, args...), b = bounded<Args...>(FB{}, args...),
                c = bounded<Args...>(FC{}, args...);
  known[0] = a.sign, known[1] = b.sign, known[2] = c.sign;
  if (c.sign == kUnknownSign || c.sign < 0) return kUnknownSign;  // C < 0 throws in the rule
  if (a.sign == kUnknownSign) return kUnknownSign;
  if (c.sign == 0) return a.sign;
  if (b.sign == kUnknownSign) return kUnknownSign;
  if (a.sign == 0) return b.sign;
  if (b.sign == 0 || a.sign == b.sign) return a.sign;
  const Sign m = compare_root_sum(a, b, c);
  return m == ZERO ? kUnknownSign : (m > 0 ? a.sign : b.sign);
}
}  // namespace detail

//> sign-of-root-sum
/// The exact sign of A + B√C at `args`, for polynomials A = `fa`, B = `fb`, C = `fc` of the
/// arguments written as for `sign_of_poly` (lambdas without captures; A² and B²C of the same
/// degrees). Throws `Undefined` when C < 0. For example the sign of a·t + b√(c·t) for numbers
/// a, b, c, t: `sign_of_root_sum([](const auto& a, const auto&, const auto&, const auto& t) {
/// return a * t; }, [](const auto&, const auto& b, const auto&, const auto&) { return b; },
/// [](const auto&, const auto&, const auto& c, const auto& t) { return c * t; }, a, b, c, t)`.
/// On `double` coordinates a floating-point filter decides first (file comment).
template <class FA, class FB, class FC, class... Args>
Sign sign_of_root_sum(const FA&, const FB&, const FC&, const Args&... args) {
  static_assert(detail::stateless_polynomial<FA> && detail::stateless_polynomial<FB> &&
                    detail::stateless_polynomial<FC>,
                "t2::sign_of_root_sum: A, B and C must be lambdas without captures (filter.hpp, bound_of)");
  static_assert(detail::derive_bound<Args...>(detail::RootSumSquares<FA, FB, FC>{}).c < HUGE_VAL,
                "t2::sign_of_root_sum: A² and B²·C must have the same degrees (else A + B√C is not homogeneous)");
  int known[3] = {detail::kUnknownSign, detail::kUnknownSign, detail::kUnknownSign};
  if constexpr (std::is_same_v<typename detail::CommonCoordinate<Args...>::type, double>) {
    detail::count_call();
    if (const int s = detail::root_sum_filter<FA, FB, FC>(known, args...); s != detail::kUnknownSign)
      return static_cast<Sign>(s);
    detail::count_exact();
  }
  return detail::root_sum_rule<FA, FB, FC>(known[0], known[1], known[2], args...);
}
//< sign-of-root-sum

}  // namespace t2
