#pragma once
//> incircle-definition
/// @file incircle.hpp
/// @brief The in-circle test of T²: is d inside the oriented circle through a, b, c?
///
/// **Front points.** For a, b, c, d on the front side this is the Euclidean predicate of
/// the lifting map (seed 002): lift each point (X, Y) to (X, Y, X² + Y²) on the
/// paraboloid; d is inside the circle through a, b, c exactly when its lift lies below
/// the plane of theirs. In homogeneous coordinates each row of the 4×4 determinant
/// |X, Y, X² + Y², 1| is multiplied by w² > 0, which gives the polynomial rows
/// [x w, y w, x² + y², w²] and keeps the sign. The result follows CGAL's
/// `side_of_oriented_circle`: POSITIVE when d is inside the circle through a, b, c and a,
/// b, c turn counter-clockwise, NEGATIVE outside, ZERO on it; reversing the turn of a, b,
/// c reverses the answer.
///
/// **Both sides: the definition of T².** The homogeneous determinant alone is blind to
/// sides (it gives ¬d the same sign as d), so T² needs a definition. With the squared
/// distances of §4.3.1 (distance.hpp), a circle of T² has a centre z and a radius in T¹;
/// a point of the other side than z is *beyond infinity* from z. So three points on both
/// sides of T² (or on Ω) lie on no circle with a proper centre: their circle is centred
/// on Ω (the lunes below). Three collinear points lie on no circle at all, and
/// `in_circle` throws `Undefined` for them. For a, b, c proper on one side σ and not
/// collinear, let z be their circumcentre on side σ and r² = d²(z, a); the *disk* is the
/// set of points with d²(z, d) < r² in the T¹ order, i.e. the points of side σ strictly
/// inside the Euclidean circle. Then
///
///     in_circle(a, b, c, d) = orient(a, b, c)
///         · (+1 if d is in the disk, 0 if d²(z, d) = r², −1 otherwise)
///
/// so a point d on the other side or on Ω is always outside the disk. The interior is the
/// side to the left of the oriented circle a → b → c: the disk when orient(a, b, c) > 0,
/// and its complement — the disk of the antipodal centre ¬z, whose radius is beyond
/// infinity — when it is negative. Note that for three back points orient(a, b, c) is the
/// opposite of the turn their drawn positions make (the planar model shows the back side
/// mirrored).
///
/// **Centres on Ω: lunes.** Seen from a point u of Ω, the sweep rule of §4.3.1 orders the
/// points of each side by their normalized coordinates along u, key_u(p) = u·(x, y)/|w|
/// (the larger, the nearer), and leaves a front and a back point incomparable. So a disk
/// centred at u has one radius on each side: on each side it is an open half-plane
/// {key_u > k}, bounded by a half-line perpendicular to u, and its boundary is a *lune*:
/// two half great circles of the sphere from the point E = u⊥ of Ω to ¬E, one on each
/// side (or one of them on Ω). A lune is a circle through a, b, c when a, b, c are not
/// all proper on one side:
/// - *a, b proper on side σ, c on side −σ or on Ω:* the half of the line a ∨ b on side σ,
///   from ¬E through a, b to E, the point of Ω the line reaches after b; then the half of
///   E ∨ c on the other side (if c is on Ω, the half of Ω through c) back to ¬E. On side
///   σ the interior is the left of a → b; on side −σ, for c proper, the points d with
///   Δ(a, b, d)/|w_d| > Δ(a, b, c)/|w_c| (farther to the left of a ∨ b than c, the two
///   signs of w the same) and for c on Ω all of side −σ or none; on Ω the open half of Ω
///   to the left of a ∨ b (the half through c itself, when c is on Ω, is the circle:
///   ZERO). **With c on Ω this is the limit case of a triangle with a vertex at infinity:
///   the circle through two points and a point at infinity is their line,** its inside
///   the half-plane to the left of a → b (CGAL's infinite vertex, made exact on every
///   side of T²);
/// - *a on side σ, b on side −σ, c on Ω:* E = c; the half of a ∨ c on side σ and the half
///   of b ∨ c on side −σ; the interior is the left of c → a on side σ and on Ω, the left
///   of b → c on side −σ.
///
/// The answer is +1 left of the oriented lune a → b → c, 0 on it, −1 right of it — the
/// same rule as for a finite circle, so reversing a, b, c again reverses the answer, a
/// rotation of a, b, c does not change it, and in_circle(¬a, ¬b, ¬c, ¬d) =
/// −in_circle(a, b, c, d). A lune through a, b, c exists only if they are not collinear
/// (else `Undefined`); with two of a, b, c on Ω and one proper there are infinitely many
/// (any E with both on one half of Ω), and `in_circle` throws `Undefined`.
//< incircle-definition

#include <algorithm>

#include "t2/kernel/error.hpp"
#include <type_traits>

#include "t2/kernel/filter.hpp"
#include "t2/kernel/detail/incircle_double.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/sign.hpp"

namespace t2 {

namespace detail {

/// The error for three collinear points, which span no circle.
inline Undefined collinear_circle() {
  return Undefined("in_circle(a, b, c, d) is undefined when a, b, c are collinear: they span no circle");
}

/// The lifted 4×4 determinant with rows [x w, y w, x² + y², w²] (Laplace along two rows).
template <class N>
N lifted_det4(const N& aw, const N& ax, const N& ay, const N& bw, const N& bx, const N& by, const N& cw,
              const N& cx, const N& cy, const N& dw, const N& dx, const N& dy) {
  return lifted_det4_any(aw, ax, ay, bw, bx, by, cw, cx, cy, dw, dx, dy);
}

/// The sign of the lifted determinant for points on one side: fast path and exact stages on
/// doubles (incircle_double.hpp); integers take it when they fit in 52 bits, GMP otherwise.
template <class T>
Sign lifted_sign(const BasicPoint<T>& a, const BasicPoint<T>& b, const BasicPoint<T>& c, const BasicPoint<T>& d) {
  if constexpr (std::is_same_v<T, double>) {
    return incircle3(a.w(), a.x(), a.y(), b.w(), b.x(), b.y(), c.w(), c.x(), c.y(), d.w(), d.x(), d.y());
  } else {
    const T* v[12] = {&a.w(), &a.x(), &a.y(), &b.w(), &b.x(), &b.y(), &c.w(), &c.x(), &c.y(), &d.w(), &d.x(), &d.y()};
    if (std::all_of(v, v + 12, [](const T* x) { return fits_filter(*x); })) {
      double f[12];
      for (int i = 0; i < 12; ++i) f[i] = v[i]->get_d();
      if (f[0] == 1 && f[3] == 1 && f[6] == 1 && f[9] == 1) {
        const InCircleFast r = incircle2_fast(f[1], f[2], f[4], f[5], f[7], f[8], f[10], f[11]);
        return r.incircle != 2 ? static_cast<Sign>(r.incircle)
                               : incircle2_exact(f[1], f[2], f[4], f[5], f[7], f[8], f[10], f[11]);
      }
      return incircle3(f[0], f[1], f[2], f[3], f[4], f[5], f[6], f[7], f[8], f[9], f[10], f[11]);
    }
    return exact_sign([](const auto&... x) { return lifted_det4(x...); }, a.w(), a.x(), a.y(), b.w(), b.x(), b.y(),
                      c.w(), c.x(), c.y(), d.w(), d.x(), d.y());
  }
}

}  // namespace detail

namespace detail {

/// The rest of in_circle on four Cartesian points when the fast path left something open.
[[gnu::noinline]] inline Sign in_circle_cartesian_slow(const Point& a, const Point& b, const Point& c, const Point& d,
                                                       InCircleFast f) {
  if (f.orient == 2 && orient(a, b, c) == ZERO) throw collinear_circle();
  return f.incircle != 2 ? static_cast<Sign>(f.incircle)
                         : incircle2_exact(a.x(), a.y(), b.x(), b.y(), c.x(), c.y(), d.x(), d.y());
}

//> incircle-lunes
/// The lune through a, b on one side σ and c on side −σ or on Ω (file comment); o = Δ(a, b, c).
template <class T>
Sign in_lune_of_pair(const BasicPoint<T>& a, const BasicPoint<T>& b, const BasicPoint<T>& c, const BasicPoint<T>& d,
                     Sign o) {
  const Sign sigma = sign_of(a.w()), sd = sign_of(d.w());
  if (sd == sigma) return orient(a, b, d);  // the half of a ∨ b
  if (c.w() == 0) {                           // the circle closes along Ω through c
    if (sd != ZERO) return -o;                // all of side −σ, or none of it
    const Sign s = orient(a, b, d);
    return s == o ? ZERO : s;  // the half of Ω through c is on the circle
  }
  if (sd == ZERO) return orient(a, b, d);  // the half of Ω left of a ∨ b
  // Side −σ: sign(Δ(a,b,d)/|w_d| − Δ(a,b,c)/|w_c|) = σ·sign(Δ(a,b,c)·w_d − Δ(a,b,d)·w_c).
  return sigma * sign_of_poly(
                     [](const auto& p, const auto& q, const auto& r, const auto& s) {
                       return det3(p, q, r) * s.w - det3(p, q, s) * r.w;
                     },
                     a, b, c, d);
}

/// The lune through a on side σ, b on side −σ and c on Ω (file comment).
template <class T>
Sign in_lune_across(const BasicPoint<T>& a, const BasicPoint<T>& b, const BasicPoint<T>& c, const BasicPoint<T>& d) {
  return sign_of(d.w()) == -sign_of(a.w()) ? orient(b, c, d) : orient(c, a, d);
}

/// in_circle when a, b, c are not all proper on one side: the lunes of the file comment.
template <class T>
Sign in_circle_lune(const BasicPoint<T>& a, const BasicPoint<T>& b, const BasicPoint<T>& c, const BasicPoint<T>& d) {
  const Sign s[3] = {sign_of(a.w()), sign_of(b.w()), sign_of(c.w())};
  if ((s[0] != ZERO) + (s[1] != ZERO) + (s[2] != ZERO) < 2)
    throw Undefined(
        "in_circle(a, b, c, d) is undefined when two of a, b, c are on Omega and one is proper: infinitely many "
        "lunes pass through them");
  const Sign o = orient(a, b, c);
  if (o == ZERO) throw collinear_circle();
  const BasicPoint<T>* p[3] = {&a, &b, &c};
  // Rotate a, b, c (which keeps the circle and its orientation) so that the odd one is last:
  // the point on Ω if there is one, else the one alone on its side.
  int k = 0;
  if (s[0] == ZERO || s[1] == ZERO || s[2] == ZERO) {
    while (s[k] != ZERO) ++k;
  } else {
    while (s[k] == s[(k + 1) % 3] || s[k] == s[(k + 2) % 3]) ++k;
  }
  const BasicPoint<T>&u = *p[(k + 1) % 3], &v = *p[(k + 2) % 3], &w = *p[k];
  if (sign_of(u.w()) == sign_of(v.w())) return in_lune_of_pair(u, v, w, d, o);
  return in_lune_across(u, v, w, d);
}
//< incircle-lunes

/// in_circle on any points (see the file comment).
template <class T>
Sign in_circle_general(const BasicPoint<T>& a, const BasicPoint<T>& b, const BasicPoint<T>& c,
                       const BasicPoint<T>& d) {
  const Sign sigma = sign_of(a.w());
  if (sigma == ZERO || sign_of(b.w()) != sigma || sign_of(c.w()) != sigma) return in_circle_lune(a, b, c, d);
  const Sign o = orient(a, b, c);
  if (o == ZERO) throw detail::collinear_circle();
  if (sign_of(d.w()) != sigma) return -o;  // beyond infinity or at infinity: outside the disk
  // The lifted sign is the Euclidean in-circle sign of the drawn positions: (their turn) *
  // (inside ? 1 : -1), and their turn is sigma * orient(a, b, c).
  return sigma * lifted_sign(a, b, c, d);
}

}  // namespace detail

/// Is d inside the oriented circle through a, b, c? POSITIVE inside (to the left of a → b → c),
/// NEGATIVE outside, ZERO on the circle; CGAL's `side_of_oriented_circle` for front points. See
/// the file comment for the definition on both sides of T² and for the lunes through points on
/// both sides or on Ω. Throws `Undefined` when a, b, c are collinear, or when two of them are on
/// Ω and the third is proper. Exact for every finite input.
template <class T>
Sign in_circle(const BasicPoint<T>& a, const BasicPoint<T>& b, const BasicPoint<T>& c, const BasicPoint<T>& d) {
  if constexpr (std::is_same_v<T, double>) {
    if (detail::all_one(a.w(), b.w(), c.w(), d.w())) {  // front Cartesian points: sigma = +1
      const auto f = detail::incircle2_fast(a.x(), a.y(), b.x(), b.y(), c.x(), c.y(), d.x(), d.y());
      if (f.orient != 2 && f.incircle != 2) [[likely]] return static_cast<Sign>(f.incircle);
      return detail::in_circle_cartesian_slow(a, b, c, d, f);
    }
  }
  return detail::in_circle_general(a, b, c, d);
}

/// The unoriented test (seed 002's "side of circle", with the sign of CGAL's
/// `side_of_bounded_circle`): POSITIVE when d is in the disk through a, b, c — the points of
/// their side nearer than a to their centre on that side — ZERO on the circle, NEGATIVE
/// elsewhere (the rest of that side, Ω and the other side), whatever the order of a, b, c. For
/// a lune (file comment) the disk is the one of its two sides that holds the triangle a, b, c
/// (the one of the sphere smaller than a hemisphere). It is orient(a, b, c) · in_circle(a, b,
/// c, d). Throws `Undefined` as `in_circle` does.
template <class T>
Sign in_disk(const BasicPoint<T>& a, const BasicPoint<T>& b, const BasicPoint<T>& c, const BasicPoint<T>& d) {
  const Sign s = in_circle(a, b, c, d);  // checks the preconditions first
  return orient(a, b, c) * s;
}

}  // namespace t2
