#pragma once
/// @file t1.hpp
/// @brief The oriented projective line T¹: points [w, x] up to a positive factor.
///
/// T¹ is two copies of the real line (front w > 0, back w < 0) joined by two points at
/// infinity, +∞ = [0, 1] and -∞ = [0, -1]; as a circle, [w, x] is the direction of the vector
/// (w, x). The library uses T¹ values for quantities that may be infinite or "beyond infinity":
/// squared distances (in T¹ with x ≥ 0) and the extents Δx, Δy of rectangles (in T¹ with w ≥ 0).

#include <string>
#include <utility>

#include "t2/kernel/error.hpp"
#include "t2/kernel/filter.hpp"
#include "t2/kernel/number.hpp"

namespace t2 {

/// A point [w, x] of T¹. [0, 0] is not a point: the constructor throws `Undefined`.
template <class T>
class BasicT1 {
 public:
  using Coordinate = T;  ///< the number type of the coordinates
  /// The point [w, x].
  BasicT1(T w, T x) : w_(std::move(w)), x_(std::move(x)) {
    require_finite(w_, "w");
    require_finite(x_, "x");
    if (w_ == 0 && x_ == 0) throw Undefined("[0,0] is not a point of T1");
  }
  /// The finite value v, i.e. [1, v].
  static BasicT1 finite(T v) { return BasicT1(T(1), std::move(v)); }
  /// +∞ = [0, 1].
  static BasicT1 plus_infinity() { return BasicT1(T(0), T(1)); }
  /// -∞ = [0, -1].
  static BasicT1 minus_infinity() { return BasicT1(T(0), T(-1)); }

  const T& w() const { return w_; }  ///< weight
  const T& x() const { return x_; }  ///< coordinate

 private:
  T w_, x_;
};

/// A point of T¹ is read by the filter's polynomials as a Hom2 (`a.w`, `a.x`; filter.hpp).
template <class T>
struct Leaves<BasicT1<T>> {
  using Coordinate = T;  ///< the number type of the coordinates
  /// The point on the stage's number type.
  template <class F>
  static auto map(const BasicT1<T>& a, F&& leaf) {
    return Hom2<decltype(leaf(a.w()))>{leaf(a.w()), leaf(a.x())};
  }
  /// True when `test` holds for both coordinates.
  template <class F>
  static bool all(const BasicT1<T>& a, F&& test) {
    return test(a.w()) && test(a.x());
  }
  /// The point's shape with every coordinate `leaf` (filter.hpp's derive_bound).
  template <class N>
  static constexpr Hom2<N> shape(const N& leaf) {
    return {leaf, leaf};
  }
};

/// T¹ points with `double` coordinates.
using T1 = BasicT1<double>;
/// T¹ points with big-integer coordinates.
using ExactT1 = BasicT1<Integer>;

/// The side of T¹ holding a: POSITIVE front, NEGATIVE back, ZERO at infinity.
template <class T>
Sign side_of(const BasicT1<T>& a) {
  return sign_of(a.w());
}
/// True at +∞ or -∞.
template <class T>
bool is_infinite(const BasicT1<T>& a) {
  return a.w() == 0;
}
/// The antipode [-w, -x].
template <class T>
BasicT1<T> antipode(const BasicT1<T>& a) {
  return BasicT1<T>(T(-a.w()), T(-a.x()));
}

/// Equality up to a positive factor. Exact.
template <class T>
bool operator==(const BasicT1<T>& a, const BasicT1<T>& b) {
  return orient(a, b) == ZERO &&
         sign_of_poly([](const auto& p, const auto& q) { return p.w * q.w + p.x * q.x; }, a, b) == POSITIVE;
}

/// Orientation of T¹ (the 2×2 determinant |a; b|): POSITIVE when b follows a counter-clockwise
/// on the circle model within half a turn. For two front points this is sign(b - a).
template <class T>
Sign orient(const BasicT1<T>& a, const BasicT1<T>& b) {
  return sign_of_poly([](const auto& p, const auto& q) { return p.w * q.x - p.x * q.w; }, a, b);
}

/// Compares two values of the closed extended line [-∞, +∞] given as T¹ points with w ≥ 0
/// (the set used for distances and rectangle extents): NEGATIVE when a < b. Throws `Undefined`
/// for a back point (w < 0), which has no place in that order.
template <class T>
Sign compare(const BasicT1<T>& a, const BasicT1<T>& b) {
  if (a.w() < 0 || b.w() < 0)
    throw Undefined("compare(a, b) on T1 orders only points with w >= 0 (front or infinite)");
  // Both infinite: +inf > -inf, and each equals itself.
  if (a.w() == 0 && b.w() == 0) return sign_of(a.x()) == sign_of(b.x()) ? ZERO : sign_of(a.x());
  // Otherwise a < b iff a.x/a.w < b.x/b.w, i.e. a.x*b.w - b.x*a.w < 0 (the weights are >= 0 and
  // not both zero), which is -orient(a, b); it extends correctly to one infinite value.
  return -orient(a, b);
}

/// The same point of T¹ with big-integer coordinates: both scaled by one positive power of two
/// (as `to_exact` of a point), so nothing is rounded.
ExactT1 to_exact(const T1& a);

/// "[w, x]".
std::string to_string(const T1& a);
/// "[w, x]" with all digits.
std::string to_string(const ExactT1& a);

}  // namespace t2
