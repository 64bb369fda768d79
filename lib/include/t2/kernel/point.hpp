#pragma once
/// @file point.hpp
/// @brief Points of T²: signed homogeneous triples [w, x, y], equal up to a *positive* factor.

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "t2/kernel/error.hpp"
#include "t2/kernel/filter.hpp"
#include "t2/kernel/number.hpp"
#include "t2/kernel/sign.hpp"

namespace t2 {

/// Where a point lies: on the front side (w > 0), on the line at infinity Ω (w = 0), or on the
/// back side (w < 0).
enum class Side { back = -1, infinity = 0, front = 1 };

/// "front", "back" or "infinity": the name of a side in messages and reports.
inline const char* to_string(Side s) {
  switch (s) {
    case Side::front: return "front";
    case Side::back: return "back";
    case Side::infinity: return "infinity";
  }
  return "?";
}

/// A point of the oriented projective plane T², with coordinates of type `T` (`double` or
/// `Integer`). `[w, x, y]` and `[αw, αx, αy]` are the same point when α > 0; with α < 0 they
/// are antipodes. `[0, 0, 0]` is not a point: the constructor throws `Undefined`.
template <class T>
class BasicPoint {
 public:
  using Coordinate = T;  ///< the number type of the coordinates

  /// The point [w, x, y]. Throws `Undefined` for [0,0,0] and `BadInput` for NaN or infinity.
  BasicPoint(T w, T x, T y) : w_(std::move(w)), x_(std::move(x)), y_(std::move(y)) {
    require_finite(w_, "w");
    require_finite(x_, "x");
    require_finite(y_, "y");
    if (w_ == 0 && x_ == 0 && y_ == 0) throw Undefined("[0,0,0] is not a point of T2");
  }

  /// The front point with Cartesian coordinates (x, y), i.e. [1, x, y].
  static BasicPoint cartesian(T x, T y) { return BasicPoint(T(1), std::move(x), std::move(y)); }
  /// The point at infinity in the direction (dx, dy), i.e. [0, dx, dy].
  static BasicPoint at_infinity(T dx, T dy) { return BasicPoint(T(0), std::move(dx), std::move(dy)); }

  const T& w() const { return w_; }  ///< homogeneous weight
  const T& x() const { return x_; }  ///< first coordinate
  const T& y() const { return y_; }  ///< second coordinate

 private:
  T w_, x_, y_;
};

/// Points with `double` coordinates: exact predicates, rounded constructions.
using Point = BasicPoint<double>;
/// Points with big-integer coordinates: exact predicates and exact constructions.
using ExactPoint = BasicPoint<Integer>;

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

/// The side of T² that holds p: front (w > 0), back (w < 0) or infinity (w = 0).
template <class T>
Side side_of(const BasicPoint<T>& p) {
  return static_cast<Side>(static_cast<int>(sign_of(p.w())));
}

/// True for points not on Ω (the "proper" points of the thesis).
template <class T>
bool is_proper(const BasicPoint<T>& p) {
  return p.w() != 0;
}
/// True for points on Ω, the line at infinity.
template <class T>
bool is_at_infinity(const BasicPoint<T>& p) {
  return p.w() == 0;
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

/// Converts a double point to integer coordinates representing the same point exactly
/// (every coordinate is scaled by the same power of two).
ExactPoint to_exact(const Point& p);

/// The nearest double point to an exact one (scaled so that no coordinate overflows).
Point to_double(const ExactPoint& p);

/// Normalized coordinates of the same point (a positive rescaling, rounded): [±1, x/|w|, y/|w|]
/// for a proper point, [0, x/m, y/m] with m = max(|x|, |y|) for a point at infinity.
Point normalized(const Point& p);

/// Cartesian coordinates (x/w, y/w) of a proper point; `std::nullopt` on Ω.
std::optional<std::pair<double, double>> to_cartesian(const Point& p);

/// The name of point i of a list (0-based, in file order), as messages and animations print
/// it: "p3".
inline std::string point_name(std::size_t i) {
  std::string s = "p";  // appended: "p" + to_string(i) draws GCC 12's false -Wrestrict (bug 105651)
  return s += std::to_string(i);
}

/// "[w, x, y]" with shortest round-trip numbers.
std::string to_string(const Point& p);
/// "[w, x, y]" with all digits.
std::string to_string(const ExactPoint& p);

}  // namespace t2
