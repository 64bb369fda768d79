#pragma once
/// @file closest_point.hpp
/// @brief The point of a segment closest to a given point, in homogeneous coordinates and
/// without a single division.

#include <type_traits>

#include "t2/kernel/error.hpp"
#include "t2/kernel/filter.hpp"
#include "t2/kernel/point.hpp"

namespace t2 {

/// The point of the segment ab nearest to q (Euclidean distance), for a, b, q proper points on
/// one side of T² (all front or all back: across Ω distances are infinite, seed 000 §4.3.1).
///
/// With Cartesian A, B, Q the answer is A + t(B − A), t = (Q−A)·(B−A) / |B−A|² clamped to
/// [0, 1]. Multiplying through by the weights gives t = N/D with the polynomials
/// N = w_b (V·U), D = w_q (U·U), where U = w_a b − w_b a and V = w_a q − w_q a (x, y parts),
/// and the point itself is the positive combination w_b(D − N)·a + w_a N·b: no division, exact
/// for `Integer` coordinates (rounded for `double`). The clamping decisions (t ≤ 0, t ≥ 1) are
/// exact signs. Throws `Undefined` when the points are not all proper and on one side.
template <class T>
BasicPoint<T> closest_point_on_segment(const BasicPoint<T>& a, const BasicPoint<T>& b, const BasicPoint<T>& q) {
  const Side s = side_of(q);
  if (s == Side::infinity || side_of(a) != s || side_of(b) != s)
    throw Undefined(
        "closest_point_on_segment(a, b, q) needs a, b, q proper and on one side of T2 (distances across the line at infinity are infinite)");
  //> closest-polys
  // U = w_a·(x_b, y_b) − w_b·(x_a, y_a) ~ B − A;
  // V = w_a·(x_q, y_q) − w_q·(x_a, y_a) ~ Q − A
  auto N = [](const auto& a, const auto& b, const auto& q) {
    return b.w * ((a.w * q.x - q.w * a.x) * (a.w * b.x - b.w * a.x) +
                  (a.w * q.y - q.w * a.y) * (a.w * b.y - b.w * a.y));
  };
  auto D = [](const auto& a, const auto& b, const auto& q) {
    return q.w * ((a.w * b.x - b.w * a.x) * (a.w * b.x - b.w * a.x) +
                  (a.w * b.y - b.w * a.y) * (a.w * b.y - b.w * a.y));
  };
  //< closest-polys
  // No captures (filter.hpp, bound_of): D and N are stateless, so their types' objects are them.
  auto DminusN = [](const auto& u, const auto& v, const auto& r) {
    return decltype(D){}(u, v, r) - decltype(N){}(u, v, r);
  };
  const auto args = [&](auto&& f) { return sign_of_poly(f, a, b, q); };
  auto evaluate = [&](auto&& f) -> T {  // gmpxx temporaries must not outlive the lambda
    if constexpr (std::is_same_v<T, double>) {
      return detail::apply_leaves(f, [](double v) { return v; }, a, b, q);
    } else {
      return detail::apply_leaves(f, [](const Integer& v) { return Exact<Integer>(v); }, a, b, q).v;
    }
  };
  const Sign sD = args(D);  // sign(w_q) or 0 when a = b
  if (sD == ZERO) return a;
  // t = N/D ≤ 0  <=>  sign(N)·sign(D) ≤ 0;   t ≥ 1  <=>  sign(D − N)·sign(D) ≤ 0.
  if (args(N) * sD != POSITIVE) return a;
  if (args(DminusN) * sD != POSITIVE) return b;
  //> closest-combine
  const T n = evaluate(N), d = evaluate(D);
  const T ca = b.w() * (d - n), cb = a.w() * n;  // P = ca·a + cb·b, both coefficients > 0
  return mix(ca, a, cb, b);
  //< closest-combine
}

}  // namespace t2
