#pragma once
/// @file vector.hpp
/// @brief Vectors (seed 000, §4.1.5) and directions (§4.1.10) of T².
///
/// A **vector** is stored, as in CGAL, by the homogeneous coordinates of its tip; its tail is
/// the origin O = [1, 0, 0] of the front side. So a vector is a segment from O: [w, x, y] with
/// w > 0 is the ordinary vector (x/w, y/w); w = 0 is an infinite vector (its tip is on Ω);
/// w < 0 reaches "beyond infinity" (its tip is on the back side, e.g. the difference from a
/// front point to a back point). Like the segment from O to ¬O, the vector with tip ¬O =
/// [-1, 0, 0] is undefined.
///
/// A **direction** is a point of Ω, [0, dx, dy]: the point at infinity one reaches by going
/// that way. Ω itself has no direction, and neither has a pair of antipodes or a pair of
/// points at infinity (§4.1.10: each of those already is a direction).

#include <string>
#include <utility>

#include "t2/kernel/error.hpp"
#include "t2/kernel/filter.hpp"
#include "t2/kernel/line.hpp"
#include "t2/kernel/number.hpp"
#include "t2/kernel/point.hpp"

namespace t2 {

/// A direction of T²: the point at infinity [0, dx, dy]. [0, 0, 0] is not a direction.
template <class T>
class BasicDirection {
 public:
  using Coordinate = T;  ///< the number type of the coordinates
  /// The direction (dx, dy). Throws `Undefined` for (0, 0).
  BasicDirection(T dx, T dy) : dx_(std::move(dx)), dy_(std::move(dy)) {
    require_finite(dx_, "dx");
    require_finite(dy_, "dy");
    if (dx_ == 0 && dy_ == 0) throw Undefined("direction(0, 0) is undefined: (0, 0) points nowhere");
  }
  /// The direction of a point at infinity. Throws `Undefined` for a proper point.
  explicit BasicDirection(const BasicPoint<T>& at_infinity)
      : BasicDirection(on_omega(at_infinity).x(), at_infinity.y()) {}
  const T& dx() const { return dx_; }  ///< first component
  const T& dy() const { return dy_; }  ///< second component
  /// The point at infinity [0, dx, dy].
  BasicPoint<T> point() const { return BasicPoint<T>(T(0), dx_, dy_); }

 private:
  static const BasicPoint<T>& on_omega(const BasicPoint<T>& p) {
    if (p.w() != 0) throw Undefined("a direction is a point at infinity (w = 0)");
    return p;
  }
  T dx_, dy_;
};

/// Directions with `double` components.
using Direction = BasicDirection<double>;
/// Directions with big-integer components.
using ExactDirection = BasicDirection<Integer>;

/// Equal directions: (dx, dy) and (αdx, αdy) with α > 0. Exact.
template <class T>
bool operator==(const BasicDirection<T>& d, const BasicDirection<T>& e) {
  return d.point() == e.point();
}

/// The opposite direction (-dx, -dy), i.e. the antipode of the point at infinity.
template <class T>
BasicDirection<T> opposite(const BasicDirection<T>& d) {
  return BasicDirection<T>(T(-d.dx()), T(-d.dy()));
}

/// The direction in which one leaves p when walking along the segment towards q: the first
/// point of Ω met on the half great circle from p through q. For proper p it is
/// sign(w_p)·(w_p q − w_q p) (for two front points this is the usual q − p; for p front and q
/// back it is where the segment pq crosses Ω); for p on Ω and q proper it is ¬p (one comes in
/// from p). Undefined (seed §4.1.10) when p = ¬q, when both points are on Ω (each already is a
/// direction), and when p = q.
template <class T>
BasicDirection<T> direction(const BasicPoint<T>& p, const BasicPoint<T>& q) {
  if (p.w() == 0 && q.w() == 0)
    throw Undefined("direction(p, q) is undefined when p and q are both at infinity");
  if (p == antipode(q)) throw Undefined("direction(p, q) is undefined when q = antipode(p)");
  if (p == q) throw Undefined("direction(p, q) is undefined when p = q");
  if (p.w() == 0) return BasicDirection<T>(T(-p.x()), T(-p.y()));
  const T s = p.w() > 0 ? T(1) : T(-1);
  return BasicDirection<T>(T(s * (p.w() * q.x() - q.w() * p.x())), T(s * (p.w() * q.y() - q.w() * p.y())));
}

/// The direction of an oriented line ⟨W, X, Y⟩: (Y, −X), the way one walks with the positive
/// side on the left. Ω has no direction: throws `Undefined`.
template <class T>
BasicDirection<T> direction(const BasicLine<T>& l) {
  if (l.X() == 0 && l.Y() == 0) throw Undefined("the line at infinity has no direction");
  return BasicDirection<T>(l.Y(), T(-l.X()));
}

/// A vector of T²: the segment from the front origin O = [1, 0, 0] to its tip [w, x, y]
/// (see the file comment). The tip ¬O = [-1, 0, 0] is undefined.
template <class T>
class BasicVector {
 public:
  using Coordinate = T;  ///< the number type of the coordinates
  /// The vector with tip [w, x, y]. Throws `Undefined` for the tip ¬O = [-1, 0, 0].
  BasicVector(T w, T x, T y) : tip_(std::move(w), std::move(x), std::move(y)) {
    if (tip_.w() < 0 && tip_.x() == 0 && tip_.y() == 0)
      throw Undefined("vector(O, antipode(O)) is undefined, like every segment between antipodes");
  }
  /// The vector whose tip is the point p.
  explicit BasicVector(const BasicPoint<T>& tip) : BasicVector(tip.w(), tip.x(), tip.y()) {}
  /// The ordinary vector (dx, dy), i.e. tip [1, dx, dy].
  static BasicVector cartesian(T dx, T dy) { return BasicVector(T(1), std::move(dx), std::move(dy)); }
  const T& w() const { return tip_.w(); }  ///< weight of the tip
  const T& x() const { return tip_.x(); }  ///< first coordinate of the tip
  const T& y() const { return tip_.y(); }  ///< second coordinate of the tip
  /// The tip as a point of T².
  const BasicPoint<T>& point() const { return tip_; }

 private:
  BasicPoint<T> tip_;
};

/// Vectors with `double` coordinates.
using Vector = BasicVector<double>;
/// Vectors with big-integer coordinates.
using ExactVector = BasicVector<Integer>;

/// Equal vectors: tips equal as points of T² (up to a positive factor). Exact.
template <class T>
bool operator==(const BasicVector<T>& u, const BasicVector<T>& v) {
  return u.point() == v.point();
}

/// The difference q − p: [w_p w_q, w_p x_q − w_q x_p, w_p y_q − w_q y_p]. For proper p the
/// translation by it (affine.hpp) maps p exactly to q, whatever their sides: a front p and a
/// back q give a vector "beyond infinity" (w < 0); q on Ω gives an infinite vector.
/// Undefined when p is on Ω (no translation moves a point at infinity) and when q = ¬p (the
/// segment from p to q is undefined).
template <class T>
BasicVector<T> vector(const BasicPoint<T>& p, const BasicPoint<T>& q) {
  if (p.w() == 0) throw Undefined("vector(p, q) is undefined when p is at infinity");
  if (p == antipode(q)) throw Undefined("vector(p, q) is undefined when q = antipode(p)");
  return BasicVector<T>(T(p.w() * q.w()), T(p.w() * q.x() - q.w() * p.x()), T(p.w() * q.y() - q.w() * p.y()));
}

/// The direction of a vector: the point of Ω met going from O towards its tip, (x, y).
/// The null vector [w, 0, 0] (w > 0) has no direction: throws `Undefined`.
template <class T>
BasicDirection<T> direction(const BasicVector<T>& v) {
  if (v.x() == 0 && v.y() == 0) throw Undefined("the null vector has no direction");
  return BasicDirection<T>(v.x(), v.y());
}

/// "direction(dx, dy)".
template <class T>
std::string to_string(const BasicDirection<T>& d) {
  const std::string s = to_string(d.point());  // "[0, dx, dy]"
  return "direction(" + s.substr(4, s.size() - 5) + ")";
}
/// "vector[w, x, y]".
template <class T>
std::string to_string(const BasicVector<T>& v) {
  return "vector" + to_string(v.point());
}

}  // namespace t2
