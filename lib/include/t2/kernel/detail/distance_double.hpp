#pragma once
/// @file distance_double.hpp
/// @brief The comparisons of distances and of coordinates on `double` input: fast paths with
/// semi-static error bounds, exact stages of floating-point expansions, GMP outside their range.
/// Notation and method as in orient_double.hpp (u = 2⁻⁵³, γ_k = k·u/(1 − k·u); a monomial that
/// meets k roundings errs by at most γ_k times its magnitude).
///
/// **Which of two front points is nearer to a third (Cartesian points, every w = 1).**
/// Δ = |A − C|² − |B − C|² = (a₁² + a₂²) − (b₁² + b₂²) with the exact differences a₁ = Aₓ − Cₓ,
/// a₂ = A_y − C_y, b₁, b₂ the same for B. The code rounds the differences, squares them, and
/// computes l = fl(fl(a₁²) + fl(a₂²)), r the same for b, det = fl(l − r). Each monomial (a₁²,
/// say) meets 5 roundings: its difference twice (it is squared), the square, the sum and the
/// subtraction, so |det − Δ| ≤ γ₅·Σ with Σ = a₁² + a₂² + b₁² + b₂². The bound is semi-static:
/// a₁² ≤ fl(a₁²)/(1 − u)³ (the difference and the square rounded it) and l ≥ (fl(a₁²) + fl(a₂²))(1
/// − u), so Σ ≤ (l + r)/(1 − u)⁴, and the code's bound fl(fl(C_d·fl(l + r)) + 2⁻¹⁰⁰⁰) is at least
/// C_d(1 − u)²(l + r) + 2⁻¹⁰⁰¹. With C_d = 5u(1 + 2⁻⁴⁰), C_d(1 − u)² ≥ 5u/((1 − 5u)(1 − u)⁴) ≥
/// γ₅/(1 − u)⁴, because 2⁻⁴⁰ exceeds 11u by far. Underflow breaks the relative model only in the
/// four squares and in the bound's product, each by at most 2⁻¹⁰⁷⁵ (a sum or difference that
/// underflows is exact): 2⁻¹⁰⁰⁰ covers them. Overflow makes l, r, det or the bound infinite or
/// NaN, and then neither `det > bound` nor `−det > bound` holds. So `det > bound` proves Δ > 0
/// and `−det > bound` proves Δ < 0.
///
/// **Comparing two ratios u/s and v/t (s, t > 0), the normalized coordinates of
/// lexicographic.hpp.** Δ = u·t − v·s. When s = t the sign is that of fl(u − v), which is exact
/// (a difference of doubles rounds to zero only when it is zero, and rounding keeps its sign),
/// i.e. the order of u and v: this is the Cartesian case s = t = 1. Otherwise l = fl(u·t), r = fl(v·s), det = fl(l − r):
/// each monomial meets 2 roundings, |u·t| ≤ |l|/(1 − u), and the code's bound fl(fl(C_r·fl(|l| +
/// |r|)) + 2⁻¹⁰⁰⁰) ≥ C_r(1 − u)²(|l| + |r|) + 2⁻¹⁰⁰¹ exceeds γ₂/(1 − u)·(|l| + |r|) with C_r = 2u(1
/// + 2⁻⁴⁰); underflow (two products, the bound) and overflow as above.
///
/// **Exact stages.** For distances: two-diff the four differences; if none was rounded, Δ is
/// the expansion a₁² + a₂² − b₁² − b₂² of exact products, else the same of the two-component
/// differences. For ratios: the expansion of two exact products. Both are polynomials of
/// degree 2 of the inputs, exact for nonzero |inputs| in [2⁻⁴⁸⁵, 2⁵⁰⁰] as in orient_double.hpp
/// (every component a multiple of 2⁻¹⁰⁷⁴, below 2¹⁰¹⁰); outside, dyadic GMP numbers decide.

#include <cmath>

#include "t2/kernel/expansion.hpp"
#include "t2/kernel/filter.hpp"
#include "t2/kernel/detail/orient_double.hpp"
#include "t2/kernel/sign.hpp"

namespace t2::detail {

/// C_d of the file comment: 5u(1 + 2⁻⁴⁰).
inline constexpr double kDistanceBound = 5 * kUnitRoundoff * (1 + 0x1p-40);
/// C_r of the file comment: 2u(1 + 2⁻⁴⁰).
inline constexpr double kRatioBound = 2 * kUnitRoundoff * (1 + 0x1p-40);

/// True when every argument is 0 or in the exponent range of the degree-2 expansions.
inline bool in_degree2_range(auto... v) { return (expansion::in_expansion_range<-485, 500>(v) && ...); }

/// The exact stages of compare_distance2 (see the file comment).
[[gnu::noinline]] inline Sign compare_distance2_exact(double ax, double ay, double bx, double by, double cx,
                                                      double cy) {
  using namespace expansion;
  count_exact();
  if (!in_degree2_range(ax, ay, bx, by, cx, cy)) {
    const Dyadic Ax(ax), Ay(ay), Bx(bx), By(by), Cx(cx), Cy(cy);
    const Dyadic a1 = Ax - Cx, a2 = Ay - Cy, b1 = Bx - Cx, b2 = By - Cy;
    return sign_of((a1 * a1 + a2 * a2) - (b1 * b1 + b2 * b2));
  }
  double a1, t1, a2, t2, b1, t3, b2, t4;
  two_diff(ax, cx, a1, t1);
  two_diff(ay, cy, a2, t2);
  two_diff(bx, cx, b1, t3);
  two_diff(by, cy, b2, t4);
  if (t1 == 0 && t2 == 0 && t3 == 0 && t4 == 0)
    return ((prod(a1, a1) + prod(a2, a2)) - (prod(b1, b1) + prod(b2, b2))).sign();
  const auto A1 = diff(ax, cx), A2 = diff(ay, cy), B1 = diff(bx, cx), B2 = diff(by, cy);
  return ((A1 * A1 + A2 * A2) - (B1 * B1 + B2 * B2)).sign();
}

/// sign(|A − C|² − |B − C|²) for Cartesian points A, B, C: exact (see the file comment).
inline Sign compare_distance2(double ax, double ay, double bx, double by, double cx, double cy) {
  count_call();
  const double a1 = ax - cx, a2 = ay - cy, b1 = bx - cx, b2 = by - cy;
  const double l = a1 * a1 + a2 * a2, r = b1 * b1 + b2 * b2;
  const double det = l - r, bound = kDistanceBound * (l + r) + 0x1p-1000;
  const int sign = (det > bound) - (-det > bound);
  if (sign != 0) [[likely]] return static_cast<Sign>(sign);
  return compare_distance2_exact(ax, ay, bx, by, cx, cy);
}

/// The exact stage of compare_ratios_double (see the file comment).
[[gnu::noinline]] inline Sign compare_ratios_double_exact(double u, double s, double v, double t) {
  using namespace expansion;
  count_exact();
  if (!in_degree2_range(u, s, v, t)) return sign_of(Dyadic(u) * Dyadic(t) - Dyadic(v) * Dyadic(s));
  return (prod(u, t) - prod(v, s)).sign();
}

/// sign(u/s − v/t) for s, t > 0: exact (see the file comment).
inline Sign compare_ratios_double(double u, double s, double v, double t) {
  count_call();
  if (s == t) return static_cast<Sign>((u > v) - (u < v));  // exact
  const double l = u * t, r = v * s, det = l - r;
  const double bound = kRatioBound * (std::fabs(l) + std::fabs(r)) + 0x1p-1000;
  const int sign = (det > bound) - (-det > bound);
  if (sign != 0) [[likely]] return static_cast<Sign>(sign);
  return compare_ratios_double_exact(u, s, v, t);
}

}  // namespace t2::detail
