#pragma once
/// @file face_disk.hpp
/// @brief The disk of a face of the Delaunay triangulation of T² when sites lie on Ω too:
/// `in_face_disk(a, b, c, d)`, the kernel's `in_circle` with its ties on Ω broken by angle,
/// and a disk for the faces with two vertices on Ω, where `in_circle` has none.
///
/// **Distances on Ω.** A point of Ω is a direction. Seed 000 (§4.3.1, figures 4.15–4.16)
/// compares distances between points of Ω by the angle between their directions; the kernel's
/// lunes (incircle.hpp) say what a circle centred at ζ ∈ Ω is: on each side a half-plane
/// {key_ζ > k}, whose boundary reaches Ω at ζ⊥ and ¬ζ⊥, 90° from ζ. So, seen from ζ ∈ Ω, a
/// site z on Ω at an angle α < 90° is nearer than every proper site (the lune of any proper site
/// passes at 90°), a site on Ω at 90° or more is not. This is also what the plane says: put each
/// site on Ω in front at a common radius t along its direction; as t → ∞ the Euclidean
/// Delaunay triangulation of the front sites and these far points tends to the one below (the
/// circle through t·u₁, t·u₂ and a near point p tends to the half-plane {m·x > m·p}, m the
/// bisector of u₁, u₂, holding the far points strictly between u₁ and u₂; the circle through
/// near a₁, a₂ and t·u holds the far points nearer in angle to the normal of a₁ a₂ than u).
///
/// **The disk of a face (a, b, c)** (counter-clockwise, d any point):
///  - *at most one vertex on Ω:* `in_circle(a, b, c, d)`, except that for a, b proper on one
///    side and c on Ω the kernel puts the whole open half of Ω through c *on* the circle (the
///    lune's Ω part); there d ∈ Ω is inside when it is strictly nearer in angle than c to the
///    lune's centre u (the pole of that half, u = (L_x, L_y) for the line L = a ∨ b), on the
///    circle when as near (d = c), outside otherwise;
///  - *p proper on side σ, z₁, z₂ on Ω* (rotated to (p, z₁, z₂)): the lune through p, z₁, z₂
///    centred at m = ẑ₁ + ẑ₂, the middle of the arc z₁ z₂ (the short one: orient(p, z₁, z₂) > 0
///    says it is the face's), with its Ω part refined as above: d on side σ is inside when
///    key_m(d) > key_m(p) (farther along m), on the circle when equal; d on Ω is inside when
///    strictly inside the arc z₁ z₂, on the circle when it is z₁ or z₂; d on side −σ is outside.
///    The comparisons with m = ẑ₁ + ẑ₂ take square roots: sign(α√q − β√p) is decided exactly
///    from the signs of α, β and of α²q − β²p (`sign_of_root_difference`, sign_sqrt.hpp).
///  - *flat faces* (orient(a, b, c) = 0 with an antipodal pair, the seed's figure 5.18): the
///    open hemisphere to the left of their great circle.
/// POSITIVE inside, ZERO on the circle, NEGATIVE outside. Throws `Undefined` for three points
/// on one line without an antipodal pair, and for a face p, z, ¬z (its arc of Ω is either half).

#include "t2/kernel/error.hpp"
#include "t2/kernel/filter.hpp"
#include "t2/kernel/incircle.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/sign.hpp"
#include "t2/kernel/sign_sqrt.hpp"

namespace t2 {

namespace detail {

/// Is the direction [0, u] of `d` strictly nearer in angle than c to the direction u =
/// (L_x, L_y) of the line a ∨ b (a, b proper, c and d on Ω)? POSITIVE nearer, ZERO as near.
inline Sign nearer_to_pole(const Point& a, const Point& b, const Point& c, const Point& d) {
  // u·v = (a_y b_w − a_w b_y) v_x + (a_w b_x − a_x b_w) v_y; compare u·d/|d| with u·c/|c|.
  static constexpr auto dot = [](const auto& p, const auto& q, const auto& v) {
    return (p.y * q.w - p.w * q.y) * v.x + (p.w * q.x - p.x * q.w) * v.y;
  };
  const Sign sa = sign_of_poly(dot, a, b, d), sb = sign_of_poly(dot, a, b, c);
  const Sign s2 = sign_of_poly(
      [](const auto& p, const auto& q, const auto& v, const auto& z) {
        const auto al = dot(p, q, v), be = dot(p, q, z);
        return al * al * (z.x * z.x + z.y * z.y) - be * be * (v.x * v.x + v.y * v.y);
      },
      a, b, d, c);
  return sign_of_root_difference(sa, sb, s2);
}

/// The sign of cross(u, v) and of u · v for two points of Ω.
inline Sign cross_omega(const Point& u, const Point& v) {
  return sign_of_poly([](const auto& p, const auto& q) { return p.x * q.y - p.y * q.x; }, u, v);
}
/// The sign of u · v for two points of Ω (their directions).
inline Sign dot_omega(const Point& u, const Point& v) {
  return sign_of_poly([](const auto& p, const auto& q) { return p.x * q.x + p.y * q.y; }, u, v);
}

//> face-disk-two-on-omega
/// The disk of the face (p, z1, z2): p proper, z1 and z2 on Ω (file comment).
inline Sign in_omega_pair_disk(const Point& p, const Point& z1, const Point& z2,
                               const Point& d) {
  const Sign sigma = sign_of(p.w()), sd = sign_of(d.w());
  const Sign turn = cross_omega(z1, z2);
  if (turn == ZERO)
    throw Undefined("in_face_disk: the face " + to_string(p) + ", " + to_string(z1) +
                    ", " + to_string(z2) + " has two antipodal points on Omega");
  if (sd == ZERO) {  // strictly inside the arc z1 z2, or one of its ends
    const Sign s1 = cross_omega(z1, d), s2 = cross_omega(d, z2);
    if (s1 == ZERO && dot_omega(z1, d) > 0) return ZERO;
    if (s2 == ZERO && dot_omega(d, z2) > 0) return ZERO;
    return s1 == turn && s2 == turn ? POSITIVE : NEGATIVE;
  }
  if (sd != sigma) return NEGATIVE;
  // key_m(d) − key_m(p) ∝ σ m·v, v = d_xy p_w − p_xy d_w; m·v ∝ (v·z1)|z2| + (v·z2)|z1|.
  static constexpr auto vz = [](const auto& q, const auto& e, const auto& z) {
    return (e.x * q.w - q.x * e.w) * z.x + (e.y * q.w - q.y * e.w) * z.y;
  };
  const Sign sa = sign_of_poly(vz, p, d, z1), sb = -sign_of_poly(vz, p, d, z2);
  const Sign s2 = sign_of_poly(
      [](const auto& q, const auto& e, const auto& y1, const auto& y2) {
        const auto a1 = vz(q, e, y1), a2 = vz(q, e, y2);
        const auto n1 = y1.x * y1.x + y1.y * y1.y, n2 = y2.x * y2.x + y2.y * y2.y;
        return a1 * a1 * n2 - a2 * a2 * n1;
      },
      p, d, z1, z2);
  return sigma * sign_of_root_difference(sa, sb, s2);
}
//< face-disk-two-on-omega

}  // namespace detail

/// Is d inside the disk of the face (a, b, c) of a Delaunay triangulation of T²? POSITIVE
/// inside, ZERO on its circle, NEGATIVE outside; exact (see the file comment for the
/// definition). a, b, c turn counter-clockwise, or are flat with an antipodal pair.
inline Sign in_face_disk(const Point& a, const Point& b, const Point& c, const Point& d) {
  const Point* v[3] = {&a, &b, &c};
  const int omega = (a.w() == 0) + (b.w() == 0) + (c.w() == 0);
  if (omega == 2) {  // rotate the proper vertex first
    const int k = a.w() != 0 ? 0 : b.w() != 0 ? 1 : 2;
    return detail::in_omega_pair_disk(*v[k], *v[(k + 1) % 3], *v[(k + 2) % 3], d);
  }
  if (omega == 0 && orient(a, b, c) == ZERO) {  // a flat face: two of its vertices antipodal
    for (int k = 0; k < 3; ++k) {  // x → y: the two on one side, in the face's order
      const Point &x = *v[k], &y = *v[(k + 1) % 3], &r = *v[(k + 2) % 3];
      if (sign_of(x.w()) == sign_of(y.w()) && sign_of(r.w()) != sign_of(x.w())) return orient(x, y, d);
    }
    return in_circle(a, b, c, d);  // all on one side: throws (collinear)
  }
  const Sign s = in_circle(a, b, c, d);
  if (s != ZERO || omega == 0 || d.w() != 0) return s;
  // d on the lune's half of Ω: only for two vertices proper on one side and one on Ω.
  const int k = a.w() == 0 ? 0 : b.w() == 0 ? 1 : 2;
  const Point &p = *v[(k + 1) % 3], &q = *v[(k + 2) % 3];
  if (sign_of(p.w()) != sign_of(q.w())) return s;
  return detail::nearer_to_pole(p, q, *v[k], d);
}

}  // namespace t2
