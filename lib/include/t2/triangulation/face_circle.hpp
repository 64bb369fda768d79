#pragma once
/// @file face_circle.hpp
/// @brief The empty-circle predicate of the faces of a Delaunay triangulation of T², including
/// faces with vertices on both sides: `in_face_circle(a, b, c, d)`.
///
/// **Why a new predicate.** `in_circle` (incircle.hpp) is the circle of three proper points of
/// one side; no circle of T² passes through points of both sides (their distances from any
/// proper centre are of different kinds). Yet the T² Voronoi diagram of sites on both sides has
/// vertices whose nearest sites lie on both sides: they are on Ω. This predicate gives each face
/// of the Delaunay triangulation the "disk" of its Voronoi vertex — the points that would be
/// nearer to that vertex than the face's own vertices — so that a face is Delaunay exactly when
/// its disk holds no site (delaunay_t2.hpp derives it and proves the properties).
///
/// **The definition.** Let a, b, c be proper points with orient(a, b, c) ≥ 0 (a face of the
/// triangulation turns counter-clockwise in T²), and d any point.
///  - *a, b, c on one side:* `in_circle(a, b, c, d)`: the Euclidean disk on their side; points
///    of the other side and of Ω are outside.
///  - *two of them, x → y in the cyclic order of the face, on side σ, the third, z, on −σ.*
///    The Voronoi vertex is the point at infinity ζ in the direction n that leaves the edge
///    x y perpendicularly on the side away from the face (n is the direction of the right
///    normal of y → x in the drawing). The disk is the open *lune* between two half great
///    circles with ends ±(x − y) on Ω: the half of the line x ∨ y on side σ, and the half of
///    the parallel line through z on side −σ; it contains ζ. In coordinates, with X, Y, Z, D
///    the drawn (Cartesian) positions:
///      - d on side σ: inside iff orient(x, y, d) > 0 (beyond the line x y, away from z);
///      - d on side −σ: inside iff σ · cross(X − Y, D − Z) > 0 (beyond the parallel through z,
///        in the direction of ζ as seen from side −σ);
///      - d = [0, u] on Ω: inside iff cross(X − Y, u) < 0 (ζ's open half of Ω). This is the limit
///        of both rules above as d runs off to [0, u] from either side.
/// The result is POSITIVE inside, ZERO on the boundary (the two half circles and their ends),
/// NEGATIVE outside. It throws `Undefined` when a, b, c are not proper points, or lie on one
/// side and are collinear.

#include "t2/error.hpp"
#include "t2/filter.hpp"
#include "t2/incircle.hpp"
#include "t2/orient.hpp"
#include "t2/point.hpp"
#include "t2/sign.hpp"

namespace t2 {

namespace detail {

/// sign(cross(P1 − P0, Q1 − Q0)) of the drawn positions, for p0, p1 on one side and q0, q1 on
/// one side (exact; the positive factors p0_w p1_w and q0_w q1_w are left out).
inline Sign cross_of_differences(const Point& p0, const Point& p1, const Point& q0, const Point& q1) {
  return sign_of_poly(
      [](const auto& aw, const auto& ax, const auto& ay, const auto& bw, const auto& bx, const auto& by,
         const auto& cw, const auto& cx, const auto& cy, const auto& dw, const auto& dx, const auto& dy) {
        return (bx * aw - ax * bw) * (dy * cw - cy * dw) - (by * aw - ay * bw) * (dx * cw - cx * dw);
      },
      p0.w(), p0.x(), p0.y(), p1.w(), p1.x(), p1.y(), q0.w(), q0.x(), q0.y(), q1.w(), q1.x(), q1.y());
}

/// sign((P1 − P0) · (Q1 − Q0)) of the drawn positions, under the conditions of
/// cross_of_differences.
inline Sign dot_of_differences(const Point& p0, const Point& p1, const Point& q0, const Point& q1) {
  return sign_of_poly(
      [](const auto& aw, const auto& ax, const auto& ay, const auto& bw, const auto& bx, const auto& by,
         const auto& cw, const auto& cx, const auto& cy, const auto& dw, const auto& dx, const auto& dy) {
        return (bx * aw - ax * bw) * (dx * cw - cx * dw) + (by * aw - ay * bw) * (dy * cw - cy * dw);
      },
      p0.w(), p0.x(), p0.y(), p1.w(), p1.x(), p1.y(), q0.w(), q0.x(), q0.y(), q1.w(), q1.x(), q1.y());
}

/// The lune rule of the file comment for the face (x, y, z), x and y on side sigma, z on −sigma.
inline Sign in_lune(const Point& x, const Point& y, const Point& z, const Point& d, Sign sigma) {
  const Sign sd = sign_of(d.w());
  if (sd == sigma) return orient(x, y, d);
  if (sd == -sigma) return sigma * cross_of_differences(y, x, z, d);
  // d = [0, u] on Omega: -sign(cross(X - Y, u)) = -sign((x_x y_w - y_x x_w) u_y - (x_y y_w - y_y x_w) u_x).
  const Sign c = sign_of_poly(
      [](const auto& xw, const auto& xx, const auto& xy, const auto& yw, const auto& yx, const auto& yy,
         const auto& ux, const auto& uy) { return (xx * yw - yx * xw) * uy - (xy * yw - yy * xw) * ux; },
      x.w(), x.x(), x.y(), y.w(), y.x(), y.y(), d.x(), d.y());
  return -c;  // x_w y_w > 0 leaves the sign alone
}

}  // namespace detail

//> in-face-circle
/// Is d inside the disk of the face (a, b, c) of a Delaunay triangulation of T²? POSITIVE
/// inside, ZERO on its boundary, NEGATIVE outside (see the file comment for the definition).
/// Exact. Throws `Undefined` when a, b or c is on Ω, or when all three are on one side and
/// collinear.
inline Sign in_face_circle(const Point& a, const Point& b, const Point& c, const Point& d) {
  const Sign sa = sign_of(a.w()), sb = sign_of(b.w()), sc = sign_of(c.w());
  if (sa == ZERO || sb == ZERO || sc == ZERO)
    throw Undefined("in_face_circle(a, b, c, d) is undefined for a face with a vertex on Omega");
  if (sa == sb && sb == sc) return in_circle(a, b, c, d);
  // Rotate so that the two vertices of one side come first, in the cyclic order of the face.
  if (sa == sb) return detail::in_lune(a, b, c, d, sa);
  if (sb == sc) return detail::in_lune(b, c, a, d, sb);
  return detail::in_lune(c, a, b, d, sc);
}
//< in-face-circle

}  // namespace t2
