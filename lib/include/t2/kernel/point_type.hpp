#pragma once
/// @file point_type.hpp
/// @brief The type of the points of T², its sides and its exact conversion, without the
/// operations on points (point.hpp). An exercise that asks for those operations allows this
/// header and not point.hpp: what its sandbox does not hold, a submission cannot call.

#include <cmath>
#include <string>
#include <utility>

#include "t2/kernel/error.hpp"
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

/// Converts a double point to integer coordinates representing the same point exactly
/// (every coordinate is scaled by the same power of two).
ExactPoint to_exact(const Point& p);

/// The nearest double point to an exact one (scaled so that no coordinate overflows).
Point to_double(const ExactPoint& p);

/// The name of point i of a list (0-based, in file order), as messages and animations print
/// it: "p3".
inline std::string point_name(std::size_t i) {
  std::string s = "p";  // appended: "p" + to_string(i) draws GCC 12's false -Wrestrict (bug 105651)
  return s += std::to_string(i);
}

}  // namespace t2
