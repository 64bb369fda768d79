#pragma once
/// @file angle.hpp
/// @brief Angles as points of Ω (seed 000, §4.3.7): the angular difference ^− and the
/// comparison of angles, with the correction of the seed's Algorithm 1.
///
/// A point [0, x, y] of Ω is a direction, and it stands for the angle θ that the vector (x, y)
/// makes with the x axis, counter-clockwise, in [0, 2π): the angle 0 is [0, 1, 0]. No angle is
/// ever computed as a real number; everything is a polynomial in the coordinates.
///
/// **Difference.** d1 ^− d2 = [0, x1 x2 + y1 y2, y1 x2 − x1 y2] is the direction of angle
/// θ1 − θ2 (as complex numbers, d1 times the conjugate of d2). The angle p̂qr is
/// dir(q→p) ^− dir(q→r) (`angle(p, q, r)`).
///
/// **Comparison.** The seed's Algorithm 1 compares two directions p, q with o = [1, 0, 0]
/// and d = [0, 1, 0]: "p > q" when Δ(p, o, q)·Δ(p, o, d) = +1, "p = q" when Δ(p, o, q) = 0,
/// "p < q" otherwise. Here Δ(p, o, q) = −(p_x q_y − p_y q_x) and Δ(p, o, d) = p_y, so the
/// algorithm decides by which way q turns from p, and that is the order of the angles only
/// when both lie in the first two quadrants, θ ∈ [0, π), and are not antipodal. As printed
/// it answers wrongly (chapter 03's program finds them on sixteen directions of known order) when:
/// - p and q are antipodal, e.g. [0,1,0] and [0,−1,0]: "equal" (the determinant is zero);
/// - θp ∈ (0, π) and θq ∈ (θp + π, 2π): "p > q" (q is "behind" p by less than half a turn);
/// - θp = π, p = [0, −1, 0]: "p < q" for every q, also for q in the upper half;
/// - θp ∈ (π, 2π): wrong for every θq ∈ (θp − π, 2π) other than θp: it answers by the turn,
///   and the angles the turn puts "ahead" of p wrap around past 2π.
/// It is not even antisymmetric. Chapter 03's program keeps it as printed, to show this.
///
/// The correction, `compare_angle`, first compares the half turns [0, π) (y > 0, or y = 0 and
/// x > 0) and [π, 2π), and only inside one half uses the turn from p to q, which there is less
/// than half a turn and so decides: a full-turn comparison counter-clockwise from [0, 1, 0].

#include <cmath>
#include <type_traits>

#include "t2/kernel/error.hpp"
#include "t2/kernel/filter.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/sign.hpp"
#include "t2/kernel/vector.hpp"

namespace t2 {

namespace detail {

template <class T>
void require_direction(const BasicPoint<T>& d, const char* rule) {
  if (d.w() != 0) throw Undefined(rule);
}

/// 0 for θ in [0, π), 1 for θ in [π, 2π).
template <class T>
int angle_half(const BasicPoint<T>& d) {
  if (d.y() > 0) return 0;
  if (d.y() < 0) return 1;
  return d.x() > 0 ? 0 : 1;
}

/// sign(cross(P1 − P0, Q1 − Q0)) of the drawn (Cartesian) positions, for proper p0, p1 on one
/// side and proper q0, q1 on one side: the turn from the direction of p0 → p1 to that of q0 → q1
/// (the positive factors p0_w p1_w and q0_w q1_w are left out). Exact. The T² Delaunay merge
/// along Ω (triangulation/delaunay_t2.hpp) orders hull edges by it.
inline Sign cross_of_differences(const Point& p0, const Point& p1, const Point& q0, const Point& q1) {
  return sign_of_poly(
      [](const auto& a, const auto& b, const auto& c, const auto& d) {
        return (b.x * a.w - a.x * b.w) * (d.y * c.w - c.y * d.w) - (b.y * a.w - a.y * b.w) * (d.x * c.w - c.x * d.w);
      },
      p0, p1, q0, q1);
}

/// sign((P1 − P0) · (Q1 − Q0)) of the drawn positions, under the conditions of
/// `cross_of_differences`. Exact.
inline Sign dot_of_differences(const Point& p0, const Point& p1, const Point& q0, const Point& q1) {
  return sign_of_poly(
      [](const auto& a, const auto& b, const auto& c, const auto& d) {
        return (b.x * a.w - a.x * b.w) * (d.x * c.w - c.x * d.w) + (b.y * a.w - a.y * b.w) * (d.y * c.w - c.y * d.w);
      },
      p0, p1, q0, q1);
}

}  // namespace detail

/// d1 ^− d2: the direction of the angle θ1 − θ2 (see the file comment). Both arguments must be
/// points of Ω, else throws `Undefined`. A construction: exact for `Integer`, rounded for
/// `double`.
template <class T>
BasicPoint<T> angle_difference(const BasicPoint<T>& d1, const BasicPoint<T>& d2) {
  const char* rule = "angle_difference(d1, d2) is defined for directions only: points [0, x, y] of Omega";
  detail::require_direction(d1, rule);
  detail::require_direction(d2, rule);
  const T x = d1.x() * d2.x() + d1.y() * d2.y();
  const T y = d1.y() * d2.x() - d1.x() * d2.y();
  if constexpr (std::is_same_v<T, double>) {
    if ((x == 0 && y == 0) || !std::isfinite(x) || !std::isfinite(y))
      return to_double(angle_difference(to_exact(d1), to_exact(d2)));
  }
  return BasicPoint<T>(T(0), x, y);
}

/// The angle p̂qr as a direction (a point of Ω): dir(q→p) ^− dir(q→r), the turn that takes the
/// way from q towards r onto the way from q towards p, counter-clockwise, with
/// dir = `t2::direction` (the first point of Ω met walking from q along the segment). For front
/// points this is the Euclidean angle from qr to qp; angle(¬p, ¬q, ¬r) = angle(p, q, r); for q
/// on Ω and p, r proper it is the angle zero, [0, 1, 0] up to a positive factor, as the seed
/// says. Throws `Undefined` when p or r is q or ¬q, and when q and p (or q and r) are both on Ω.
template <class T>
BasicPoint<T> angle(const BasicPoint<T>& p, const BasicPoint<T>& q, const BasicPoint<T>& r) {
  const BasicDirection<T> a = direction(q, p), b = direction(q, r);
  return angle_difference(BasicPoint<T>(T(0), a.dx(), a.dy()), BasicPoint<T>(T(0), b.dx(), b.dy()));
}

/// Compares the angles of two directions p, q (points of Ω), measured counter-clockwise from
/// [0, 1, 0] in [0, 2π): NEGATIVE when θp < θq, ZERO when p = q. The corrected Algorithm 1 (see
/// the file comment). Throws `Undefined` when p or q is not on Ω. Exact.
template <class T>
Sign compare_angle(const BasicPoint<T>& p, const BasicPoint<T>& q) {
  const char* rule = "compare_angle(p, q) compares directions only: points [0, x, y] of Omega";
  detail::require_direction(p, rule);
  detail::require_direction(q, rule);
  const int hp = detail::angle_half(p), hq = detail::angle_half(q);
  if (hp != hq) return hp < hq ? NEGATIVE : POSITIVE;
  // Same half turn: q is ahead of p iff p_x q_y - p_y q_x > 0.
  return sign_of_poly([](const auto& a, const auto& b) { return a.y * b.x - a.x * b.y; }, p, q);
}

}  // namespace t2
