#pragma once
/// @file point.hpp
/// @brief Points of T²: signed homogeneous triples [w, x, y], equal up to a *positive* factor.
/// The type is in point_type.hpp; here are the operations on points.

#include <optional>
#include <string>
#include <utility>

#include "t2/kernel/filter.hpp"
#include "t2/kernel/point_type.hpp"

namespace t2 {

/// A point is read by the filter's polynomials as a Hom3 (`p.w`, `p.x`, `p.y`; filter.hpp).
template <class T>
struct Leaves<BasicPoint<T>> {
  using Coordinate = T;  ///< the number type of the coordinates
  /// The point on the stage's number type.
  template <class F>
  static auto map(const BasicPoint<T>& p, F&& leaf) {
    return Hom3<decltype(leaf(p.w()))>{leaf(p.w()), leaf(p.x()), leaf(p.y())};
  }
  /// True when `test` holds for the three coordinates.
  template <class F>
  static bool all(const BasicPoint<T>& p, F&& test) {
    return test(p.w()) && test(p.x()) && test(p.y());
  }
  /// The point's shape with every coordinate `leaf` (filter.hpp's derive_bound).
  template <class N>
  static constexpr Hom3<N> shape(const N& leaf) {
    return {leaf, leaf, leaf};
  }
};

/// The antipode ¬p = [-w, -x, -y]: distinct from p, it coincides with p in the planar model
/// and is diametrically opposite on the sphere.
template <class T>
BasicPoint<T> antipode(const BasicPoint<T>& p) {
  return BasicPoint<T>(T(-p.w()), T(-p.x()), T(-p.y()));
}

/// The positive combination αp + βq = [αw_p + βw_q, αx_p + βx_q, αy_p + βy_q], for α, β ≥ 0
/// not both zero (the caller's duty; not checked). On the sphere it is the direction of the
/// vector αp + βq: a point of the shorter arc from p to q, so of the segment pq of T² whenever
/// q ≠ ¬p. Exact with `Integer` coordinates; with `double` the products and sums are rounded
/// (exact only when they are representable). Throws `Undefined` when the sum is [0, 0, 0]
/// (αp = −βq, so q = ¬p), and `BadInput` when a `double` coordinate overflows.
template <class T>
BasicPoint<T> mix(const T& alpha, const BasicPoint<T>& p, const T& beta, const BasicPoint<T>& q) {
  return BasicPoint<T>(T(alpha * p.w() + beta * q.w()), T(alpha * p.x() + beta * q.x()),
                       T(alpha * p.y() + beta * q.y()));
}

/// Equality in T²: p = q iff q = αp for some α > 0 (so p != ¬p). Exact for every input.
template <class T>
bool operator==(const BasicPoint<T>& p, const BasicPoint<T>& q) {
  // p × q = 0 (the three minors) and p · q > 0.
  if (sign_of_poly([](const auto& a, const auto& b) { return a.w * b.x - a.x * b.w; }, p, q) != ZERO) return false;
  if (sign_of_poly([](const auto& a, const auto& b) { return a.w * b.y - a.y * b.w; }, p, q) != ZERO) return false;
  if (sign_of_poly([](const auto& a, const auto& b) { return a.x * b.y - a.y * b.x; }, p, q) != ZERO) return false;
  return sign_of_poly([](const auto& a, const auto& b) { return a.w * b.w + a.x * b.x + a.y * b.y; }, p, q) ==
         POSITIVE;
}

/// Normalized coordinates of the same point (a positive rescaling, rounded): [±1, x/|w|, y/|w|]
/// for a proper point, [0, x/m, y/m] with m = max(|x|, |y|) for a point at infinity.
Point normalized(const Point& p);

/// Cartesian coordinates (x/w, y/w) of a proper point; `std::nullopt` on Ω.
std::optional<std::pair<double, double>> to_cartesian(const Point& p);

/// "[w, x, y]" with shortest round-trip numbers.
std::string to_string(const Point& p);
/// "[w, x, y]" with all digits.
std::string to_string(const ExactPoint& p);

}  // namespace t2
