#pragma once
/// @file orient_double.hpp
/// @brief Δ(p, q, r) on `double` coordinates: a fast path of plain double arithmetic with an
/// error bound derived once, then exact stages of floating-point expansions (expansion.hpp),
/// GMP only outside the expansions' exponent range.
///
/// Notation: u = 2⁻⁵³ (the unit roundoff), fl(·) a rounded operation. Without overflow or
/// underflow, fl(a ∘ b) = (a ∘ b)(1 + δ) with |δ| ≤ u, and a product of k factors (1 + δᵢ)^±1 is
/// 1 + θ with |θ| ≤ γ_k = k·u/(1 − k·u) (Higham, *Accuracy and Stability of Numerical
/// Algorithms*, §3.1). So if a polynomial is evaluated in floating point and every monomial m
/// of its expansion meets at most k roundings on its way to the result, the computed value
/// differs from the exact one by at most γ_k · Σ|m|. Each bound below is this fact, a bound on
/// Σ|m| that costs a few operations, and a margin for the rounding of the bound itself.
///
/// **Cartesian points (every w = 1), the common case.** Δ = det[1 pₓ p_y; 1 qₓ q_y; 1 rₓ r_y]
/// = a·d − b·c with a = qₓ − pₓ, b = q_y − p_y, c = rₓ − pₓ, d = r_y − p_y. The code computes the
/// rounded differences, l = fl(a·d), r = fl(b·c), det = fl(l − r). Each of the two monomials
/// meets 4 roundings (two differences, the product, the subtraction), so with A·D and B·C the
/// exact products of the exact differences, |det − Δ| ≤ γ₄(|A·D| + |B·C|). The bound is
/// *semi-static*: it is computed from l and r, which the fast path has anyway. Since
/// |A·D| ≤ |l|/(1 − u)³ (three roundings made l), γ₄(|A·D| + |B·C|) ≤ γ₄/(1 − u)³ · (|l| + |r|),
/// and the code's bound fl(fl(C₂·fl(|l| + |r|)) + 2⁻¹⁰⁰⁰), made with three roundings, is at least
/// C₂(1 − u)³(|l| + |r|) + 2⁻¹⁰⁰¹. With C₂ = 4u(1 + 2⁻⁴⁰): C₂(1 − u)³ ≥ 4u/((1 − 4u)(1 − u)³) =
/// γ₄/(1 − u)³, because (1 + 2⁻⁴⁰)(1 − u)⁶(1 − 4u) ≥ 1 (2⁻⁴⁰ exceeds 10u by far). Underflow breaks the relative model only in the two products and in
/// C₂·(|l| + |r|), each by an absolute error of at most 2⁻¹⁰⁷⁵ (a subtraction of doubles that
/// underflows is exact): the term 2⁻¹⁰⁰⁰ covers them. Overflow gives ±∞ or NaN somewhere in l,
/// r, det or the bound, and then neither `det > bound` nor `−det > bound` holds: such input goes
/// on to the exact stage. So `det > bound` proves Δ > 0 and `−det > bound` proves Δ < 0.
///
/// **Homogeneous points.** Δ = a(ei − fh) − b(di − fg) + c(dh − eg) on the rows (a, b, c) = p,
/// (d, e, f) = q, (g, h, i) = r. Each monomial meets 5 roundings (its inner product, the minor's
/// subtraction, the outer product, at most two outer sums) and takes one factor from each
/// column, so Σ|m| ≤ 6·m₀m₁m₂ with mⱼ the largest magnitude in column j, and |det − Δ| ≤
/// 6γ₅·m₀m₁m₂. The bound fl(fl(C₃·m₀)·m₁)·m₂) with C₃ = 30u(1 + 2⁻⁴⁰) exceeds it: C₃(1 − u)³ ≥
/// 30u/(1 − 5u). This bound needs 2⁻³⁰⁰ ≤ mⱼ ≤ 2³⁰⁰ (checked): then nothing overflows, and an
/// underflowing operation, whose absolute error 2⁻¹⁰⁷⁵ is later multiplied by at most the
/// maxima of the remaining factors of its monomials, errs by at most 2⁻¹⁰⁷⁵/2⁻⁶⁰⁰ relative to
/// m₀m₁m₂ — far below the margin 2⁻⁴⁰·C₃. A column that is all zeros makes Δ = 0 exactly.
///
/// **Exact stages.** When the bound cannot decide, the Cartesian case recomputes the differences
/// with two-diff: if none was rounded (a common case: integer grids, nearby points), the exact
/// a·d − b·c of the rounded differences, a 4-component expansion, is Δ. Otherwise one more
/// filter of Shewchuk's kind (his "stage C") adds the first-order terms of the tails: with
/// a = a₀ + a₁ (head and tail), Δ = E₀ + R₁ + R₂ where E₀ = a₀d₀ − b₀c₀ (exact, an expansion),
/// R₁ = a₀d₁ + a₁d₀ − b₀c₁ − b₁c₀ and R₂ = a₁d₁ − b₁c₁. With e₀ the largest component of E₀
/// and ê the rounded sum of its at most four components, smallest first (the smaller components
/// sum to less than the lowest bit of e₀, so Σ|components| ≤ 2|e₀| and |E₀ − ê| ≤ 2γ₃|e₀|), r₁ =
/// fl(R₁) (|r₁ − R₁| ≤ γ₃T with T = |a₀d₁| + |a₁d₀| + |b₀c₁| + |b₁c₀|), |R₂| ≤ uT (each tail is at
/// most u times its head) and s = fl(ê + r₁): |Δ − s| ≤ 2γ₃|e₀| + (γ₃ + u)T + u|s|, which the
/// computed 7u|e₀| + 5u·T + 2⁻¹⁰⁰⁰ exceeds. Only when that fails too is the whole Δ
/// evaluated as an expansion of the two-component differences. The expansions are exact in the
/// exponent range of expansion.hpp, checked per predicate from its degree (2 for the Cartesian
/// case: nonzero |x| in [2⁻⁴⁸⁵, 2⁵⁰⁰]; 3 for the homogeneous one: [2⁻³⁰⁰, 2³⁰⁰]); outside it the
/// dyadic GMP numbers of filter.hpp decide.

#include <algorithm>
#include <cmath>

#include "t2/kernel/expansion.hpp"
#include "t2/kernel/filter.hpp"
#include "t2/kernel/sign.hpp"

namespace t2::detail {

/// u = 2⁻⁵³, the unit roundoff of double.
inline constexpr double kUnitRoundoff = 0x1p-53;
/// C₂ of the file comment: 4u(1 + 2⁻⁴⁰).
inline constexpr double kOrient2Bound = 4 * kUnitRoundoff * (1 + 0x1p-40);
/// C₃ of the file comment: 30u(1 + 2⁻⁴⁰).
inline constexpr double kOrient3Bound = 30 * kUnitRoundoff * (1 + 0x1p-40);

/// The 3×3 determinant on dyadic GMP numbers: the last resort, for any finite input.
inline Sign orient_dyadic(double a, double b, double c, double d, double e, double f, double g, double h,
                          double i) {
  const Dyadic A(a), B(b), C(c), D(d), E(e), F(f), G(g), H(h), I(i);
  return sign_of(A * (E * I - F * H) - B * (D * I - F * G) + C * (D * H - E * G));
}

/// The exact stages of the Cartesian orientation (see the file comment).
[[gnu::noinline]] inline Sign orient2_exact(double px, double py, double qx, double qy, double rx, double ry) {
  using namespace expansion;
  count_exact();
  constexpr int lo = -485, hi = 500;
  if (!(in_expansion_range<lo, hi>(px) && in_expansion_range<lo, hi>(py) && in_expansion_range<lo, hi>(qx) &&
        in_expansion_range<lo, hi>(qy) && in_expansion_range<lo, hi>(rx) && in_expansion_range<lo, hi>(ry)))
    return orient_dyadic(1, px, py, 1, qx, qy, 1, rx, ry);
  //> orient2-exact
  double a, a1, b, b1, c, c1, d, d1;
  two_diff(qx, px, a, a1);
  two_diff(qy, py, b, b1);
  two_diff(rx, px, c, c1);
  two_diff(ry, py, d, d1);
  const auto e0 = prod(a, d) - prod(b, c);  // exact: a 4-component expansion
  if (a1 == 0 && b1 == 0 && c1 == 0 && d1 == 0) return e0.sign();
  const double h = e0.approx();
  const double r1 = (a * d1 + a1 * d) - (b * c1 + b1 * c);
  const double t =
      (std::fabs(a * d1) + std::fabs(a1 * d)) + (std::fabs(b * c1) + std::fabs(b1 * c));
  const double s = e0.estimate() + r1;
  const double bound =
      (7 * kUnitRoundoff * std::fabs(h) + 5 * kUnitRoundoff * t) + 0x1p-1000;
  if (s > bound) return POSITIVE;
  if (-s > bound) return NEGATIVE;
  const auto A = diff(qx, px), B = diff(qy, py), C = diff(rx, px), D = diff(ry, py);
  return (A * D - B * C).sign();
  //< orient2-exact
}

//> orient2-fast
/// What a fast path computes: the rounded value of the polynomial and its error bound.
struct Filtered2 {
  double value;  ///< the polynomial evaluated in doubles
  double bound;  ///< |value − exact| < bound when no overflow occurred (file comment)
};

/// The fast path for three Cartesian points: Δ in doubles and the file comment's bound.
inline Filtered2 orient2_filter(double px, double py, double qx, double qy, double rx,
                                double ry) {
  const double a = qx - px, b = qy - py, c = rx - px, d = ry - py;
  const double l = a * d, r = b * c;
  return {l - r, kOrient2Bound * (std::fabs(l) + std::fabs(r)) + 0x1p-1000};
}

/// Δ of three Cartesian points (px, py), (qx, qy), (rx, ry): exact (file comment).
inline Sign orient2(double px, double py, double qx, double qy, double rx, double ry) {
  count_call();
  const auto [det, bound] = orient2_filter(px, py, qx, qy, rx, ry);
  // No branch on the (random) sign itself.
  const int sign = (det > bound) - (-det > bound);
  if (sign != 0) [[likely]] return static_cast<Sign>(sign);
  return orient2_exact(px, py, qx, qy, rx, ry);
}
//< orient2-fast

/// The exact stage of the homogeneous orientation: expansions, or GMP outside their range.
[[gnu::noinline]] inline Sign orient3_exact(double a, double b, double c, double d, double e, double f, double g,
                                            double h, double i) {
  using namespace expansion;
  count_exact();
  constexpr int lo = -300, hi = 300;
  const double v[9] = {a, b, c, d, e, f, g, h, i};
  if (!std::all_of(v, v + 9, [](double x) { return in_expansion_range<lo, hi>(x); }))
    return orient_dyadic(a, b, c, d, e, f, g, h, i);
  const Expansion<1> A(a), B(b), C(c), D(d), E(e), F(f), G(g), H(h), I(i);
  return (A * (E * I - F * H) - B * (D * I - F * G) + C * (D * H - E * G)).sign();
}

/// Δ of three homogeneous triples (a, b, c), (d, e, f), (g, h, i): exact (see the file comment).
inline Sign orient3(double a, double b, double c, double d, double e, double f, double g, double h, double i) {
  count_call();
  const double det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
  const double m0 = std::max({std::fabs(a), std::fabs(d), std::fabs(g)});
  const double m1 = std::max({std::fabs(b), std::fabs(e), std::fabs(h)});
  const double m2 = std::max({std::fabs(c), std::fabs(f), std::fabs(i)});
  const double lo = std::min({m0, m1, m2}), hi = std::max({m0, m1, m2});
  if (lo == 0) return ZERO;  // a column of zeros
  if (lo >= 0x1p-300 && hi <= 0x1p300) {
    const double bound = kOrient3Bound * m0 * m1 * m2;
    const int sign = (det > bound) - (-det > bound);
    if (sign != 0) [[likely]] return static_cast<Sign>(sign);
  }
  return orient3_exact(a, b, c, d, e, f, g, h, i);
}

}  // namespace t2::detail
