#pragma once
/// @file incircle_double.hpp
/// @brief The lifted in-circle determinant on `double` coordinates: fast path with a
/// semi-static error bound, exact stages of floating-point expansions, GMP outside their range.
/// Notation and method as in orient_double.hpp (u = 2⁻⁵³, γ_k = k·u/(1 − k·u), a monomial that
/// meets k roundings errs by at most γ_k times its magnitude).
///
/// **Cartesian points (every w = 1).** The lifted 4×4 determinant with rows [x, y, x² + y², 1]
/// does not change when every point is translated by −d (its third column changes by a
/// combination of the others), so it equals the 3×3 determinant
///
///     H = α·m₁ + β·m₂ + γ·m₃,  m₁ = b̂ₓĉ_y − ĉₓb̂_y,  m₂ = ĉₓâ_y − âₓĉ_y,  m₃ = âₓb̂_y − b̂ₓâ_y,
///
/// with â = a − d, b̂ = b − d, ĉ = c − d and α = âₓ² + â_y², β, γ the same for b̂, ĉ (Shewchuk's
/// form). Computed left to right, each monomial (e.g. âₓ²·b̂ₓ·ĉ_y) meets 11 roundings: 2 from
/// the rounded âₓ, 1 square, 1 sum in α, 2 differences b̂ₓ, ĉ_y, 1 product, 1 minor subtraction,
/// 1 product by α, at most 2 outer sums. With M_x, M_y the largest |differences| along x and y
/// (computed: mₓ, m_y; exact ones are at most m/(1 − u)) and M = max(M_x, M_y), the sum of
/// the magnitudes of the monomials is at most 3·(2M²)·(2M_xM_y), so |fl(H) − H| ≤ 12γ₁₁·M²M_xM_y
/// ≤ 12γ₁₁/(1 − u)⁴ · m²mₓm_y. The bound fl(fl(fl(C·lo)·hi)·fl(hi·hi)), lo = min(mₓ, m_y), hi =
/// max(mₓ, m_y) = m, is at least C(1 − u)⁴·lo·hi³; C = 132u(1 + 2⁻⁴⁰) makes it exceed the error.
///
/// The same minors give the orientation of a, b, c for free: Δ(a, b, c) = m₁ + m₂ + m₃ (Δ is
/// invariant under translation too). Each of its six monomials meets 6 roundings and is at most
/// M_xM_y, so |fl(Δ) − Δ| ≤ 6γ₆/(1 − u)²·mₓm_y, below fl(fl(C_o·mₓ)·m_y) with C_o = 36u(1 +
/// 2⁻⁴⁰). `in_circle` must throw for collinear a, b, c: this certifies Δ ≠ 0 without calling
/// `orient`.
///
/// Both bounds are trusted only when 2⁻²⁰⁰ ≤ lo and hi ≤ 2²⁰⁰: then nothing overflows, and an
/// operation that underflows errs by 2⁻¹⁰⁷⁵ at most, which the later factors multiply by at
/// most 2·hi² — at most 2⁻⁶⁷³ relative to lo·hi³, far below the margin 2⁻⁴⁰·C.
///
/// **Homogeneous points.** Rows [x w, y w, x² + y², w²], Laplace expansion along the first two
/// rows (six products of 2×2 minors). A monomial takes one entry from each column: 5 roundings
/// inside the entries (two for x² + y²), 2 in the upper minor, 2 in the lower one, 1 in their
/// product, at most 5 outer sums: 15. With m_w, mₓ, m_y the largest |w|, |x|, |y| of the four
/// points, the 24 terms of the determinant are each at most (mₓm_w)(m_ym_w)(mₓ² + m_y²)(m_w²), so
/// the error is at most 24γ₁₅·m_w⁴mₓm_y(mₓ² + m_y²); the code's bound, C_h = 360u(1 + 2⁻⁴⁰)
/// times that product evaluated with 8 roundings, exceeds it (C_h(1 − u)⁸ ≥ 360u/(1 − 15u)). It
/// is trusted when m_w, mₓ, m_y ∈ [2⁻¹⁰⁰, 2¹⁰⁰]: an underflow's 2⁻¹⁰⁷⁵ is then at most 2⁻²⁷⁵
/// relative to the bound.
///
/// **Exact stages.** First, for Cartesian input on a coarse grid, the fast path's own
/// evaluation: let 2^E be the smallest power of two above every |coordinate| (frexp), g =
/// 2^(E−11), and suppose every coordinate is k·g with k an integer (|k| < 2¹¹) and E ∈ [−200,
/// 200]. Then every quantity of the evaluation is an integer multiple of a power of g whose
/// integer part is below 2⁵³, so no operation rounds: the differences are k·g with |k| < 2¹²,
/// the squares, products and their sums and differences (α, m₁, …) are k·g² with |k| < 2²⁵, the
/// terms α·m are k·g⁴ with |k| < 2⁵⁰ and H is a sum of three of them, |k| < 3·2⁵⁰ < 2⁵³; g⁴ ≥
/// 2⁻⁸⁴⁴ is normal and 2⁵³g⁴ ≤ 2⁸⁶¹ is finite. So fl(H) = H, zero included. Small integer
/// grids (every |x| < 2¹¹) are the common case; they fail the fast path only when H = 0, and this
/// certifies the zero at the cost of one more evaluation.
/// Then expansions (expansion.hpp); nonzero |coordinates| must lie in [2⁻²¹⁰,
/// 2²⁵⁰] (degree 4) for Cartesian input, in [2⁻⁸⁰, 2¹²⁰] (degree 8) for homogeneous input;
/// outside, dyadic GMP numbers decide. For Cartesian input an adaptive stage comes first (in the
/// spirit of Shewchuk's stages B and C). Two-diff splits each difference into its rounded head
/// xᵢ and the tail tᵢ rounded away (|tᵢ| ≤ u|xᵢ|), and H(x + t) = E₀ + R₁ + R₂ with E₀ = H(x),
/// R₁ = Σ tᵢ∂H/∂xᵢ(x) and R₂ the terms of degree ≥ 2 in the tails. Let P be the permanent (the
/// sum of the magnitudes of the monomials of H at x).
/// - E₀ is evaluated in double-word arithmetic (expansion.hpp): exact products, then sums with
///   relative error ≤ 3u²(1 + 5u) and products with ≤ 5u². Each monomial goes through the minor's
///   sum, the lift's sum, their product and two outer sums, so |ê − E₀| ≤ 18u²P.
/// - A monomial of degree 4 gives at most ((1 + u)⁴ − 1 − 4u)|m(x)| ≤ 6.01u²|m(x)| to R₂, so
///   |R₂| ≤ 6.01u²P; the monomials of R₁ sum to at most 4uP and its rounded value r₁ meets at most
///   11 roundings: |R₁ − r₁| ≤ 4γ₁₁uP ≤ 44.1u²P.
/// - s = fl(ê_hi + fl(ê_lo + r₁)) adds u|ê_lo + r₁| ≤ 5.1u²P and u|s|.
/// So |H − s| ≤ 73.3u²P + u|s|, which 128u²P̂ (P̂ the rounded P, at least P(1 − u)⁷) exceeds
/// whenever |s| exceeds it. This runs only when every nonzero head lies in [2⁻¹²⁰, 2¹²⁰]: every
/// quantity is then 0 or above 2⁻⁷⁰⁰ (a multiple of the heads' lowest bits) and below 2⁵⁰⁰, so
/// the relative error model holds. When it cannot decide (exactly cocircular input, mostly),
/// H is evaluated exactly as an expansion: of the heads alone when no tail is nonzero, of the
/// two-component differences otherwise.

#include <algorithm>
#include <cmath>

#include "t2/kernel/expansion.hpp"
#include "t2/kernel/filter.hpp"
#include "t2/kernel/detail/orient_double.hpp"
#include "t2/kernel/sign.hpp"

namespace t2::detail {

/// C of the file comment: 132u(1 + 2⁻⁴⁰).
inline constexpr double kInCircle2Bound = 132 * kUnitRoundoff * (1 + 0x1p-40);
/// C_o of the file comment: 36u(1 + 2⁻⁴⁰).
inline constexpr double kInCircleOrientBound = 36 * kUnitRoundoff * (1 + 0x1p-40);
/// C_h of the file comment: 360u(1 + 2⁻⁴⁰).
inline constexpr double kInCircle3Bound = 360 * kUnitRoundoff * (1 + 0x1p-40);

/// The lifted 4×4 determinant with rows [x w, y w, x² + y², w²] (Laplace along two rows), on any
/// number type whose operators may return other types (expansions grow with each operation).
template <class N>
auto lifted_det4_any(const N& aw, const N& ax, const N& ay, const N& bw, const N& bx, const N& by, const N& cw,
                     const N& cx, const N& cy, const N& dw, const N& dx, const N& dy) {
  const auto r00 = ax * aw, r01 = ay * aw, r03 = aw * aw;
  const auto r02 = ax * ax + ay * ay;
  const auto r10 = bx * bw, r11 = by * bw, r13 = bw * bw;
  const auto r12 = bx * bx + by * by;
  const auto r20 = cx * cw, r21 = cy * cw, r23 = cw * cw;
  const auto r22 = cx * cx + cy * cy;
  const auto r30 = dx * dw, r31 = dy * dw, r33 = dw * dw;
  const auto r32 = dx * dx + dy * dy;
  return ((((((r00 * r11 - r01 * r10) * (r22 * r33 - r23 * r32)) - ((r00 * r12 - r02 * r10) * (r21 * r33 - r23 * r31))) +
            ((r00 * r13 - r03 * r10) * (r21 * r32 - r22 * r31))) +
           ((r01 * r12 - r02 * r11) * (r20 * r33 - r23 * r30))) -
          ((r01 * r13 - r03 * r11) * (r20 * r32 - r22 * r30))) +
         ((r02 * r13 - r03 * r12) * (r20 * r31 - r21 * r30));
}

/// The Cartesian H of the file comment on expansions (differences already taken), each term
/// α·m₁ as âₓ·(âₓ·m₁) + â_y·(â_y·m₁): scaling by a short expansion is much cheaper than a
/// product of two long ones (Shewchuk's order of operations).
template <class N>
auto incircle2_any(const N& adx, const N& ady, const N& bdx, const N& bdy, const N& cdx, const N& cdy) {
  const auto m1 = bdx * cdy - cdx * bdy, m2 = cdx * ady - adx * cdy, m3 = adx * bdy - bdx * ady;
  return ((m1 * adx) * adx + (m1 * ady) * ady + ((m2 * bdx) * bdx + (m2 * bdy) * bdy)) +
         ((m3 * cdx) * cdx + (m3 * cdy) * cdy);
}

/// R₁ of the file comment: the terms of H(x + t) that are linear in the tails t of the
/// differences x = (âₓ, â_y, b̂ₓ, b̂_y, ĉₓ, ĉ_y), i.e. Σ tᵢ·∂H/∂xᵢ(x), rounded.
inline double incircle2_first_order(const double (&x)[6], const double (&t)[6]) {
  const double adx = x[0], ady = x[1], bdx = x[2], bdy = x[3], cdx = x[4], cdy = x[5];
  const double m1 = bdx * cdy - cdx * bdy, m2 = cdx * ady - adx * cdy, m3 = adx * bdy - bdx * ady;
  const double al = adx * adx + ady * ady, be = bdx * bdx + bdy * bdy, ga = cdx * cdx + cdy * cdy;
  return ((t[0] * ((2 * adx * m1 - be * cdy) + ga * bdy) + t[1] * ((2 * ady * m1 + be * cdx) - ga * bdx)) +
          (t[2] * ((2 * bdx * m2 + al * cdy) - ga * ady) + t[3] * ((2 * bdy * m2 - al * cdx) + ga * adx))) +
         (t[4] * ((2 * cdx * m3 - al * bdy) + be * ady) + t[5] * ((2 * cdy * m3 + al * bdx) - be * adx));
}

/// H at the rounded differences x in double-word arithmetic (see the file comment).
inline expansion::DoubleWord incircle2_double_word(const double (&x)[6]) {
  using namespace expansion;
  const double adx = x[0], ady = x[1], bdx = x[2], bdy = x[3], cdx = x[4], cdy = x[5];
  auto minor = [](double p, double q, double r, double s) { return dw_add(dw_prod(p, q), dw_neg(dw_prod(r, s))); };
  auto lift = [](double p, double q) { return dw_add(dw_prod(p, p), dw_prod(q, q)); };
  return dw_add(dw_add(dw_mul(lift(adx, ady), minor(bdx, cdy, cdx, bdy)), dw_mul(lift(bdx, bdy), minor(cdx, ady, adx, cdy))),
                dw_mul(lift(cdx, cdy), minor(adx, bdy, bdx, ady)));
}

/// The permanent of H at x: the sum of the magnitudes of its monomials, rounded.
inline double incircle2_permanent(const double (&x)[6]) {
  const double adx = x[0], ady = x[1], bdx = x[2], bdy = x[3], cdx = x[4], cdy = x[5];
  return ((adx * adx + ady * ady) * (std::fabs(bdx * cdy) + std::fabs(cdx * bdy)) +
          (bdx * bdx + bdy * bdy) * (std::fabs(cdx * ady) + std::fabs(adx * cdy))) +
         (cdx * cdx + cdy * cdy) * (std::fabs(adx * bdy) + std::fabs(bdx * ady));
}

/// Do the coordinates lie on the coarse grid of the file comment, k·2^(E−11) with |k| < 2¹¹,
/// 2^E the smallest power of two above all of them, E ∈ [−200, 200]? Then the fast path's
/// evaluation of H is exact.
inline bool on_coarse_grid(const double (&v)[8]) {
  double hi = 0;
  for (const double x : v) hi = std::max(hi, std::fabs(x));
  int e = 0;
  (void)std::frexp(hi, &e);  // hi < 2^e (e = 0 for hi = 0)
  if (e < -200 || e > 200) return false;
  const double s = std::ldexp(1.0, 11 - e);
  for (const double x : v) {
    const double k = x * s;  // exact (a power of two, no underflow), |k| < 2^11
    if (static_cast<double>(static_cast<int>(k)) != k) return false;
  }
  return true;
}

/// The exact sign of the lifted determinant of four Cartesian points.
[[gnu::noinline]] inline Sign incircle2_exact(double ax, double ay, double bx, double by, double cx, double cy,
                                              double dx, double dy) {
  using namespace expansion;
  count_exact();
  const double v[8] = {ax, ay, bx, by, cx, cy, dx, dy};
  if (on_coarse_grid(v)) {  // the fast path's evaluation is exact (file comment)
    const double adx = ax - dx, ady = ay - dy, bdx = bx - dx, bdy = by - dy, cdx = cx - dx, cdy = cy - dy;
    const double m1 = bdx * cdy - cdx * bdy, m2 = cdx * ady - adx * cdy, m3 = adx * bdy - bdx * ady;
    const double h = ((adx * adx + ady * ady) * m1 + (bdx * bdx + bdy * bdy) * m2) + (cdx * cdx + cdy * cdy) * m3;
    return static_cast<Sign>((h > 0) - (h < 0));
  }
  if (!std::all_of(v, v + 8, [](double x) { return in_expansion_range<-210, 250>(x); })) {
    const Dyadic one(1.0);
    return sign_of(lifted_det4_any(one, Dyadic(ax), Dyadic(ay), one, Dyadic(bx), Dyadic(by), one, Dyadic(cx),
                                   Dyadic(cy), one, Dyadic(dx), Dyadic(dy)));
  }
  double d[6], t[6];
  two_diff(ax, dx, d[0], t[0]);
  two_diff(ay, dy, d[1], t[1]);
  two_diff(bx, dx, d[2], t[2]);
  two_diff(by, dy, d[3], t[3]);
  two_diff(cx, dx, d[4], t[4]);
  two_diff(cy, dy, d[5], t[5]);
  //> incircle2-adaptive
  if (std::all_of(d, d + 6, [](double x) { return in_expansion_range<-120, 120>(x); })) {
    const DoubleWord e0 = incircle2_double_word(d);  // H of the rounded differences, to ~u²
    const double s = e0.hi + (e0.lo + incircle2_first_order(d, t));
    const double bound = 0x1p-99 * incircle2_permanent(d);  // 128u²P
    const int sign = (s > bound) - (-s > bound);
    if (sign != 0) return static_cast<Sign>(sign);
  }
  const Expansion<1> A(d[0]), B(d[1]), C(d[2]), D(d[3]), E(d[4]), F(d[5]);
  if (std::all_of(t, t + 6, [](double x) { return x == 0; }))  // no difference was rounded
    return incircle2_any(A, B, C, D, E, F).sign();
  //< incircle2-adaptive
  return incircle2_any(diff(ax, dx), diff(ay, dy), diff(bx, dx), diff(by, dy), diff(cx, dx), diff(cy, dy)).sign();
}

/// What the fast path of the Cartesian in-circle test certified.
struct InCircleFast {
  int orient;    ///< sign of Δ(a, b, c), or 2 when not certified
  int incircle;  ///< sign of the lifted determinant, or 2 when not certified
};

//> incircle2-fast
/// The fast path for four Cartesian points: H and Δ(a, b, c) (see the file comment).
inline InCircleFast incircle2_fast(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                                   double dy) {
  count_call();
  const double adx = ax - dx, ady = ay - dy, bdx = bx - dx, bdy = by - dy, cdx = cx - dx, cdy = cy - dy;
  const double m1 = bdx * cdy - cdx * bdy, m2 = cdx * ady - adx * cdy, m3 = adx * bdy - bdx * ady;
  const double det = ((adx * adx + ady * ady) * m1 + (bdx * bdx + bdy * bdy) * m2) + (cdx * cdx + cdy * cdy) * m3;
  const double o = (m1 + m2) + m3;
  const double mx = std::max({std::fabs(adx), std::fabs(bdx), std::fabs(cdx)});
  const double my = std::max({std::fabs(ady), std::fabs(bdy), std::fabs(cdy)});
  const double lo = std::min(mx, my), hi = std::max(mx, my);
  InCircleFast r{2, 2};
  if (lo >= 0x1p-200 && hi <= 0x1p200) {
    const double ob = kInCircleOrientBound * mx * my;
    const int so = (o > ob) - (-o > ob);
    r.orient = so != 0 ? so : 2;
    const double hb = kInCircle2Bound * lo * hi * (hi * hi);
    const int sh = (det > hb) - (-det > hb);
    r.incircle = sh != 0 ? sh : 2;
  }
  return r;
}
//< incircle2-fast

/// The exact stage of the homogeneous lifted determinant.
[[gnu::noinline]] inline Sign incircle3_exact(const double (&v)[12]) {
  using namespace expansion;
  count_exact();
  if (std::all_of(v, v + 12, [](double x) { return in_expansion_range<-80, 120>(x); })) {
    Expansion<1> e[12];
    for (int i = 0; i < 12; ++i) e[i] = Expansion<1>(v[i]);
    return lifted_det4_any(e[0], e[1], e[2], e[3], e[4], e[5], e[6], e[7], e[8], e[9], e[10], e[11]).sign();
  }
  return sign_of(lifted_det4_any(Dyadic(v[0]), Dyadic(v[1]), Dyadic(v[2]), Dyadic(v[3]), Dyadic(v[4]), Dyadic(v[5]),
                                 Dyadic(v[6]), Dyadic(v[7]), Dyadic(v[8]), Dyadic(v[9]), Dyadic(v[10]),
                                 Dyadic(v[11])));
}

/// The sign of the homogeneous lifted determinant of [w, x, y] triples a, b, c, d (exact).
inline Sign incircle3(double aw, double ax, double ay, double bw, double bx, double by, double cw, double cx,
                      double cy, double dw, double dx, double dy) {
  count_call();
  const double det = lifted_det4_any(aw, ax, ay, bw, bx, by, cw, cx, cy, dw, dx, dy);
  const double mw = std::max({std::fabs(aw), std::fabs(bw), std::fabs(cw), std::fabs(dw)});
  const double mx = std::max({std::fabs(ax), std::fabs(bx), std::fabs(cx), std::fabs(dx)});
  const double my = std::max({std::fabs(ay), std::fabs(by), std::fabs(cy), std::fabs(dy)});
  const double lo = std::min({mw, mx, my}), hi = std::max({mw, mx, my});
  if (lo >= 0x1p-100 && hi <= 0x1p100) {
    const double w2 = mw * mw;
    const double bound = kInCircle3Bound * (w2 * w2) * (mx * my) * (mx * mx + my * my);
    const int sign = (det > bound) - (-det > bound);
    if (sign != 0) [[likely]] return static_cast<Sign>(sign);
  }
  const double v[12] = {aw, ax, ay, bw, bx, by, cw, cx, cy, dw, dx, dy};
  return incircle3_exact(v);
}

}  // namespace t2::detail
