#pragma once
/// @file midpoint.hpp
/// @brief The midpoint of two points of T² (seed 000, §4.3.2), and the naive formulas that fail.
///
/// The formula of T² (de Rezende and Stolfi) weights each point by the absolute weight of the
/// other:
///
///     midpoint(p, q) = [ |q_w| p_w + |p_w| q_w,  |q_w| p_x + |p_w| q_x,  |q_w| p_y + |p_w| q_y ].
///
/// What it gives, case by case (P, Q the Cartesian positions of proper points):
/// - p, q on the same side σ = ±1: |p_w q_w| σ [2, P + Q], the Euclidean midpoint on that side.
/// - p front, q back: w = 0 exactly, the point [0, P − Q] of Ω, which is where the segment pq
///   crosses Ω. Right: a midpoint on either side would be nearer to the point of that side (the
///   other is beyond infinity), so only Ω is at "equal distance".
/// - p proper, q on Ω: [0, |p_w| q_x, |p_w| q_y] = q. Halfway to infinity is still infinity.
/// - q = ¬p: the formula gives [0, 0, 0]. The segment of two antipodes is undefined in T² (every
///   half great circle joins them), so is its midpoint: `Undefined`.
/// - p, q both on Ω: the formula gives [0, 0, 0] too. The midpoint should be the direction that
///   bisects the angle of p and q, [0, p/|p| + q/|q|]; that needs square roots, so it is not a
///   construction of T² (which never leaves the coordinate ring). The library returns p when
///   p = q and throws `Undefined` otherwise.
///
/// The naive formulas a first attempt produces live in chapter 03's program, which shows why
/// they fail; they are not part of the library.

#include <array>
#include <cmath>
#include <type_traits>

#include "t2/kernel/error.hpp"
#include "t2/kernel/number.hpp"
#include "t2/kernel/point.hpp"

namespace t2 {

namespace detail {

inline bool all_zero_or_not_finite(double w, double x, double y) {
  return (w == 0 && x == 0 && y == 0) || !std::isfinite(w) || !std::isfinite(x) || !std::isfinite(y);
}

template <class T>
T abs_value(const T& v) {
  return v < 0 ? T(-v) : v;
}

/// The seed formula on raw coordinates (no checks).
template <class T>
std::array<T, 3> midpoint_formula(const BasicPoint<T>& p, const BasicPoint<T>& q) {
  const T ap = abs_value(p.w()), aq = abs_value(q.w());
  return {T(aq * p.w() + ap * q.w()), T(aq * p.x() + ap * q.x()), T(aq * p.y() + ap * q.y())};
}

}  // namespace detail

/// The midpoint of p and q in T² (see the file comment): the Euclidean midpoint for points on
/// the same side, the crossing of Ω for points on opposite sides, q itself when only q is on Ω.
/// Throws `Undefined` when q = ¬p, and when p and q are distinct points of Ω. No division: exact
/// for `Integer` coordinates; for `double` rounded (recomputed exactly if rounding would
/// produce [0, 0, 0] or overflow).
template <class T>
BasicPoint<T> midpoint(const BasicPoint<T>& p, const BasicPoint<T>& q) {
  if (p == antipode(q)) throw Undefined("midpoint(p, q) is undefined when q = antipode(p): so is segment(p, q)");
  if (p.w() == 0 && q.w() == 0) {
    if (p == q) return p;
    throw Undefined(
        "midpoint(p, q) is undefined when p and q are distinct points of Omega: the bisecting "
        "direction needs square roots");
  }
  auto m = detail::midpoint_formula(p, q);
  if constexpr (std::is_same_v<T, double>) {
    if (detail::all_zero_or_not_finite(m[0], m[1], m[2])) return to_double(midpoint(to_exact(p), to_exact(q)));
  }
  return BasicPoint<T>(m[0], m[1], m[2]);
}

}  // namespace t2
