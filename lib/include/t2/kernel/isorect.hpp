#pragma once
/// @file isorect.hpp
/// @brief Iso-rectangles of T² (seed 000, §4.1.7): a corner a, extents Δx, Δy in T¹ (w ≥ 0)
/// and an orientation.
///
/// Two opposite corners do not determine an axis-parallel rectangle of T² once one of them
/// is at infinity, so the thesis stores a proper corner a = [w_a, x_a, y_a] and the extents
/// Δx = [w_Δx, x_Δx], Δy = [w_Δy, y_Δy], values of T¹ with w ≥ 0 (finite or ±∞). In Cartesian
/// terms b = a + (Δx, 0), c = a + (Δx, Δy), d = a + (0, Δy); homogeneously, with no division,
///
///     b = [w_a w_Δx,       x_a w_Δx + x_Δx w_a,              y_a w_Δx]
///     c = [w_a w_Δx w_Δy,  x_a w_Δx w_Δy + x_Δx w_a w_Δy,    y_a w_Δx w_Δy + y_Δy w_a w_Δx]
///     d = [w_a w_Δy,       x_a w_Δy,                         y_a w_Δy + y_Δy w_a]
///
/// **Corrections to the seed.** (1) Its printed Cartesian formulas have typos: Y_c uses the
/// x-coordinate of Δy, and Y_d reads x_a/w_a + … where it must be y_a/w_a + y_Δy/w_Δy (the
/// homogeneous c above is the correct one; the seed's also writes x_Δy for y_Δy).
/// (2) When Δx and Δy are both infinite the formula gives c = [0, 0, 0], and the seed then
/// sets c = [0, x_a, y_a]. That is wrong: for a at the origin it is again [0, 0, 0], and for
/// a = (−1, 2) with Δx = Δy = +∞ it is the direction (−1, 2), which is not even on the arc of
/// Ω between b = [0, 1, 0] and d = [0, 0, 1] that closes the quadrant. The right corner is
/// the limit of c along the diagonal (w_Δx = w_Δy = t → 0, divided by t):
/// c = [0, w_a x_Δx, w_a y_Δy], the sum of b and d, always on that arc.
///
/// Vertices on different sides of T² are undefined (figure 4.4: the sides ab and dc would
/// cross at infinity). With a proper and both extents in T¹ with w ≥ 0, every vertex is on
/// a's side or on Ω; an extent "beyond infinity" (w < 0) is exactly what breaks the rule.

#include <string>
#include <utility>

#include "t2/kernel/error.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/t1.hpp"

namespace t2 {

namespace detail {
/// a + Δ on extended Cartesian values given as T¹ points with w ≥ 0: [w1 w2, x1 w2 + x2 w1].
template <class T>
BasicT1<T> t1_add(const BasicT1<T>& a, const BasicT1<T>& b) {
  return BasicT1<T>(T(a.w() * b.w()), T(a.x() * b.w() + b.x() * a.w()));
}
/// hi − lo on extended Cartesian values (w ≥ 0): [w1 w2, x_hi w_lo − x_lo w_hi].
template <class T>
BasicT1<T> t1_sub(const BasicT1<T>& hi, const BasicT1<T>& lo) {
  return BasicT1<T>(T(hi.w() * lo.w()), T(hi.x() * lo.w() - lo.x() * hi.w()));
}
/// The extended Cartesian value x/w of a homogeneous coordinate pair, as T¹ with w ≥ 0.
template <class T>
BasicT1<T> cartesian_t1(const T& w, const T& x) {
  return w < 0 ? BasicT1<T>(T(-w), T(-x)) : BasicT1<T>(w, x);
}
/// Checks the common preconditions of iso-rectangles and boxes.
template <class T>
void check_rect(const BasicPoint<T>& a, const BasicT1<T>& dx, const BasicT1<T>& dy, const char* what) {
  if (a.w() == 0) throw Undefined(std::string(what) + " is undefined when its corner a is at infinity");
  if (dx.w() < 0 || dy.w() < 0)
    throw Undefined(std::string(what) +
                    " is undefined when its vertices lie on different sides of T2 (an extent beyond infinity, w < 0)");
}
/// Vertex i (0 = a, 1 = b, 2 = c, 3 = d) of the rectangle a, Δx, Δy, by the formulas of
/// isorect.hpp (with the corrected corner c when both extents are infinite).
template <class T>
BasicPoint<T> rect_vertex(const BasicPoint<T>& a, const BasicT1<T>& dx, const BasicT1<T>& dy, int i) {
  const T &wa = a.w(), &xa = a.x(), &ya = a.y();
  const T &wx = dx.w(), &xx = dx.x(), &wy = dy.w(), &yy = dy.x();
  switch (((i % 4) + 4) % 4) {
    case 0:
      return a;
    case 1:
      return BasicPoint<T>(T(wa * wx), T(xa * wx + xx * wa), T(ya * wx));
    case 2:
      if (wx == 0 && wy == 0) return BasicPoint<T>(T(0), T(wa * xx), T(wa * yy));
      return BasicPoint<T>(T(wa * wx * wy), T(xa * wx * wy + xx * wa * wy), T(ya * wx * wy + yy * wa * wx));
    default:
      return BasicPoint<T>(T(wa * wy), T(xa * wy), T(ya * wy + yy * wa));
  }
}
}  // namespace detail

/// An oriented axis-parallel rectangle of T² (see the file comment): corner a, extents Δx,
/// Δy ∈ T¹ with w ≥ 0, and the orientation of its boundary. Zero extents give degenerate
/// (flat or one-point) rectangles, allowed as in CGAL.
template <class T>
class BasicIsoRect {
 public:
  using Coordinate = T;  ///< the number type of the coordinates

  /// The rectangle a, a + Δx, a + Δx + Δy, a + Δy, traversed with `orientation` (POSITIVE:
  /// counter-clockwise in T², i.e. Δ(vertex 0, vertex 1, vertex 3) > 0). Throws `Undefined`
  /// for a at infinity or an extent with w < 0 (vertices on different sides), `BadInput` for
  /// orientation ZERO.
  BasicIsoRect(BasicPoint<T> a, BasicT1<T> dx, BasicT1<T> dy, Sign orientation = POSITIVE)
      : a_(std::move(a)), dx_(std::move(dx)), dy_(std::move(dy)), o_(orientation) {
    detail::check_rect(a_, dx_, dy_, "iso_rect(a, dx, dy)");
    if (o_ == ZERO) throw BadInput("an iso-rectangle is oriented: POSITIVE or NEGATIVE, not ZERO");
  }

  const BasicPoint<T>& a() const { return a_; }  ///< the proper corner a
  const BasicT1<T>& dx() const { return dx_; }   ///< the extent along x
  const BasicT1<T>& dy() const { return dy_; }   ///< the extent along y
  Sign orientation() const { return o_; }        ///< the orientation of the boundary

  /// The vertex a, b, c or d of the file comment by name (i = 0..3, modulo 4), whatever the
  /// orientation.
  BasicPoint<T> corner(int i) const { return detail::rect_vertex(a_, dx_, dy_, i); }

  /// Vertex i of the boundary traversed with `orientation()` (modulo 4), starting at a:
  /// a, b, c, d when that cycle already turns that way (sign w_a · sign x_Δx · sign y_Δy =
  /// Δ(a, b, d) equals the orientation, or is zero for a flat rectangle), a, d, c, b otherwise.
  BasicPoint<T> vertex(int i) const {
    const int j = ((i % 4) + 4) % 4;
    return corner(natural() == -o_ ? (4 - j) % 4 : j);
  }

  /// Δ(a, b, d) = sign(w_a)·sign(x_Δx)·sign(y_Δy): the orientation of the cycle a, b, c, d.
  Sign natural() const { return sign_of(a_.w()) * sign_of(dx_.x()) * sign_of(dy_.x()); }

 private:
  BasicPoint<T> a_;
  BasicT1<T> dx_, dy_;
  Sign o_;
};

/// Iso-rectangles with `double` coordinates.
using IsoRect = BasicIsoRect<double>;
/// Iso-rectangles with big-integer coordinates.
using ExactIsoRect = BasicIsoRect<Integer>;

/// The iso-rectangle with opposite corners a (proper) and c, oriented as asked. c may be a
/// proper point on a's side (finite extents) or a point at infinity [0, cx, cy] with cx, cy
/// both non-zero (both extents infinite; the corner c of the result is then c itself).
/// Throws `Undefined` when c is on the other side of T² or on an axis direction of Ω.
template <class T>
BasicIsoRect<T> iso_rect(const BasicPoint<T>& a, const BasicPoint<T>& c, Sign orientation = POSITIVE) {
  if (a.w() == 0) throw Undefined("iso_rect(a, c) is undefined when a is at infinity");
  if (c.w() == 0) {
    if (c.x() == 0 || c.y() == 0)
      throw Undefined("iso_rect(a, c) with c at infinity needs c off the axis directions");
    const T s = a.w() > 0 ? T(1) : T(-1);
    return BasicIsoRect<T>(a, BasicT1<T>(T(0), T(s * c.x())), BasicT1<T>(T(0), T(s * c.y())), orientation);
  }
  if ((a.w() > 0) != (c.w() > 0))
    throw Undefined("iso_rect(a, c) is undefined when a and c lie on different sides of T2");
  const auto ax = detail::cartesian_t1(a.w(), a.x()), ay = detail::cartesian_t1(a.w(), a.y());
  const auto cx = detail::cartesian_t1(c.w(), c.x()), cy = detail::cartesian_t1(c.w(), c.y());
  return BasicIsoRect<T>(a, detail::t1_sub(cx, ax), detail::t1_sub(cy, ay), orientation);
}

/// The same rectangle traversed the other way.
template <class T>
BasicIsoRect<T> opposite(const BasicIsoRect<T>& r) {
  return BasicIsoRect<T>(r.a(), r.dx(), r.dy(), -r.orientation());
}

/// "iso_rect([..], [..], [..], [..], +)": the four vertices in boundary order and the orientation.
template <class T>
std::string to_string(const BasicIsoRect<T>& r) {
  return "iso_rect(" + to_string(r.vertex(0)) + ", " + to_string(r.vertex(1)) + ", " + to_string(r.vertex(2)) +
         ", " + to_string(r.vertex(3)) + ", " + to_symbol(r.orientation()) + ")";
}

}  // namespace t2
