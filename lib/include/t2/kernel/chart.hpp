#pragma once
/// @file chart.hpp
/// @brief Charts of T²: a projective map, given by two points, that sends an open hemisphere
/// to the front side, so that a planar algorithm (a sweep, a sort "left to right") runs on any
/// points of T² that lie in an open hemisphere; and the exact order of a chart.
///
/// **Chart.** A planar algorithm needs an order "left to right" and orientation tests.
/// Orientation is Δ on the original points. For the order, a *chart* is a pair of points X∞,
/// Y∞ of T² with Δ(X∞, Y∞, p) > 0 for every input point p: the projective map M with
/// M X∞ = [0,1,0], M Y∞ = [0,0,1] (and det M > 0) sends every input point to the front side, keeps
/// every Δ, and in its image x(p) < x(q) ⇔ Δ(p, q, Y∞) > 0 and y(p) < y(q) ⇔ Δ(q, p, X∞) > 0. So
/// the algorithm runs on the original points, never on rounded images. For front-only input the
/// chart is X∞ = [0,1,0], Y∞ = [0,0,1] (then Δ(X∞, Y∞, p) = sign w, and the order is the usual
/// (x, y) order). A chart point may be *symbolic*, z₀ + εz₁ + ε²z₂ with ε > 0 infinitesimal:
/// Δ(p, q, z) is then the first nonzero of Δ(p, q, z₀), Δ(p, q, z₁), Δ(p, q, z₂) (Δ is linear in
/// z). Two symbolic charts serve T²: `lex_chart()` for lexicographically positive points and
/// `edge_chart()` built from one edge of a hull.
///
/// The order is a template on traits `K` with `K::orient(p, q, r)` (the hull's `HullTraits`, or
/// a counting or tracing set), so that every Δ it evaluates goes through the caller's traits.

#include <array>
#include <cstddef>

#include "t2/kernel/orient.hpp"
#include "t2/kernel/point.hpp"

namespace t2 {

/// A chart point z₀ + εz₁ + ε²z₂ (terms past `count` unused; zero terms are left out).
struct ChartPoint {
  std::array<Point, 3> z;  ///< the terms, by increasing power of ε
  int count;               ///< how many terms are used (1 to 3)
};

/// Δ(p, q, z) for a chart point z: the first nonzero term.
template <class K>
Sign orient_to(const Point& p, const Point& q, const ChartPoint& z) {
  for (int i = 0; i < z.count; ++i)
    if (const Sign s = K::orient(p, q, z.z[static_cast<std::size_t>(i)]); s != ZERO) return s;
  return ZERO;
}

/// A chart: X∞ and Y∞ with Δ(X∞, Y∞, p) > 0 for every point it is used on (file comment).
struct Chart {
  ChartPoint x_inf;    ///< X∞, the point at infinity of the image's x axis
  ChartPoint y_inf;    ///< Y∞, the point at infinity of the image's y axis
  bool front = false;  ///< the plain chart of front points: X∞ = [0,1,0], Y∞ = [0,0,1]
};

/// The chart of front points (w > 0): the usual (x, y) order.
inline Chart front_chart() {
  const Point X(0, 1, 0), Y(0, 0, 1);
  return {{{X, X, X}, 1}, {{Y, Y, Y}, 1}, true};
}

/// The chart of lexicographically positive points ([w, x, y] > 0 in the order w, x, y: the
/// front, and the half of Ω with x > 0 or x = 0 < y): X∞ = [−ε, 1, 0], Y∞ = [−ε², 0, 1], for
/// which Δ(X∞, Y∞, p) = w + εx + ε²y > 0.
inline Chart lex_chart() {
  const Point X(0, 1, 0), Y(0, 0, 1), O(-1, 0, 0);
  return {{{X, O, O}, 2}, {{Y, O, O}, 2}, false};
}

/// The chart of a set whose hull has the edge v0 → v1 (all points on its left or on the
/// segment v0 v1) and c a point strictly left of v0 → v1: X∞ = v0 − εc, Y∞ = v1 − εc. Then
/// Δ(X∞, Y∞, p) = Δ(v0, v1, p) + ε(α + β)Δ(v0, v1, c) > 0, where p = αv0 + βv1 on the segment.
inline Chart edge_chart(const Point& v0, const Point& v1, const Point& c) {
  const Point nc = antipode(c);
  return {{{v0, nc, nc}, 2}, {{v1, nc, nc}, 2}, false};
}

/// The order of a chart: lexicographic (x, y) in the image; `compare` is ZERO only for equal
/// points of T².
template <class K>
struct ChartOrder {
  const Chart& chart;  ///< the chart

  /// NEGATIVE when p comes before q, ZERO when p = q, POSITIVE after.
  Sign compare(const Point& p, const Point& q) const {
    //> hull-chart-order
    // The common case: plain comparisons, exact.
    if (chart.front && p.w() == 1 && q.w() == 1) {
      if (p.x() != q.x()) return p.x() < q.x() ? NEGATIVE : POSITIVE;
      return p.y() < q.y() ? NEGATIVE : (p.y() > q.y() ? POSITIVE : ZERO);
    }
    if (const Sign s = orient_to<K>(p, q, chart.y_inf); s != ZERO) return -s;
    return orient_to<K>(p, q, chart.x_inf);
    //< hull-chart-order
  }
  /// p comes strictly before q.
  bool less(const Point& p, const Point& q) const { return compare(p, q) < 0; }
  /// For p, q on one ray from a point o (o ≠ p, q): q lies farther from o than p. Along a line
  /// the chart order is monotone, so "farther" is "further in the order, away from o".
  bool farther(const Point& o, const Point& p, const Point& q) const {
    return less(o, p) ? less(p, q) : less(q, p);
  }
};

}  // namespace t2
