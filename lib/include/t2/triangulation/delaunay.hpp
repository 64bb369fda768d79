#pragma once
/// @file delaunay.hpp
/// @brief The Delaunay triangulation of front points of T² by randomized incremental
/// construction: BRIO–Hilbert insertion order, a remembering walk, Lawson flips, exact
/// predicates and a symbolic perturbation that makes the result unique.
///
/// **Algorithm.** Points are inserted in the order of `spatial_order`. Each is located by the
/// walk of triangulation.hpp from the last triangle created, then inserted in its triangle, on
/// its edge, or — outside the hull — in the infinite triangle of a hull edge it sees; then
/// every edge opposite the new point p is tested and flipped while p lies inside the circle of
/// the triangle across (Lawson). For an infinite triangle (a, b, v∞) the "circle" is the line
/// a → b and its inside the open half-plane beyond it (plus the open segment ab): flipping those
/// edges is what adds the other hull edges that p sees (Algorithm 9 of seed 000 with v∞).
///
/// **Degenerate input, the rule.**
///  - *Duplicates* are merged: the point of smallest index is the vertex, the others are listed
///    in `Triangulation::duplicates()` as (dropped, kept) pairs.
///  - *All points collinear* (or fewer than three distinct points): no triangle. The result has
///    dimension() 1 (0 if all points are equal, −1 if there are none), its points, no triangle
///    and no hull edge, and its duplicates.
///  - *Cocircular points* are triangulated as if perturbed (Devillers and Teillaud,
///    "Perturbations for Delaunay and weighted Delaunay 3D triangulations", CGAL's
///    `side_of_oriented_circle(..., perturb = true)`): point s is lifted to (s, |s|² + ε^{r(s)})
///    where r(s) is the rank of s in the *decreasing* lexicographic (x, y) order, so the
///    lexicographically larger a point, the larger its lift's perturbation. When the exact
///    in-circle sign of a, b, c (counter-clockwise) and d is zero, the sign of the perturbed
///    4×4 determinant |x, y, x² + y² + ε_s, 1| is the sign of its first nonzero ε-coefficient in
///    that order. Expanding along the lift column, the coefficient of ε_d is −orient(a, b, c) and
///    that of ε_c, ε_b, ε_a is orient(a, b, d), orient(a, d, c), orient(d, b, c). Going through
///    the points from the largest: if it is d the answer is NEGATIVE (orient(a, b, c) > 0);
///    otherwise the orientation of the other three decides unless it is zero. Two steps always
///    decide: if the coefficients of the two largest points (neither d) both vanished, the two
///    triples without each would be collinear; they share two points, so all four points would be
///    collinear, against orient(a, b, c) > 0. *Consistency:* the perturbed predicate is the exact
///    in-circle sign of one fixed set of lifted points (for every ε small enough), no four of
///    which are coplanar; so Lawson's flips terminate with its unique Delaunay triangulation —
///    the projection of the lower hull of the lifted points — and the walk terminates on it
///    (triangulation.hpp). The perturbation depends on the points only, not on their indices or
///    their order, so the triangle set is the same for every permutation of the input, and it
///    is the one CGAL's `Delaunay_triangulation_2` computes (the tests compare them).
///
/// **T² input.** When some point is not in front (w ≤ 0), `delaunay` builds the dual of the
/// T² Voronoi diagram instead (delaunay_t2.hpp: the planar triangulations of each side, merged
/// along Ω, with the lunes of `in_circle` (incircle.hpp) for faces on both sides). Front
/// input never takes that path, so its result is the planar one above, unchanged.
///
/// **Memory.** The result holds the points (24 bytes a point), the triangles (2n − 2 of them
/// with v∞, Euler's formula for n + 1 vertices, 24 bytes each: 48 a point, reserved once) and
/// the vertex link of triangulation.hpp (4 a point). The
/// construction adds a copy of the points in insertion order (24) and the order itself (4): the
/// walk and the flips then touch memory in order (building on the points in input order instead
/// saves those 28 bytes but is a fifth slower at 10⁶ points). So, at the end of the insertions:
///  - `delaunay(points)`, the caller keeps its vector: 24 + 24 + 4 + 48 + 4 = 104 bytes a point
///    (the peak); then the copy is freed, the link moved to the input indices in place, the
///    order freed and the input copied, and 100 remain.
///  - `delaunay(std::move(points))`, the result takes the caller's vector: the copy in
///    insertion order replaces it and is moved back into the input order in place at the end
///    (`unpermute`, through a buffer of an eighth of the points), after the link has moved
///    through a second array: 24 + 4 + 48 + 4 + 4 = 84 bytes a point at the peak, in about the
///    same time (1 to 6 % more). A caller that needs its points
///    afterwards reads them in `points()` of the result, the same points at the same indices:
///    this is the way to triangulate under 100 bytes a point while keeping the points.
///
/// `t2 bench delaunay --n 1000000 --vs owned,cgal` measures both (the peak resident memory of
/// the process, which adds about 4 MB of code and libraries to these counts).
///
/// **Traits and trace.** `delaunay_with<K>` takes the predicates from a traits type K (orient,
/// in_circle, compare_xy on `t2::Point`); the default `DelaunayTraits` calls the exact
/// `t2::orient`, `t2::in_circle` and `t2::compare_xy`. Its steps go to a hook (t2/trace/hook.hpp)
/// in input indices: the first triangle (`start`), each point inserted before its flips
/// (`insert`), each in-circle test of a finite triangle with its perturbed answer (`in_circle`,
/// `tie` when the exact sign was zero), each flip (`flip`, the two new triangles), each merged
/// duplicate (`duplicate`) and the end (`done`); the reports lend the triangulation and its
/// insertion order. The default `NoTrace` costs nothing (bench/bench_delaunay.cpp). Front input
/// only: the T² assembly of delaunay_t2.hpp is not traced.

#include <algorithm>
#include <cstdint>
#include <string>
#include <span>
#include <vector>

#include "t2/kernel/error.hpp"
#include "t2/kernel/incircle.hpp"
#include "t2/kernel/lexicographic.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/kernel/point.hpp"
#include "t2/trace/hook.hpp"
#include "t2/triangulation/spatial_sort.hpp"
#include "t2/triangulation/triangulation.hpp"

namespace t2 {

/// The default traits of `delaunay_with`: the exact predicates of the library, no trace.
struct DelaunayTraits {
  /// Exact orientation of three points.
  static Sign orient(const Point& p, const Point& q, const Point& r) { return t2::orient(p, q, r); }
  /// Exact oriented in-circle test.
  static Sign in_circle(const Point& a, const Point& b, const Point& c, const Point& d) {
    return t2::in_circle(a, b, c, d);
  }
  /// Exact lexicographic comparison of Cartesian coordinates (the perturbation order); points
  /// with w = 1 compare their doubles directly.
  static Sign compare_xy(const Point& p, const Point& q) {
    if (p.w() == 1 && q.w() == 1) {
      if (p.x() != q.x()) return p.x() < q.x() ? NEGATIVE : POSITIVE;
      return p.y() < q.y() ? NEGATIVE : p.y() > q.y() ? POSITIVE : ZERO;
    }
    return t2::compare_xy(p, q);
  }
};

//> perturbed-in-circle
/// The in-circle sign of d against the counter-clockwise triangle a, b, c under the
/// symbolic perturbation of the file comment: never ZERO for four distinct points.
template <class K>
Sign perturbed_in_circle(const K& k, const Point& a, const Point& b, const Point& c,
                         const Point& d) {
  const Sign s = k.in_circle(a, b, c, d);
  if (s != ZERO) return s;
  const Point* p[4] = {&a, &b, &c, &d};
  std::sort(p, p + 4, [&](const Point* u, const Point* v) {
    return k.compare_xy(*u, *v) == NEGATIVE;
  });
  for (int i = 3; i > 1; --i) {  // from the largest point, whose perturbation dominates
    Sign o = ZERO;
    if (p[i] == &d) return NEGATIVE;
    if (p[i] == &c) o = k.orient(a, b, d);
    if (p[i] == &b) o = k.orient(a, d, c);
    if (p[i] == &a) o = k.orient(d, b, c);
    if (o != ZERO) return o;
  }
  throw Undefined(
      "perturbed_in_circle: four collinear points (a, b, c must turn counter-clockwise)");
}
//< perturbed-in-circle

namespace detail {

/// Is the finite point p in conflict with triangle t, i.e. inside its (perturbed) circle, or for
/// an infinite triangle (a, b, v∞) strictly beyond a → b or inside the segment ab?
template <class K>
bool in_conflict(const K& k, const Triangulation& tr, Triangulation::Index t, const Point& p) {
  const Triangulation::Index v0 = tr.vertex(t, 0), v1 = tr.vertex(t, 1), v2 = tr.vertex(t, 2);
  const int inf = v0 == Triangulation::infinite ? 0 : v1 == Triangulation::infinite ? 1 : v2 == Triangulation::infinite ? 2 : -1;
  if (inf < 0) return perturbed_in_circle(k, tr.point(v0), tr.point(v1), tr.point(v2), p) == POSITIVE;
  const Point& a = tr.point(tr.vertex(t, (inf + 1) % 3));
  const Point& b = tr.point(tr.vertex(t, (inf + 2) % 3));
  const Sign o = k.orient(a, b, p);
  if (o != ZERO) return o == POSITIVE;
  const Sign ap = k.compare_xy(a, p), pb = k.compare_xy(p, b);
  return ap != ZERO && ap == pb;  // strictly between a and b on their line
}

/// The triangulation of T² input (defined in delaunay_t2.hpp, included at the end); with
/// `whole_sphere` the clockwise faces beyond a hull are kept (the Delaunay complex, complex.hpp).
template <class K>
Triangulation delaunay_t2(std::span<const Point> input, const K& kernel, bool whole_sphere = false);

/// Degenerate input: dimension 0 or 1 (no triangle); duplicates found by sorting.
template <class K>
void finish_degenerate(const K& k, Triangulation& tr, std::vector<std::uint32_t>& order, int dimension) {
  const auto& pts = tr.points();
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    const Sign s = k.compare_xy(pts[a], pts[b]);
    return s != ZERO ? s == NEGATIVE : a < b;
  });
  for (std::size_t m = 1, first = 0; m < order.size(); ++m) {
    if (k.compare_xy(pts[order[first]], pts[order[m]]) == ZERO)
      tr.add_duplicate(order[m], order[first]);
    else
      first = m;
  }
  tr.set_dimension(order.empty() ? -1 : dimension);
  tr.finish();
}

/// The points input[order[m]] for every m.
inline std::vector<Point> in_order(std::span<const Point> input, const std::vector<std::uint32_t>& order) {
  std::vector<Point> sorted;
  sorted.reserve(order.size());
  for (std::uint32_t k : order) sorted.push_back(input[k]);
  return sorted;
}

/// The incremental construction on the points of `tr`, which are those of the input in the
/// insertion `order` (vertex m is the m-th inserted point); at the end the input indices are
/// restored by `renumber`: from a copy of `input`, or in place when `input` is null (the
/// construction owns the points).
template <class K, class Tr = NoTrace>
Triangulation incremental(K& kernel, Triangulation tr, std::vector<std::uint32_t> order,
                          const std::span<const Point>* input, Tr&& trace = {}) {
  using Index = Triangulation::Index;
  const auto& pts = tr.points();
  const Index n = static_cast<Index>(order.size());
  auto restore = [&](std::vector<std::uint32_t> o) {
    if (input != nullptr)
      tr.renumber(std::move(o), *input);
    else
      tr.renumber(std::move(o));
  };
  auto degenerate = [&](int dimension) {
    restore(order);
    detail::finish_degenerate(kernel, tr, order, dimension);
    return std::move(tr);
  };
  // The first triangle: the first point, the first other point, the first point off their line.
  Index ib = 1, ic = 0;
  while (ib < n && kernel.compare_xy(pts[0], pts[ib]) == ZERO) ++ib;
  if (ib >= n) return degenerate(0);
  for (ic = ib + 1; ic < n; ++ic)
    if (kernel.orient(pts[0], pts[ib], pts[ic]) != ZERO) break;
  if (ic >= n) return degenerate(1);
  if (kernel.orient(pts[0], pts[ib], pts[ic]) > 0)
    tr.make_triangle(0, ib, ic, n);
  else
    tr.make_triangle(ib, 0, ic, n);
  using trace::Event;
  tell(trace, [&] { return trace::about(Event::start, tr, order, {order[tr.vertex(0, 0)], order[tr.vertex(0, 1)], order[tr.vertex(0, 2)]}); });
  // Then the points skipped above (equal to the first or on the first line), then the rest.
  auto next_point = [&, m = Index(1)]() mutable {
    while (m == ib || m == ic) ++m;
    return m++;
  };
  std::vector<Index> stack;
  std::uint32_t rng = 2463534242u;
  Index last = 0;
  //> delaunay-loop
  for (Index m = 3; m < n; ++m) {
    const Index p = next_point();
    const Triangulation::Location loc = tr.locate(
        pts[p], last,
        [&](const Point& u, const Point& v, const Point& w) {
          return kernel.orient(u, v, w);
        },
        rng);
    if (loc.kind == Triangulation::Location::vertex) {
      // the kept point is the one of smaller input index
      const Index v = tr.vertex(loc.t, loc.i);
      if (order[p] < order[v]) tr.rename_vertex(loc.t, v, p);
      tr.add_duplicate(order[p] < order[v] ? v : p, order[p] < order[v] ? p : v);
      tell(trace, [&] {
        const auto [kept, gone] = std::minmax(order[p], order[v]);
        return trace::about(Event::duplicate, tr, order, {gone, kept});
      });
      continue;
    }
    const Index first_new = static_cast<Index>(tr.size());
    if (loc.kind == Triangulation::Location::face) {
      tr.insert_in_face(loc.t, p);
      stack = {3 * loc.t, 3 * first_new, 3 * (first_new + 1)};
    } else {
      const Index u = tr.neighbor(loc.t, loc.i);
      tr.insert_on_edge(loc.t, loc.i, p);
      stack = {3 * loc.t, 3 * u, 3 * first_new, 3 * (first_new + 1)};
    }
    tell(trace, [&] { return trace::about(Event::insert, tr, order, {order[p]}); });
    last = loc.t;
    // Lawson: every edge opposite p, p is vertex 0 of its triangle
    while (!stack.empty()) {
      const Index t = stack.back() / 3;
      stack.pop_back();
      const Index u = tr.neighbor(t, 0);
      const bool conflict = detail::in_conflict(kernel, tr, u, pts[p]);
      // a finite triangle's circle: what it was asked, what it said
      if constexpr (trace::traced<Tr>) {
        if (!tr.is_infinite(u)) {
          const Index v0 = tr.vertex(u, 0), v1 = tr.vertex(u, 1), v2 = tr.vertex(u, 2);
          trace::Report r = trace::about(Event::in_circle, tr, order,
                                         {order[v0], order[v1], order[v2], order[p]});
          r.sign = conflict ? POSITIVE : NEGATIVE;
          const Sign s = kernel.in_circle(tr.point(v0), tr.point(v1), tr.point(v2), pts[p]);
          r.tie = s == ZERO;
          trace(r);
        }
      }
      if (!conflict) continue;
      tr.flip(t, 0);
      tell(trace, [&] { return trace::about(Event::flip, tr, order, {order[p]}, {t, u}); });
      stack.push_back(3 * t);
      stack.push_back(3 * u);
    }
  }
  //< delaunay-loop
  tell(trace, [&] { return trace::about(Event::done, tr, order, {}); });
  restore(std::move(order));
  tr.finish();
  return tr;
}

}  // namespace detail

//> delaunay
/// The Delaunay triangulation of points of T² with the predicates of traits K; see the file
/// comment for the algorithm and the rule on degenerate input, delaunay_t2.hpp for input that is
/// not all in front (which `trace` does not hear). Throws `Undefined` for points on Ω around an empty side (delaunay_t2.hpp),
/// `BadInput` for more than 715 827 882 points (32-bit half-edge indices).
template <class K = DelaunayTraits, class Tr = NoTrace>
Triangulation delaunay_with(std::span<const Point> input, K kernel = {}, Tr&& trace = {}) {
  if (std::any_of(input.begin(), input.end(), [](const Point& p) { return p.w() <= 0; }))
    return detail::delaunay_t2(input, kernel);
  if (input.size() > Triangulation::none / 6)  // half-edges 3t + i of 2n triangles fit 32 bits
    throw BadInput("delaunay: more than " + std::to_string(Triangulation::none / 6) + " points");
  // The triangulation is built on a copy of the points in insertion order (vertex m is the m-th
  // inserted point), so that the walk and the flips touch memory in order; `renumber` restores
  // the input indices and points at the end.
  std::vector<std::uint32_t> order = spatial_order(input);
  std::vector<Point> sorted = detail::in_order(input, order);
  return detail::incremental(kernel, Triangulation(std::move(sorted)), std::move(order), &input, trace);
}

/// The same on a vector of points that the result takes over: `points()` of the result holds
/// them afterwards, in the same order. The construction keeps one copy of the points instead of
/// two: 84 bytes a point at the peak against 104 (see the file comment), in about the same time.
template <class K = DelaunayTraits>
Triangulation delaunay_with(std::vector<Point>&& points, K kernel = {}) {
  const std::span<const Point> input(points);
  if (std::any_of(input.begin(), input.end(), [](const Point& p) { return p.w() <= 0; }) ||
      input.size() > Triangulation::none / 6)
    return delaunay_with(input, kernel);  // the T² assembly copies, or the size error
  std::vector<std::uint32_t> order = spatial_order(input);
  std::vector<Point> sorted = detail::in_order(input, order);
  std::vector<Point>().swap(points);
  return detail::incremental(kernel, Triangulation(std::move(sorted)), std::move(order), nullptr);
}

/// The Delaunay triangulation of front points with the exact predicates of the library (the
/// points are copied into the triangulation).
inline Triangulation delaunay(std::span<const Point> points) { return delaunay_with(points); }
/// The same for a vector of points.
inline Triangulation delaunay(const std::vector<Point>& points) { return delaunay_with(std::span<const Point>(points)); }
/// The same for a vector of points that the result takes over (read them back in `points()`):
/// one copy of the points in memory instead of two.
inline Triangulation delaunay(std::vector<Point>&& points) { return delaunay_with(std::move(points)); }
//< delaunay

// The default instantiations are compiled once, in lib/src/triangulation/delaunay.cpp.
#ifndef T2_FILTER_STATS  // a program that counts the exact stages compiles its own copy
/// @cond INSTANTIATIONS
extern template Triangulation delaunay_with<DelaunayTraits, NoTrace>(std::span<const Point>, DelaunayTraits,
                                                                      NoTrace&&);
extern template Triangulation delaunay_with<DelaunayTraits>(std::vector<Point>&&, DelaunayTraits);
/// @endcond
#endif

}  // namespace t2

#include "t2/triangulation/delaunay_t2.hpp"  // IWYU pragma: export
