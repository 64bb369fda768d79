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
/// sides of T² (or on Ω) lie on no circle, and `in_circle` throws `Undefined` for them,
/// as for three collinear points. For a, b, c proper on one side σ and not collinear, let
/// z be their circumcentre on side σ and r² = d²(z, a); the *disk* is the set of points
/// with d²(z, d) < r² in the T¹ order, i.e. the points of side σ strictly inside the
/// Euclidean circle. Then
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
//< incircle-definition

#include <algorithm>

#include "t2/error.hpp"
#include <type_traits>

#include "t2/filter.hpp"
#include "t2/incircle_double.hpp"
#include "t2/orient.hpp"
#include "t2/point.hpp"
#include "t2/sign.hpp"

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

/// in_circle on any points (see the file comment).
template <class T>
Sign in_circle_general(const BasicPoint<T>& a, const BasicPoint<T>& b, const BasicPoint<T>& c,
                       const BasicPoint<T>& d) {
  const Sign sigma = sign_of(a.w());
  if (sigma == ZERO || sign_of(b.w()) != sigma || sign_of(c.w()) != sigma)
    throw Undefined(
        "in_circle(a, b, c, d) is undefined unless a, b, c are proper points on one side: no circle of T2 "
        "passes through points on both sides or on Omega");
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
/// the file comment for the definition on both sides of T². Throws `Undefined` when a, b, c are
/// not proper points of one side, or are collinear. Exact for every finite input.
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
/// elsewhere (the rest of that side, Ω and the other side), whatever the order of a, b, c. It is
/// orient(a, b, c) · in_circle(a, b, c, d). Throws `Undefined` as `in_circle` does.
template <class T>
Sign in_disk(const BasicPoint<T>& a, const BasicPoint<T>& b, const BasicPoint<T>& c, const BasicPoint<T>& d) {
  const Sign s = in_circle(a, b, c, d);  // checks the preconditions first
  return orient(a, b, c) * s;
}

}  // namespace t2
