#pragma once
/// @file lexicographic.hpp
/// @brief Orders of points: the lexicographic wxy order (seed 000, §4.3.3) and the cyclic order
/// of the points of a line.
///
/// **Normalized coordinates.** Every point has one representative with a fixed scale: a proper
/// point [w, x, y] is [w/|w|, x/|w|, y/|w|] = [±1, x/|w|, y/|w|], a point of Ω is
/// [0, x/m, y/m] with m = max(|x|, |y|) (the scale `t2::normalized` uses). The lexicographic
/// order compares those triples, w first: back points (w = −1) < points of Ω (w = 0) < front
/// points (w = +1). Mind that for a back point x/|w| = −X, minus its Cartesian coordinate X =
/// x/w: among back points the seed's order runs against their drawn positions.
/// All comparisons are exact, by cross-multiplication with the positive scales, no division.
///
/// **Order along a line.** A line of T² is a circle (a great circle of the sphere model), so
/// its points have a cyclic order, the sense in which the oriented line runs. To sort them the
/// circle is cut at one point, the *start*: for a line l other than Ω, the start is the point
/// at infinity behind l, ¬D, where D is the point at infinity l runs towards. From there the
/// order is: ¬D, then the front points in the direction of l (the usual order along a line),
/// then D, then the back points, which continue the turn of the circle. For l = ±Ω (no front
/// or back points) the start is [0, 1, 0] and the order is the turn of Ω in l's sense
/// (counter-clockwise for ⟨1, 0, 0⟩, as `compare_angle` orders directions).

#include <algorithm>
#include <type_traits>
#include <vector>

#include "t2/kernel/detail/distance_double.hpp"
#include "t2/kernel/error.hpp"
#include "t2/kernel/filter.hpp"
#include "t2/kernel/line.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/sign.hpp"

namespace t2 {

namespace detail {

template <class T>
T abs_of(const T& v) {
  return v < 0 ? T(-v) : v;
}

/// The positive scale of the normalized coordinates: |w|, or max(|x|, |y|) on Ω.
template <class T>
T normal_scale(const BasicPoint<T>& p) {
  if (p.w() != 0) return abs_of(p.w());
  const T ax = abs_of(p.x()), ay = abs_of(p.y());
  return ax < ay ? ay : ax;
}

/// sign(u/s - v/t) for positive s, t: on doubles the fast path of distance_double.hpp.
template <class T>
Sign compare_ratios(const T& u, const T& s, const T& v, const T& t) {
  if constexpr (std::is_same_v<T, double>) {
    return compare_ratios_double(u, s, v, t);
  } else {
    return sign_of_poly([](const auto& a, const auto& b, const auto& c, const auto& d) { return a * d - c * b; }, u,
                        s, v, t);
  }
}

}  // namespace detail

/// Compares the normalized x coordinates of p and q (see the file comment). Exact.
template <class T>
Sign compare_x(const BasicPoint<T>& p, const BasicPoint<T>& q) {
  return detail::compare_ratios(p.x(), detail::normal_scale(p), q.x(), detail::normal_scale(q));
}

/// Compares the normalized y coordinates of p and q (see the file comment). Exact.
template <class T>
Sign compare_y(const BasicPoint<T>& p, const BasicPoint<T>& q) {
  return detail::compare_ratios(p.y(), detail::normal_scale(p), q.y(), detail::normal_scale(q));
}

namespace detail {
/// compare_xy on normalized coordinates, out of line (the Cartesian case is inline).
template <class T>
[[gnu::noinline]] Sign compare_xy_general(const BasicPoint<T>& p, const BasicPoint<T>& q) {
  const Sign s = compare_x(p, q);
  return s != ZERO ? s : compare_y(p, q);
}
}  // namespace detail

/// Compares normalized (x, y) lexicographically, ignoring the side: for two front points this
/// is CGAL's `compare_xy`. Exact.
template <class T>
Sign compare_xy(const BasicPoint<T>& p, const BasicPoint<T>& q) {
  if constexpr (std::is_same_v<T, double>) {
    if (detail::all_one(p.w(), q.w())) {  // Cartesian: comparisons of doubles are exact
      const int sx = (p.x() > q.x()) - (p.x() < q.x());
      if (sx != 0) [[likely]] return static_cast<Sign>(sx);
      return static_cast<Sign>((p.y() > q.y()) - (p.y() < q.y()));
    }
  }
  return detail::compare_xy_general(p, q);
}

/// The lexicographic wxy order of §4.3.3 on normalized coordinates: NEGATIVE when p < q, so
/// back < Ω < front. ZERO exactly when p = q (antipodes differ). Exact, no division.
template <class T>
Sign compare_lexicographic(const BasicPoint<T>& p, const BasicPoint<T>& q) {
  const int sw = static_cast<int>(sign_of(p.w())) - static_cast<int>(sign_of(q.w()));
  if (sw != 0) return sw < 0 ? NEGATIVE : POSITIVE;
  return compare_xy(p, q);
}

/// True when p comes strictly before q in the wxy order (a strict weak ordering for std::sort).
template <class T>
bool less_wxy(const BasicPoint<T>& p, const BasicPoint<T>& q) {
  return compare_lexicographic(p, q) == NEGATIVE;
}

/// True when p comes strictly before q in the normalized xy order (ignores the side).
template <class T>
bool less_xy(const BasicPoint<T>& p, const BasicPoint<T>& q) {
  return compare_xy(p, q) == NEGATIVE;
}

namespace detail {

/// Position class of a point of l along the cut circle: 0 start, 1 first open half, 2 the point
/// opposite the start, 3 second open half.
template <class T>
int along_rank(const BasicLine<T>& l, const BasicPoint<T>& p) {
  if (side(l, p) != ZERO) throw Undefined("compare_along_line(l, p, q) orders only points that lie on l");
  if (l.X() == 0 && l.Y() == 0) {
    // l = +-Omega: start [0,1,0], halves split by the line y = 0 (signed by l's sense).
    const Sign sy = sign_of(l.W()) * sign_of(p.y());
    if (sy == ZERO) return p.x() > 0 ? 0 : 2;
    return sy == POSITIVE ? 1 : 3;
  }
  if (p.w() > 0) return 1;
  if (p.w() < 0) return 3;
  // On Omega: D = [0, Y, -X] is where l runs to; p is D or its antipode (the start).
  const Sign d = sign_of_poly([](const auto& q, const auto& m) { return q.x * m.Y - q.y * m.X; }, p, l);
  return d == POSITIVE ? 2 : 0;
}

}  // namespace detail

/// The order of two points of the line l along l, cut at its start (see the file comment):
/// NEGATIVE when p comes first, ZERO when p = q. Throws `Undefined` when p or q is not on l.
/// Exact.
template <class T>
Sign compare_along_line(const BasicLine<T>& l, const BasicPoint<T>& p, const BasicPoint<T>& q) {
  const int rp = detail::along_rank(l, p), rq = detail::along_rank(l, q);
  if (rp != rq) return rp < rq ? NEGATIVE : POSITIVE;
  if (rp == 0 || rp == 2) return ZERO;  // a single point in each of these classes
  // Both in the same open half circle: q follows p iff (p x q) . n > 0, n = (W, X, Y).
  return -orient(p, q, BasicPoint<T>(l.W(), l.X(), l.Y()));  // the normal of l as a triple
}

/// The points of l sorted along l, cut at its start (see the file comment); equal points keep
/// their input order. Throws `Undefined` when a point is not on l.
template <class T>
std::vector<BasicPoint<T>> sort_along(const BasicLine<T>& l, std::vector<BasicPoint<T>> points) {
  for (const auto& p : points) (void)detail::along_rank(l, p);  // reject points off the line first
  std::stable_sort(points.begin(), points.end(), [&l](const BasicPoint<T>& p, const BasicPoint<T>& q) {
    return compare_along_line(l, p, q) == NEGATIVE;
  });
  return points;
}

}  // namespace t2
