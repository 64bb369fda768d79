#pragma once
/// @file antipodal_edge.hpp
/// @brief The edge between a hull vertex z and its antipode ¬z (seed 000, §5.3, figure 5.18):
/// the half great circle that leaves z along the bisector of the hull angle at z, outwards,
/// and the exact side of a point with respect to it.
///
/// Between antipodes there are infinitely many segments (every half great circle from z to ¬z),
/// so orient(z, ¬z, p) = 0 for every p says nothing. The seed picks the one that bisects the
/// angle u z w of the hull edges u → z and z → w at the moment ¬z arrives, pointing out of the
/// hull. We take the angle in the sphere model (the angle between the great circles at z; it is
/// the planar angle when z is the centre of the front side).
///
/// **The side, exactly.** P₁ = u × z and P₂ = z × w are the poles of the two hull edges (both
/// inside the hull: orient(u, z, P₁) = |P₁|² > 0). Both are perpendicular to z, so n₁ = P₁/|P₁|
/// and n₂ = P₂/|P₂| are the unit inward normals of the two edges at z, and B = n₁ + n₂ is the
/// inward bisector: with the edge towards w at angle 0 and the one towards u at angle θ
/// (0 < θ ≤ 180°), n₂ is at 90° and n₁ at θ − 90°, their sum at θ/2, of length 2 cos(90° − θ/2)
/// > 0 (for θ = 180° it is the perpendicular, the bisector of a straight angle). The edge leaves
/// z along −B, and p lies to its left iff det(z, −B, p) > 0, that is iff
/// D₁/|P₁| + D₂/|P₂| < 0 with Dₖ = det(z, Pₖ, p), the sign of D₁√L₂ + D₂√L₁ (Lₖ = |Pₖ|²):
/// equal signs decide at once, opposite signs by comparing D₁²L₂ with D₂²L₁. Integers of
/// degree 12 in the coordinates, exact with GMP; no square root is ever taken.
///
/// **Lemma (the bisector keeps the triangulation a planar subdivision).** Let H be the hull of
/// the points inserted so far (in an open hemisphere), z a vertex with neighbours u, w, and ¬z
/// the new point. After ¬z replaces v∞ the faces are: those of H; a triangle (y, x, ¬z) for every
/// hull edge x → y not at z; the lunes L_w = (w, z, ¬z) and L_u = (z, u, ¬z). They cover the
/// sphere once, and every face that is not flat is the intersection of open hemispheres.
///
/// *Proof.* Use the half great circles from z to ¬z (meridians) and their angle φ at z, with w
/// at φ = 0 and u at φ = θ. (1) The meridian along −B (φ = 180° + θ/2) meets H only in z: H is
/// convex and lies in an open hemisphere, so a great circle through z meets it in one arc
/// shorter than 180° from z, leaving z inside the angle [0, θ]; 180° + θ/2 is not in it, and
/// that arc cannot reach round to the other half of the circle. So the new edge crosses no
/// edge of H. (2) The triangles (y, x, ¬z): for φ in (0, θ) the meridian leaves H through one
/// far edge x → y and runs on to ¬z inside (y, x, ¬z), which is a proper triangle because ¬z
/// sees x → y strictly (orient(x, y, ¬z) = −orient(x, y, z) < 0 when z is not on the circle of
/// x → y; if it is, the face is flat, its vertices on one arc, and the meridians of the
/// neighbouring faces cover the same points). (3) The lunes: L_w covers the meridians with φ in
/// [180° + θ/2, 360°] and L_u those in [θ, 180° + θ/2]; each has angle 180° − θ/2, which is
/// below 180° and above 0, so each lune is the intersection of the open hemisphere left of its
/// circle through w (resp. u) and the one left of the new edge, and the two share only the new
/// edge. Meridians partition the sphere minus {z, ¬z}; every meridian is covered once, so the
/// faces tile the sphere. ∎ Any direction strictly between 180° and 180° + θ would do (both
/// angles stay in (0°, 180°)); the bisector is the seed's choice, and it is the only one that
/// does not depend on the coordinates (it gives both lunes the same angle).
///
/// *Any lunes, not only Algorithm 9's* (the T² Delaunay records its antipodal edges by the same
/// rule, face_kind.hpp). Let the faces at z other than the two lunes cover the angle θ from the
/// meridian of w counter-clockwise to that of u, for any θ in (0°, 360°) (θ > 180° is possible
/// when z is no hull corner). The derivation of B above still holds: n₂ at 90° and n₁ at θ − 90°
/// differ by |180° − θ| < 180°, so B points at θ/2 with length 2 cos((θ − 180°)/2) > 0. The edge
/// runs at 180° + θ/2, strictly inside (θ, 360°), the angle the two lunes share, and each lune
/// has the angle 180° − θ/2 in (0°, 180°): an intersection of two open hemispheres, so (3)
/// holds word for word and the faces still tile.
///
/// *Later insertions.* An insertion replaces one face or two by faces with the same union, so
/// the tiling persists. The edge z → ¬z is never moved: a point inside a lune leaves one lune
/// (p, z, ¬z) with the same edge, a point on the edge removes it (figure 5.20), and no new edge
/// between antipodes appears (a proper triangle lies in an open hemisphere, so it never holds
/// both a point and its antipode; a lune holds only its own two).

#include <vector>

#include "t2/kernel/number.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/sign.hpp"
#include "t2/triangulation/face_kind.hpp"  // AntipodalEdge, the record

namespace t2 {

namespace detail {

/// The integer coordinates (w, x, y) of a point, exactly.
struct Vec3 {
  Integer c[3];  ///< w, x, y
};

/// The exact coordinates of p (all three scaled by one power of two).
inline Vec3 vec3(const Point& p) {
  const ExactPoint e = to_exact(p);
  return {{e.w(), e.x(), e.y()}};
}

/// a × b.
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {{a.c[1] * b.c[2] - a.c[2] * b.c[1], a.c[2] * b.c[0] - a.c[0] * b.c[2], a.c[0] * b.c[1] - a.c[1] * b.c[0]}};
}

/// a · b.
inline Integer dot(const Vec3& a, const Vec3& b) { return a.c[0] * b.c[0] + a.c[1] * b.c[1] + a.c[2] * b.c[2]; }

}  // namespace detail

//> antipodal-side
/// The side of p with respect to the edge z → ¬z of e (positive: to its left, the side of
/// the lune (w, z, ¬z)); exact (see the file comment). `P` holds the points.
inline Sign side_of_antipodal_edge(const std::vector<Point>& P, const AntipodalEdge& e,
                                   const Point& p) {
  using detail::cross, detail::dot, detail::vec3;
  const detail::Vec3 z = vec3(P[e.z]), q = vec3(p);
  const detail::Vec3 p1 = cross(vec3(P[e.u]), z), p2 = cross(z, vec3(P[e.w]));
  const detail::Vec3 zq = cross(q, z);  // det(z, P, q) = P · (q × z)
  const Integer d1 = dot(p1, zq), d2 = dot(p2, zq);
  const int s1 = sgn(d1), s2 = sgn(d2);
  int s;  // the sign of D1·√L2 + D2·√L1
  if (s1 == s2 || s2 == 0) s = s1;
  else if (s1 == 0) s = s2;
  else {
    const Integer a = d1 * d1 * dot(p2, p2), b = d2 * d2 * dot(p1, p1);
    s = a > b ? s1 : a < b ? s2 : 0;
  }
  return static_cast<Sign>(-s);  // left of the edge along −B
}
//< antipodal-side

/// True when p lies strictly inside the arc a → b shorter than 180° (a ≠ ±b), on the great
/// circle of a and b: det(a, p, N) > 0 and det(p, b, N) > 0 with N = a × b. Exact.
inline bool inside_arc(const Point& a, const Point& b, const Point& p) {
  using detail::cross;
  const detail::Vec3 A = detail::vec3(a), B = detail::vec3(b), q = detail::vec3(p), N = cross(A, B);
  if (sgn(detail::dot(N, q)) != 0) return false;  // not on the circle
  return sgn(detail::dot(cross(A, q), N)) > 0 && sgn(detail::dot(cross(q, B), N)) > 0;
}

}  // namespace t2
