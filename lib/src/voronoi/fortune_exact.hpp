#pragma once
// The exact stages of Fortune's sweep (fortune.cpp) for sites whose coordinates are doubles
// (w = 1): each sign is a polynomial sign of the kernel's filter (filter.hpp: a floating-point
// filter, then expansions, then GMP only outside their range), with the coordinates as numbers,
// so no rational is made. Private to lib/src/voronoi.
//
// Every polynomial below is homogeneous in the coordinates (one total degree in all its
// monomials: a translation or a scaling of the plane does not change its sign pattern), which is
// what filter.hpp's bound needs.

#include <cmath>

#include "fortune_interval.hpp"
#include "t2/kernel/expansion.hpp"
#include "t2/kernel/filter.hpp"
#include "t2/kernel/incircle.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/sign.hpp"

namespace t2::detail {

//> fortune-breakpoint-doubles
/// sign(β − a), β the abscissa of the breakpoint of the arcs of p = (xp, yp) (left) and q =
/// (xq, yq) (right) when the sweep line is y = L, for the site (a, L) (fortune.hpp): with
/// dp = yp − L ≤ 0 and dq = yq − L ≤ 0, it is sign(dq − dp)·sign(A − √C) for A = dq·xp − dp·xq −
/// a(dq − dp) and C = dp·dq·|pq|² ≥ 0. sign(A − √C) is sign(A) when A < 0, −sign(C) when A = 0,
/// and sign(A² − C) when A > 0. When dp = dq the breakpoint is the midpoint: sign(xp + xq − 2a).
inline Sign breakpoint_sign(double xp, double yp, double xq, double yq, double a, double L) {
  if (yp == yq)
    return sign_of_poly([](const auto& xp, const auto& xq, const auto& a) { return xp + xq - a - a; }, xp, xq, a);
  const Sign side = yq > yp ? POSITIVE : NEGATIVE;  // sign(dq − dp)
  const Sign A = sign_of_poly(
      [](const auto& xp, const auto& yp, const auto& xq, const auto& yq, const auto& a, const auto& L) {
        return (yq - L) * xp - (yp - L) * xq - a * (yq - yp);
      },
      xp, yp, xq, yq, a, L);
  if (A == NEGATIVE) return -side;
  if (A == ZERO) return yp == L || yq == L ? ZERO : -side;  // C = 0 exactly when dp or dq is 0
  const Sign d = sign_of_poly(
      [](const auto& xp, const auto& yp, const auto& xq, const auto& yq, const auto& a, const auto& L) {
        const auto A = (yq - L) * xp - (yp - L) * xq - a * (yq - yp);
        return A * A - (yp - L) * (yq - L) * ((xp - xq) * (xp - xq) + (yp - yq) * (yp - yq));
      },
      xp, yp, xq, yq, a, L);
  return side * d;
}
//< fortune-breakpoint-doubles

/// sign(e − s) in the order of events (y, then x; a circle event first at one point) for the
/// circle event of a, b, c (counter-clockwise) and the site s. With b' = b − a, c' = c − a,
/// D = 2(b'ₓc'ᵧ − b'ᵧc'ₓ) > 0, B = |b'|², C = |c'|², the centre is a + (Nₓ, Nᵧ)/D with Nₓ = c'ᵧB −
/// b'ᵧC, Nᵧ = b'ₓC − c'ₓB, and the radius √Q/D with Q = Nₓ² + Nᵧ² > 0. So the event's y minus
/// s's is (A + √Q)/D with A = (aᵧ − sᵧ)D + Nᵧ: positive when A ≥ 0, else sign(Q − A²); on a tie
/// the x order is sign((aₓ − sₓ)D + Nₓ).
inline Sign circle_top_vs_site(double ax, double ay, double bx, double by, double cx, double cy, double sx, double sy) {
  const Sign A = sign_of_poly(
      [](const auto& ax, const auto& ay, const auto& bx, const auto& by, const auto& cx, const auto& cy, const auto&,
         const auto& sy) {
        const auto ux = bx - ax, uy = by - ay, vx = cx - ax, vy = cy - ay;
        const auto D = (ux * vy - uy * vx) + (ux * vy - uy * vx);
        return (ay - sy) * D + ux * (vx * vx + vy * vy) - vx * (ux * ux + uy * uy);
      },
      ax, ay, bx, by, cx, cy, sx, sy);
  if (A != NEGATIVE) return POSITIVE;
  // A < 0: s is above the centre. On the circle (in_circle = 0, degree 4: cheaper than the
  // degree 6 below), s is the top, a tie resolved for the circle, exactly when it is on the
  // centre's vertical (the x order is 0); else it is below the top.
  const auto x_order = [&] {
    return sign_of_poly(
        [](const auto& ax, const auto& ay, const auto& bx, const auto& by, const auto& cx, const auto& cy,
           const auto& sx, const auto&) {
          const auto ux = bx - ax, uy = by - ay, vx = cx - ax, vy = cy - ay;
          const auto D = (ux * vy - uy * vx) + (ux * vy - uy * vx);
          return (ax - sx) * D + vy * (ux * ux + uy * uy) - uy * (vx * vx + vy * vy);
        },
        ax, ay, bx, by, cx, cy, sx, sy);
  };
  if (in_circle(Point(1, ax, ay), Point(1, bx, by), Point(1, cx, cy), Point(1, sx, sy)) == ZERO)
    return x_order() == ZERO ? NEGATIVE : POSITIVE;
  const Sign y = sign_of_poly(
      [](const auto& ax, const auto& ay, const auto& bx, const auto& by, const auto& cx, const auto& cy, const auto&,
         const auto& sy) {
        const auto ux = bx - ax, uy = by - ay, vx = cx - ax, vy = cy - ay;
        const auto B = ux * ux + uy * uy, C = vx * vx + vy * vy;
        const auto D = (ux * vy - uy * vx) + (ux * vy - uy * vx);
        const auto Nx = vy * B - uy * C, Ny = ux * C - vx * B;
        const auto A = (ay - sy) * D + Ny;
        return Nx * Nx + Ny * Ny - A * A;
      },
      ax, ay, bx, by, cx, cy, sx, sy);
  if (y != ZERO) return y;
  const Sign x = x_order();
  return x != ZERO ? x : NEGATIVE;
}

/// sign(2cₓ − S), cₓ the abscissa of the centre of the circle through a, b, c (counter-
/// clockwise): with D' = D/2 > 0 (notation of circle_top_vs_site), 2cₓ − S = 2aₓ − S + Nₓ/D'.
inline Sign centre_x_vs(double ax, double ay, double bx, double by, double cx, double cy, double S) {
  return sign_of_poly(
      [](const auto& ax, const auto& ay, const auto& bx, const auto& by, const auto& cx, const auto& cy, const auto& S) {
        const auto ux = bx - ax, uy = by - ay, vx = cx - ax, vy = cy - ay;
        return (ax + ax - S) * (ux * vy - uy * vx) + vy * (ux * ux + uy * uy) - uy * (vx * vx + vy * vy);
      },
      ax, ay, bx, by, cx, cy, S);
}

/// An enclosure of the sum of an expansion's components (each exact: a point interval).
template <int N>
Interval enclose(const expansion::Expansion<N>& e) {
  Interval s{0, 0};
  for (int i = 0; i < e.n; ++i) s = s + Interval{e.c[i], e.c[i]};
  return s;
}

/// A tight enclosure of the y of the circle event of a, b, c (counter-clockwise; the formula of
/// circle_top_vs_site: y = aᵧ + (Nᵧ + √Q)/D), or the whole line when a coordinate is outside
/// [2⁻³⁰⁰, 2³⁰⁰] (then an expansion of degree 3 could underflow or overflow). D, Nₓ, Nᵧ are
/// evaluated exactly as expansions (expansion.hpp) and enclosed by the interval sums of their
/// components, so they carry no error from the cancellations of ill-conditioned circles (three
/// nearly collinear sites), which make the interval formula of event_y wide; Nᵧ + √Q is read
/// as Nₓ²/(√Q − Nᵧ) when Nᵧ < 0 (no cancellation). Every step is an Interval operation, so the
/// result contains the exact y (fortune_interval.hpp).
inline Interval tight_event_y(double ax, double ay, double bx, double by, double cx, double cy) {
  for (double v : {ax, ay, bx, by, cx, cy})
    if (!expansion::in_expansion_range<-300, 300>(v)) return {-HUGE_VAL, HUGE_VAL};
  using expansion::diff;
  const auto ux = diff(bx, ax), uy = diff(by, ay), vx = diff(cx, ax), vy = diff(cy, ay);
  const auto d = ux * vy - uy * vx;
  const auto B = ux * ux + uy * uy, C = vx * vx + vy * vy;
  const Interval D = enclose(d + d), Nx = enclose(vy * B - uy * C), Ny = enclose(ux * C - vx * B);
  const Interval r = sqrt(Nx * Nx + Ny * Ny);
  Interval T;
  if (Ny.hi < 0) T = Nx * Nx * recip(r - Ny);
  else T = Ny + r;
  return (Interval{ay, ay} + T * recip(D)).settled();
}

/// a − b as a double, and whether it is exact (Knuth's TwoSum: the rounding error, computed
/// exactly when nothing overflows, is 0).
inline bool exact_difference(double a, double b, double& d) {
  const double y = -b;
  d = a + y;
  const double yv = d - a, av = d - yv;
  return std::isfinite(d) && (a - av) + (y - yv) == 0;
}

}  // namespace t2::detail
