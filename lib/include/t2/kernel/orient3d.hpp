#pragma once
/// @file orient3d.hpp
/// @brief The orientation of four points of R³ (seed 004's `Volume6`, for 3-D hulls): exact on
/// `double` coordinates, with the fast path and exact stages of orient_double.hpp.
///
/// **Definition.** For p₀, p₁, p₂, p₃ of R³ let a = p₁ − p₀, b = p₂ − p₀, c = p₃ − p₀.
/// `orient3d(p₀, p₁, p₂, p₃)` is the sign of c · (a × b) = det[a; b; c] (rows): POSITIVE when p₃
/// lies in the *positive half-space* of the oriented triangle (p₀, p₁, p₂) — the side its normal
/// a × b points to, from where the triangle is seen counter-clockwise —, ZERO when the four
/// points are coplanar, NEGATIVE otherwise. `volume6` is that determinant: six times the signed
/// volume of the tetrahedron. Seed 004 (§ on Volume6) defines the same sign in words, then writes
/// the test as the 4×4 determinant with rows [xᵢ, yᵢ, zᵢ, 1]; that determinant is −c · (a × b)
/// (subtract the first row from the others and expand along the last column), so its sign is
/// the opposite one. The library follows the words (and Shewchuk's orient3d with the rows in the
/// order p₁, p₂, p₃ relative to p₀).
///
/// **Fast path.** The nine differences are rounded, then det = a·(e·i − f·h) − b·(d·i − f·g) +
/// c·(d·h − e·g) on the rows (a, b, c), (d, e, f), (g, h, i) of differences. Each of its six
/// monomials takes one difference from each column and meets 8 roundings (3 differences, the
/// inner product, the minor's subtraction, the outer product, at most 2 outer sums). With mₓ, m_y,
/// m_z the largest |rounded differences| of each column (the exact ones are at most m/(1 − u)),
/// |fl(det) − det| ≤ 6γ₈/(1 − u)³·mₓm_ym_z, and fl(fl(fl(C·mₓ)·m_y)·m_z) with C = 48u(1 + 2⁻⁴⁰)
/// exceeds it (C(1 − u)³ ≥ 48u/((1 − 8u)(1 − u)³)). Trusted when every m lies in [2⁻³⁰⁰, 2³⁰⁰],
/// where the underflow argument of orient_double.hpp applies verbatim; a column of zero
/// differences makes det = 0 exactly (the points share that coordinate).
///
/// **Exact stages.** Two-diff gives each difference with its tail; if no tail is nonzero the
/// determinant of the heads, evaluated as an expansion, is exact; otherwise the determinant of
/// the two-component differences is. Degree 3: nonzero coordinates in [2⁻³⁰⁰, 2³⁰⁰]. Outside
/// that range, dyadic GMP numbers.

#include <algorithm>
#include <cmath>

#include "t2/kernel/expansion.hpp"
#include "t2/kernel/filter.hpp"
#include "t2/kernel/detail/orient_double.hpp"
#include "t2/kernel/sign.hpp"

namespace t2 {

/// A point of R³ with `double` coordinates (for the 3-D hulls of Part V).
struct Point3 {
  double x = 0;  ///< first coordinate
  double y = 0;  ///< second coordinate
  double z = 0;  ///< third coordinate
};

namespace detail {

/// C of the file comment: 48u(1 + 2⁻⁴⁰).
inline constexpr double kOrient3dBound = 48 * kUnitRoundoff * (1 + 0x1p-40);

/// The 3×3 determinant of the rows (a, b, c), (d, e, f), (g, h, i) on any number type whose
/// operators may change the type (expansions).
template <class N>
auto det3_any(const N& a, const N& b, const N& c, const N& d, const N& e, const N& f, const N& g, const N& h,
              const N& i) {
  return (a * (e * i - f * h) - b * (d * i - f * g)) + c * (d * h - e * g);
}

/// The exact stages of orient3d (see the file comment).
[[gnu::noinline]] inline Sign orient3d_exact(const Point3& p, const Point3& q, const Point3& r, const Point3& s) {
  using namespace expansion;
  count_exact();
  const double v[12] = {p.x, p.y, p.z, q.x, q.y, q.z, r.x, r.y, r.z, s.x, s.y, s.z};
  if (!std::all_of(v, v + 12, [](double x) { return in_expansion_range<-300, 300>(x); })) {
    auto D = [](double x, double y) { return Dyadic(x) - Dyadic(y); };
    return sign_of(det3_any(D(q.x, p.x), D(q.y, p.y), D(q.z, p.z), D(r.x, p.x), D(r.y, p.y), D(r.z, p.z),
                            D(s.x, p.x), D(s.y, p.y), D(s.z, p.z)));
  }
  double h[9], t[9];
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j) two_diff(v[3 * (k + 1) + j], v[j], h[3 * k + j], t[3 * k + j]);
  if (std::all_of(t, t + 9, [](double x) { return x == 0; })) {
    Expansion<1> e[9];
    for (int k = 0; k < 9; ++k) e[k] = Expansion<1>(h[k]);
    return det3_any(e[0], e[1], e[2], e[3], e[4], e[5], e[6], e[7], e[8]).sign();
  }
  Expansion<2> e[9];
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j) e[3 * k + j] = diff(v[3 * (k + 1) + j], v[j]);
  return det3_any(e[0], e[1], e[2], e[3], e[4], e[5], e[6], e[7], e[8]).sign();
}

}  // namespace detail

//> orient3d
/// The orientation of p₃ relative to the oriented triangle (p₀, p₁, p₂) of R³: the sign of
/// (p₃ − p₀)·((p₁ − p₀) × (p₂ − p₀)), POSITIVE on the side the triangle's normal points to (see
/// the file comment). Exact for every finite input.
inline Sign orient3d(const Point3& p0, const Point3& p1, const Point3& p2, const Point3& p3) {
  detail::count_call();
  const double a = p1.x - p0.x, b = p1.y - p0.y, c = p1.z - p0.z;
  const double d = p2.x - p0.x, e = p2.y - p0.y, f = p2.z - p0.z;
  const double g = p3.x - p0.x, h = p3.y - p0.y, i = p3.z - p0.z;
  const double det = (a * (e * i - f * h) - b * (d * i - f * g)) + c * (d * h - e * g);
  const double mx = std::max({std::fabs(a), std::fabs(d), std::fabs(g)});
  const double my = std::max({std::fabs(b), std::fabs(e), std::fabs(h)});
  const double mz = std::max({std::fabs(c), std::fabs(f), std::fabs(i)});
  const double lo = std::min({mx, my, mz}), hi = std::max({mx, my, mz});
  if (lo == 0) return ZERO;  // the four points share a coordinate: coplanar
  if (lo >= 0x1p-300 && hi <= 0x1p300) {
    const double bound = detail::kOrient3dBound * mx * my * mz;
    const int sign = (det > bound) - (-det > bound);
    if (sign != 0) [[likely]] return static_cast<Sign>(sign);
  }
  return detail::orient3d_exact(p0, p1, p2, p3);
}
//< orient3d

/// Volume6 of seed 004: det[p₁ − p₀; p₂ − p₀; p₃ − p₀], six times the signed volume of the
/// tetrahedron, rounded (a construction; its sign may be wrong — decide with `orient3d`).
inline double volume6(const Point3& p0, const Point3& p1, const Point3& p2, const Point3& p3) {
  const double a = p1.x - p0.x, b = p1.y - p0.y, c = p1.z - p0.z;
  const double d = p2.x - p0.x, e = p2.y - p0.y, f = p2.z - p0.z;
  const double g = p3.x - p0.x, h = p3.y - p0.y, i = p3.z - p0.z;
  return detail::det3_any(a, b, c, d, e, f, g, h, i);
}

}  // namespace t2
