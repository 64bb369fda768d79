#pragma once
/// @file distance.hpp
/// @brief Squared distances as points of T¹, and the comparison of distances between proper
/// points and points at infinity (seed 000, §4.3.1).
///
/// **Squared distance.** For proper points a, b (w ≠ 0) the squared distance is the T¹ point
///
///     d²(a, b) = [ sign(a_w b_w) (a_w b_w)²,  (a_x b_w − b_x a_w)² + (a_y b_w − b_y a_w)² ].
///
/// Its coordinate x is never negative, so d² lives on the closed upper half of the circle
/// model of T¹, which the library orders counter-clockwise from 0 = [1, 0]:
///
///     0 = [1,0]  <  finite values [1, t]  <  +∞ = [0,1]  <  [−1, t] (t decreasing)  <  [−1, 0].
///
/// For a and b on the same side, d² = [1, |A − B|²] with A, B the Cartesian positions: the
/// Euclidean value. For a front point and a back point, w < 0: the distance is "beyond
/// infinity", [−1, |A − B|²], and the *larger* the Euclidean distance between the drawn
/// positions, the *nearer* the value is to +∞, i.e. the smaller it is. The largest value of all,
/// [−1, 0], is the distance from a point to its antipode.
///
/// **Points at infinity.** If exactly one of a, b is on Ω the formula gives [0, positive]: the
/// distance is +∞, which is what the library returns. If both are on Ω the formula gives the
/// invalid pair [0, 0]; the distance between two directions is an angle, not a value of T¹, and
/// `squared_distance` throws `Undefined` (use `compare_distance`, which handles that case).
///
/// **Comparing distances.** `compare_distance(a, b, c)` decides which of a, b is nearer to c,
/// in every configuration; see its comment for the rules and for the one undefined case.
///
/// **Error bounds on doubles.** Three Cartesian points take the fast path of
/// distance_double.hpp. Every other case is the sign of a polynomial through `sign_of_poly`,
/// whose bound filter.hpp derives from the polynomial's shape (u = 2⁻⁵³, Mₚ the largest
/// |coordinate| of point p, count monomials each meeting at most k roundings, |error| ≤
/// count·γ_k·Π Mₚ^dₚ, C = count·k·u·(1 + 2⁻⁴⁰)):
/// - all proper, E = (eₓ² + e_y²)·b_w² − (fₓ² + f_y²)·a_w², eₓ = aₓc_w − cₓa_w, fₓ = bₓc_w − cₓb_w:
///   each squared difference multiplies out to 2·2 monomials, so 16 in all, of degree 2 in each
///   of a, b, c; a monomial meets 2 roundings in each of its two factors eₓ, the square, the sum
///   eₓ² + e_y², the square b_w², their product and the final difference: k = 9, so
///   |error| ≤ 16γ₉·(M_aM_bM_c)², C = 144u(1 + 2⁻⁴⁰), trusted for M ∈ [2⁻¹⁵⁰, 2¹⁵⁰];
/// - c on Ω (the sweep), a_w(uₓbₓ + u_yb_y) − b_w(uₓaₓ + u_ya_y): 4 monomials of degree 1 in
///   each point, k = 4 (product, sum, product, difference): C = 16u(1 + 2⁻⁴⁰);
/// - the angle rule and the 90° convention: the dot products v·c (3 monomials, k = 3,
///   C = 9u(1 + 2⁻⁴⁰)), then
///   (a·c)²(b·b) − (b·c)²(a·a): 54 monomials of degree 2 in each point, k = 12 (3 in a dot
///   product, 7 in its square, 3 + 7 + 1 in the product, 1 in the difference): C = 648u(1 + 2⁻⁴⁰).
/// The test test_filter_bound checks that filter.hpp derives these constants.

#include <string>
#include <type_traits>

#include "t2/kernel/detail/distance_double.hpp"
#include "t2/kernel/error.hpp"
#include "t2/kernel/filter.hpp"
#include "t2/kernel/number.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/sign.hpp"
#include "t2/kernel/t1.hpp"

namespace t2 {

/// d²(a, b) as a point of T¹ (see the file comment): finite [1, |A−B|²] on the same side,
/// "beyond infinity" [−1, |A−B|²] across sides, +∞ when exactly one point is on Ω. A
/// construction: exact for `Integer` coordinates; for `double` computed exactly and then rounded
/// once (use `compare_distance` to decide). Throws `Undefined` when both points are on Ω.
template <class T>
BasicT1<T> squared_distance(const BasicPoint<T>& a, const BasicPoint<T>& b) {
  if (a.w() == 0 && b.w() == 0)
    throw Undefined(
        "squared_distance(a, b) is undefined when both a and b are on Omega: the distance between two "
        "directions is an angle, not a value of T1 (compare_distance compares it)");
  if constexpr (std::is_same_v<T, double>) {
    // Rounded products of doubles can overflow or underflow (to +inf, or to a false [0, 0]):
    // compute exactly and round once, scaled so that the larger coordinate is near 1.
    const auto e = squared_distance(to_exact(a), to_exact(b));
    const Point r = to_double(ExactPoint(e.w(), e.x(), Integer(0)));
    return BasicT1<T>(r.w(), r.x());
  }
  const T ww = a.w() * b.w();
  const T dx = a.x() * b.w() - b.x() * a.w();
  const T dy = a.y() * b.w() - b.y() * a.w();
  const T w = ww < 0 ? T(-(ww * ww)) : T(ww * ww);
  return BasicT1<T>(w, T(dx * dx + dy * dy));
}

/// Compares two squared distances d1, d2 (T¹ points with x ≥ 0) in the order of the file
/// comment: NEGATIVE when d1 < d2 (d1 is the nearer), ZERO when equal, POSITIVE otherwise.
/// Exact. Throws `Undefined` for a T¹ point with x < 0, which is not a squared distance.
template <class T>
Sign compare_distance_values(const BasicT1<T>& d1, const BasicT1<T>& d2) {
  if (d1.x() < 0 || d2.x() < 0)
    throw Undefined("compare_distance_values(d1, d2): a squared distance is a point [w, x] of T1 with x >= 0");
  // On the half circle x >= 0 the angle of (w, x) grows with x*w' - w*x' except between its two
  // ends [1,0] and [-1,0], where that determinant is zero although the points differ.
  if (d1.x() == 0 && d2.x() == 0) {
    if (sign_of(d1.w()) == sign_of(d2.w())) return ZERO;
    return sign_of(d1.w()) == POSITIVE ? NEGATIVE : POSITIVE;  // 0 = [1,0] < [-1,0]
  }
  return sign_of_poly([](const auto& p, const auto& q) { return p.x * q.w - p.w * q.x; }, d1, d2);
}

namespace detail {

/// The "angle at the origin" rule: compares the angles ∠(a o c) and ∠(b o c) between the
/// vectors a, c and b, c of R³. NEGATIVE when ∠(a o c) < ∠(b o c).
template <class T>
Sign compare_angles_at_origin(const BasicPoint<T>& a, const BasicPoint<T>& b, const BasicPoint<T>& c) {
  static constexpr auto dot = [](const auto& p, const auto& q) { return p.w * q.w + p.x * q.x + p.y * q.y; };
  const Sign sp = sign_of_poly(dot, a, c);
  const Sign sq = sign_of_poly(dot, b, c);
  // The angle shrinks as cos = (v.c)/(|v||c|) grows; compare (a.c)/|a| with (b.c)/|b|.
  if (sp != sq) return sp > sq ? NEGATIVE : POSITIVE;
  if (sp == ZERO) return ZERO;
  // Same strict sign: compare (a.c)^2 |b|^2 with (b.c)^2 |a|^2.
  const Sign e = sign_of_poly(
      [](const auto& u, const auto& v, const auto& r) {  // no captures (filter.hpp, bound_of)
        const auto p = dot(u, r), q = dot(v, r);
        return p * p * dot(v, v) - q * q * dot(u, u);
      },
      a, b, c);
  // e > 0: |cos a| > |cos b|. With positive cosines the larger is the smaller angle.
  return sp == POSITIVE ? -e : e;
}

/// compare_distance on any points (see there); out of line, so that the Cartesian fast path
/// of `compare_distance` keeps only its own loads and operations.
template <class T>
[[gnu::noinline]] Sign compare_distance_general(const BasicPoint<T>& a, const BasicPoint<T>& b,
                                                const BasicPoint<T>& c) {
  const int ia = a.w() == 0, ib = b.w() == 0, ic = c.w() == 0;
  if (ic && ia + ib == 1) {
    // The 90° convention: the proper point is 90° from c, so the one on Ω is nearer iff its
    // angle to c is under 90°, i.e. iff its dot product with c is positive.
    const Sign s = sign_of_poly([](const auto& p, const auto& q) { return p.w * q.w + p.x * q.x + p.y * q.y; },
                                ia ? a : b, c);
    return ia ? -s : s;
  }
  if (ia + ib + ic >= 2) return compare_angles_at_origin(a, b, c);
  const Sign sa = sign_of(a.w()), sb = sign_of(b.w()), sc = sign_of(c.w());
  if (ic) {
    // Sweep rule: compare key(v) = u.(v_x, v_y)/|v_w| of a and b, the larger being nearer.
    if (sa != sb)
      throw Undefined(
          "compare_distance(a, b, c) is undefined when c is on Omega and a, b are proper points on "
          "opposite sides: approaching c from the front or from the back gives opposite answers");
    const Sign s = sign_of_poly(
        [](const auto& p, const auto& q, const auto& u) { return p.w * (u.x * q.x + u.y * q.y) - q.w * (u.x * p.x + u.y * p.y); },
        a, b, c);
    return sa * s;  // sign(|a_w| key(b) - |b_w| key(a)) up to the positive |a_w b_w|
  }
  if (ia) return sb == sc ? POSITIVE : NEGATIVE;  // +inf against finite / beyond infinity
  if (ib) return sa == sc ? NEGATIVE : POSITIVE;
  // All proper: the T1 order of the squared distances.
  const Sign ra = sa * sc, rb = sb * sc;  // the sides of a and b relative to c
  if (ra != rb) return ra == POSITIVE ? NEGATIVE : POSITIVE;
  const Sign e = sign_of_poly(
      [](const auto& p, const auto& q, const auto& r) {
        const auto ex = p.x * r.w - r.x * p.w, ey = p.y * r.w - r.y * p.w;  // (A - C) a_w c_w
        const auto fx = q.x * r.w - r.x * q.w, fy = q.y * r.w - r.y * q.w;  // (B - C) b_w c_w
        return (ex * ex + ey * ey) * (q.w * q.w) - (fx * fx + fy * fy) * (p.w * p.w);
      },
      a, b, c);
  // e = sign(|A-C|^2 - |B-C|^2): the Euclidean order on c's side, reversed beyond infinity.
  return ra == POSITIVE ? e : -e;
}

}  // namespace detail

/// Is a nearer to c than b is? Returns NEGATIVE when d(a, c) < d(b, c), ZERO when the distances
/// are equal, POSITIVE when d(a, c) > d(b, c). (CGAL's `compare_distance_to_point(c, a, b)`
/// puts the reference point first; here it is last.) Exact for every finite input.
///
/// The rules, by how many of the three points are on Ω:
/// - **None:** the squared distances of the file comment, compared in T¹ (a point on the
///   other side of c is beyond infinity, farther than any point of c's side or of Ω).
/// - **c proper, one of a, b on Ω:** the point on Ω is at distance +∞ from c: farther than a
///   proper point on c's side, nearer than one on the other side.
/// - **c on Ω, a and b proper on the same side — the sweep rule of §4.3.1:** sweep the plane
///   with lines perpendicular to the direction of c, towards c; the point met later is the
///   nearer. With c = [0, u] this compares u·(x, y)/|w| of a and b, the larger being nearer (a
///   tie is a tie of the limit of d(a, c') − d(b, c') as c' runs off to c, from either side).
/// - **c on Ω, a and b proper on opposite sides: undefined** (throws `Undefined`). Letting a
///   proper point c' run off to c on the front makes the front point nearer (the back one is
///   beyond infinity), letting it run off on the back makes the back point nearer: no answer
///   is right. The seed states the sweep rule for the same canonical hemisphere only.
/// - **a and b on Ω, c proper, or all three on Ω — the angle rule of §4.3.1:** compare the
///   angles ∠(a o c) and ∠(b o c) between the triples seen as vectors of R³ (o its origin).
///   Both cases are the limit of the proper configuration (with all three on Ω the triple
///   angle is the angle between directions).
/// - **c and one of a, b on Ω, the other proper — the 90° convention of chapter 03, §5:** no
///   limit decides, and the seed's angle at the origin would depend on where the origin
///   [1, 0, 0] is. Every proper point, on either side, counts as 90° from c: the point of Ω is
///   nearer iff it is less than 90° from c, tied at exactly 90°, farther beyond. It is the
///   order of the disks around c (incircle.hpp: a circle centred on Ω through a proper point
///   is a line perpendicular to c, and meets Ω 90° from c).
template <class T>
Sign compare_distance(const BasicPoint<T>& a, const BasicPoint<T>& b, const BasicPoint<T>& c) {
  if constexpr (std::is_same_v<T, double>) {
    if (detail::all_one(a.w(), b.w(), c.w())) [[likely]]  // three Cartesian points: distance_double.hpp
      return detail::compare_distance2(a.x(), a.y(), b.x(), b.y(), c.x(), c.y());
  }
  return detail::compare_distance_general(a, b, c);
}

/// Compares the distance d(a, b) with the distance d(c, d), in the order of the file comment
/// (finite on one side, then +∞, then "beyond infinity" across sides): NEGATIVE when a, b are
/// the nearer pair, ZERO when the distances are equal, POSITIVE otherwise. Exact. Throws
/// `Undefined` when a and b, or c and d, are both on Ω (the distance between two directions is
/// an angle, not a value of T¹). This is the order of `compare_distance_values` on
/// `squared_distance(a, b)` and `squared_distance(c, d)`, decided without constructing them.
///
/// **Proof.** A pair's class, 0 (same side), 1 (exactly one on Ω) or 2 (opposite sides), is read
/// from the signs of its weights, and a lower class is nearer. In classes 0 and 2 the values are
/// [±1, |A − B|²] and [±1, |C − D|²], and with u = b_x a_w − a_x b_w (likewise u_y, v, v_y)
///
///     E = (uₓ² + u_y²)(c_w d_w)² − (vₓ² + v_y²)(a_w b_w)² = (a_w b_w c_w d_w)² (|A − B|² − |C − D|²),
///
/// whose sign is that of |A − B|² − |C − D|²: the answer in class 0, and its opposite in class 2
/// (there a larger Euclidean length is nearer to +∞, hence smaller). Two pairs of class 1 are
/// both at +∞. E has 16 monomials of degree 2 in each point; `sign_of_poly` derives its bound.
template <class T>
Sign compare_distance(const BasicPoint<T>& a, const BasicPoint<T>& b, const BasicPoint<T>& c,
                      const BasicPoint<T>& d) {
  const auto pair_class = [](const BasicPoint<T>& p, const BasicPoint<T>& q) {
    const Sign sp = sign_of(p.w()), sq = sign_of(q.w());
    if (sp == ZERO && sq == ZERO)
      throw Undefined("compare_distance(a, b, c, d) is undefined when both points of a pair are on Omega: "
                      "the distance between two directions is an angle, not a value of T1");
    if (sp == ZERO || sq == ZERO) return 1;
    return sp == sq ? 0 : 2;
  };
  const int kab = pair_class(a, b), kcd = pair_class(c, d);
  if (kab != kcd) return kab < kcd ? NEGATIVE : POSITIVE;
  if (kab == 1) return ZERO;
  const Sign e = sign_of_poly(
      [](const auto& aw, const auto& ax, const auto& ay, const auto& bw, const auto& bx, const auto& by,
         const auto& cw, const auto& cx, const auto& cy, const auto& dw, const auto& dx, const auto& dy) {
        const auto ux = bx * aw - ax * bw, uy = by * aw - ay * bw;
        const auto vx = dx * cw - cx * dw, vy = dy * cw - cy * dw;
        return (ux * ux + uy * uy) * (cw * dw) * (cw * dw) - (vx * vx + vy * vy) * (aw * bw) * (aw * bw);
      },
      a.w(), a.x(), a.y(), b.w(), b.x(), b.y(), c.w(), c.x(), c.y(), d.w(), d.x(), d.y());
  return kab == 0 ? e : -e;
}

}  // namespace t2
