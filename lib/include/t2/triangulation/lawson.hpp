#pragma once
/// @file lawson.hpp
/// @brief Lawson's flip algorithm, the teaching baseline of chapter 10: take any triangulation
/// and flip illegal edges until none is left. The result is the Delaunay triangulation of
/// delaunay.hpp (the same triangle set, with the same symbolic perturbation for cocircular
/// points).
///
/// **Legal edges.** An edge shared by two finite triangles (a, b, c) and (c, b, d) — d opposite
/// the edge bc — is *legal* when d is not inside the circle through a, b, c under the perturbed
/// in-circle test of delaunay.hpp (`perturbed_in_circle(a, b, c, d)` is NEGATIVE; it is never
/// ZERO for distinct points). Hull edges (next to an infinite triangle) and the edges at v∞ are
/// always legal: every triangulation of the points has the same hull.
///
/// **Why flipping is possible.** If bc is illegal, then d lies in the open disc of a, b, c and on
/// the other side of bc from a, so the quadrilateral a, b, d, c is strictly convex (a point of the
/// disc beyond the chord bc sees a and the chord in an arc shorter than a half circle) and the
/// flip of `Triangulation::flip` applies; afterwards ad is legal.
///
/// **Why it stops.** Lift every point s to ŝ = (s, |s|² + ε_s) (delaunay.hpp). A triangulation
/// lifts to a piecewise linear surface over the hull. The four lifted points of an illegal edge
/// form a tetrahedron whose edge b̂ĉ lies above âd̂ (d inside the circle means d̂ lies below the
/// plane of â, b̂, ĉ); the flip replaces the two upper faces of that tetrahedron by the two lower
/// ones, so the surface goes down strictly over the quadrilateral and nowhere up. A surface
/// never comes back after going strictly down, so no triangulation repeats; there are finitely
/// many triangulations, so the algorithm stops, after at most C(n, 2) flips in fact (an edge
/// flipped away lies above the new surface and can never come back). When no illegal edge is
/// left, every edge is locally Delaunay, hence (delaunay.hpp) the surface is the lower hull of
/// the lifted points: the Delaunay triangulation.
///
/// **Running time.** O(n log n) for the sweep of triangulate.hpp, then Θ(n²) flips in the worst
/// case (points on a parabola in the wrong order), and in practice a few flips per point.

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "t2/kernel/error.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "t2/triangulation/triangulate.hpp"
#include "t2/triangulation/triangulation.hpp"

namespace t2 {

//> is-legal
/// True when the edge opposite vertex i of triangle t is legal (see the file comment): a
/// hull edge, an edge at v∞, or an edge whose far vertex d is outside the (perturbed)
/// circle of t.
inline bool is_legal(const Triangulation& tr, Triangulation::Index t, int i) {
  const Triangulation::Index e = tr.twin(t, i), u = e / 3;
  if (tr.is_infinite(t) || tr.is_infinite(u)) return true;
  const Point& d = tr.point(tr.vertex(u, static_cast<int>(e % 3)));
  return perturbed_in_circle(DelaunayTraits{}, tr.point(tr.vertex(t, 0)),
                             tr.point(tr.vertex(t, 1)), tr.point(tr.vertex(t, 2)),
                             d) == NEGATIVE;
}
//< is-legal

//> lawson
/// Lawson's algorithm: flips illegal edges of `tr` (dimension 2) until every edge is
/// legal; returns the number of flips. A stack holds half-edges that may be illegal: at
/// first all of them, then, after each flip, the four outer edges of its quadrilateral
/// (the only edges whose far vertex changed).
inline std::size_t flip_to_delaunay(Triangulation& tr) {
  using Index = Triangulation::Index;
  if (tr.dimension() < 2) return 0;
  std::vector<Index> stack;
  for (Index e = 0; e < 3 * tr.size(); ++e)
    if (e < tr.twin(e / 3, static_cast<int>(e % 3))) stack.push_back(e);
  std::size_t flips = 0;
  while (!stack.empty()) {
    const Index t = stack.back() / 3;
    const int i = static_cast<int>(stack.back() % 3);
    stack.pop_back();
    if (is_legal(tr, t, i)) continue;
    const Index u = tr.neighbor(t, i);
    tr.flip(t, i);  // t = (p, q, d) and u = (p, d, r); the new edge p–d is legal
    ++flips;
    stack.insert(stack.end(), {3 * t, 3 * t + 2, 3 * u, 3 * u + 1});
  }
  return flips;
}
//< lawson

/// The Delaunay triangulation of front points by Lawson's algorithm: `triangulate`, then
/// `flip_to_delaunay`. The same triangles as `delaunay(points)`, in O(n²) worst-case time.
/// Throws `Undefined` for a point not on the front side (the flips assume a planar hull).
inline Triangulation delaunay_by_flips(std::span<const Point> points) {
  for (std::size_t k = 0; k < points.size(); ++k)
    if (points[k].w() <= 0)
      throw Undefined("delaunay_by_flips: point " + std::to_string(k) + " = " + to_string(points[k]) +
                      " is not on the front side (w > 0); Lawson's flips take front points only");
  Triangulation tr = triangulate(points);
  flip_to_delaunay(tr);
  return tr;
}
/// The same for a vector of points.
inline Triangulation delaunay_by_flips(const std::vector<Point>& points) {
  return delaunay_by_flips(std::span<const Point>(points));
}

}  // namespace t2
