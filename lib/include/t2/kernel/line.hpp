#pragma once
/// @file line.hpp
/// @brief Oriented lines ⟨W, X, Y⟩ of T², join, meet, the sign test ⋄ and duality.
///
/// The line ⟨W, X, Y⟩ is the set of points with Ww + Xx + Yy = 0, and it is oriented: its
/// positive side holds the points where that sum is positive. ⟨W,X,Y⟩ and ⟨αW,αX,αY⟩ are the
/// same oriented line for α > 0; for α < 0 they are the same set with opposite orientations.
/// Join and meet are cross products: no division, so exact with `Integer` coordinates.

#include <array>
#include <string>
#include <utility>

#include "t2/kernel/error.hpp"
#include "t2/kernel/filter.hpp"
#include "t2/kernel/number.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/kernel/point.hpp"

namespace t2 {

/// An oriented line ⟨W, X, Y⟩ of T². ⟨0,0,0⟩ is not a line: the constructor throws `Undefined`.
template <class T>
class BasicLine {
 public:
  using Coordinate = T;  ///< the number type of the coordinates

  /// The line ⟨W, X, Y⟩.
  BasicLine(T W, T X, T Y) : W_(std::move(W)), X_(std::move(X)), Y_(std::move(Y)) {
    require_finite(W_, "W");
    require_finite(X_, "X");
    require_finite(Y_, "Y");
    if (W_ == 0 && X_ == 0 && Y_ == 0) throw Undefined("<0,0,0> is not a line of T2");
  }
  const T& W() const { return W_; }  ///< coefficient of w
  const T& X() const { return X_; }  ///< coefficient of x
  const T& Y() const { return Y_; }  ///< coefficient of y

 private:
  T W_, X_, Y_;
};

/// Lines with `double` coefficients.
using Line = BasicLine<double>;
/// Lines with big-integer coefficients.
using ExactLine = BasicLine<Integer>;

/// A line is read by the filter's polynomials as a Line3 (`l.W`, `l.X`, `l.Y`; filter.hpp).
template <class T>
struct Leaves<BasicLine<T>> {
  using Coordinate = T;  ///< the number type of the coefficients
  /// The line on the stage's number type.
  template <class F>
  static auto map(const BasicLine<T>& l, F&& leaf) {
    return Line3<decltype(leaf(l.W()))>{leaf(l.W()), leaf(l.X()), leaf(l.Y())};
  }
  /// True when `test` holds for the three coefficients.
  template <class F>
  static bool all(const BasicLine<T>& l, F&& test) {
    return test(l.W()) && test(l.X()) && test(l.Y());
  }
  /// The line's shape with every coefficient `leaf` (filter.hpp's derive_bound).
  template <class N>
  static constexpr Line3<N> shape(const N& leaf) {
    return {leaf, leaf, leaf};
  }
};

/// Ω, the line at infinity ⟨1, 0, 0⟩, oriented so that the front side is its positive side.
template <class T = double>
BasicLine<T> omega() {
  return BasicLine<T>(T(1), T(0), T(0));
}

/// l ⋄ p: the side of line l on which point p lies (seed 000, §4.3.6). ZERO when p is on l.
/// Exact for every finite input. Note side(l, ¬p) = -side(l, p).
///
/// On doubles the fast path is W·w + X·x + Y·y in plain arithmetic against the bound filter.hpp
/// derives for it: three monomials of degree 1 in l and in p, each meeting its product and at
/// most two sums (k = 3), so |fl(v) − v| ≤ 3γ₃·M_l·M_p with M_l, M_p the largest |coefficient| of
/// l and |coordinate| of p; the code's bound is 9u(1 + 2⁻⁴⁰)·M_l·M_p, trusted for M_l, M_p ∈
/// [2⁻⁴⁵⁰, 2⁴⁵⁰]. The exact stage is the expansion of the three exact products (filter.hpp).
template <class T>
Sign side(const BasicLine<T>& l, const BasicPoint<T>& p) {
  return sign_of_poly([](const auto& m, const auto& q) { return m.W * q.w + m.X * q.x + m.Y * q.y; }, l, p);
}

/// The opposite line ¬l = <-W, -X, -Y>: the same points, the orientation and the sides swapped
/// (one verb, `opposite`, for segments, circles, directions and rectangles too).
template <class T>
BasicLine<T> opposite(const BasicLine<T>& l) {
  return BasicLine<T>(T(-l.W()), T(-l.X()), T(-l.Y()));
}

/// The old name of `opposite(l)`, kept while code written against it moves (issue 11).
template <class T>
[[deprecated("reverse(l) is now opposite(l)")]] BasicLine<T> reverse(const BasicLine<T>& l) {
  return opposite(l);
}

/// Equality of oriented lines (up to a positive factor). Exact.
template <class T>
bool operator==(const BasicLine<T>& l, const BasicLine<T>& m) {
  return BasicPoint<T>(l.W(), l.X(), l.Y()) == BasicPoint<T>(m.W(), m.X(), m.Y());
}

namespace detail {
/// Cross product of two triples, exact for integers; for doubles rounded, recomputed exactly
/// when rounding would lose the result (all three zero, or an overflow). Throws `Undefined`
/// with `rule` when the exact product is zero (the operands are equal or opposite).
std::array<double, 3> cross(const std::array<double, 3>& a, const std::array<double, 3>& b,
                            const char* rule);
std::array<Integer, 3> cross(const std::array<Integer, 3>& a, const std::array<Integer, 3>& b,
                             const char* rule);
}  // namespace detail

/// p ∨ q: the line through p and q, oriented from p towards q (so r is on its positive side
/// when orient(p, q, r) is POSITIVE). Undefined when p = q or p = ¬q.
template <class T>
BasicLine<T> join(const BasicPoint<T>& p, const BasicPoint<T>& q) {
  auto c = detail::cross(std::array<T, 3>{p.w(), p.x(), p.y()}, std::array<T, 3>{q.w(), q.x(), q.y()},
                         "join(p, q) is undefined when p = q or p = antipode(q)");
  return BasicLine<T>(c[0], c[1], c[2]);
}

/// l ∧ m: the meeting point of two lines — of the two antipodal common points, the one for
/// which (l, m) turn counter-clockwise. Undefined when l and m are the same line (either
/// orientation). Parallel front lines meet on Ω.
template <class T>
BasicPoint<T> meet(const BasicLine<T>& l, const BasicLine<T>& m) {
  auto c = detail::cross(std::array<T, 3>{l.W(), l.X(), l.Y()}, std::array<T, 3>{m.W(), m.X(), m.Y()},
                         "meet(l, m) is undefined when l and m are the same line");
  return BasicPoint<T>(c[0], c[1], c[2]);
}

/// Duality: the point whose coordinates are the line's coefficients. p is on l iff dual(l)
/// is on dual(p), and side(l, p) = side(dual(p), dual(l)).
template <class T>
BasicPoint<T> dual(const BasicLine<T>& l) {
  return BasicPoint<T>(l.W(), l.X(), l.Y());
}
/// Duality: the line whose coefficients are the point's coordinates.
template <class T>
BasicLine<T> dual(const BasicPoint<T>& p) {
  return BasicLine<T>(p.w(), p.x(), p.y());
}

/// "<W, X, Y>".
std::string to_string(const Line& l);
/// "<W, X, Y>" with all digits.
std::string to_string(const ExactLine& l);

}  // namespace t2
