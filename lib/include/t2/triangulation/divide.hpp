#pragma once
/// @file divide.hpp
/// @brief The Delaunay triangulation of front points by Guibas and Stolfi's divide and conquer
/// on the quad-edge (quadedge.hpp; "Primitives for the manipulation of general subdivisions
/// and the computation of Voronoi diagrams", ACM TOG 4(2), 1985, §6; seed 003, §4.3.3.1).
///
/// **Algorithm.** Sort the points lexicographically by (x, y) and merge equal ones. Split the
/// sorted sequence in two halves, triangulate each recursively (two points: one edge; three:
/// a triangle or, collinear, two edges), and merge: find the lower common tangent of the two
/// hulls (`basel`, from the right half to the left one), then climb. At every step the next
/// Delaunay triangle on basel has its third vertex among the neighbours of basel's ends: the
/// left candidate is the first edge counter-clockwise from basel at its left end whose circle
/// with basel holds no next neighbour (edges whose circle does are not Delaunay any more and
/// are deleted), the right candidate likewise clockwise at the right end; of the two, the one
/// whose circle does not hold the other wins, its edge to the other end of basel is added and
/// becomes the new basel. No candidate above basel: basel is the upper common tangent, done.
///
/// **Running time.** The sort is O(n log n). A merge of halves of sizes a and b costs
/// O(a + b): every step adds one edge (a cross edge, at most a + b − 1 of them, the merged
/// triangulation being planar), every deletion removes an edge of a half (at most 3(a + b)
/// of them), and the tangent search walks each hull once. So T(n) = 2T(n/2) + O(n) =
/// O(n log n), in the worst case, not only in expectation.
///
/// **Exactness and ties.** Orientations are the kernel's exact `orient`; the in-circle test is
/// `perturbed_in_circle` of delaunay.hpp, always called with a counter-clockwise first triple
/// (the valid candidates lie strictly to the right of basel, i.e. above it). Cocircular points
/// are thus decided by the same symbolic perturbation as the incremental and flip algorithms,
/// and the merge computes the lower hull of the same perturbed lifted points: the three
/// algorithms give the same triangle set (the tests check it). Duplicates are merged as in
/// delaunay.hpp (the smallest index is the vertex, the others listed in
/// `Triangulation::duplicates()`); all-collinear input has no triangle (dimension 1).
///
/// **Memory.** The quad-edge: 24 bytes an edge, about 3 edges a point (72); during the
/// recursion also the sorted distinct points (24) and their input indices (4). The sorted
/// points are freed before the conversion, whose slot table (24) and triangle vertices (24)
/// then join the quad-edge: with the caller's points (24) the peak is about 148 bytes a point.
///
/// **Output.** The quad-edge is converted to the flat triangle arrays of triangulation.hpp: one
/// triangle per inner face (a 3-cycle of `lnext`) and one infinite triangle per edge of the
/// outer face. Front points only: a point with w ≤ 0 throws `Undefined` (the T² construction is
/// incremental, delaunay_t2.hpp).

#include <span>
#include <string>
#include <utility>
#include <vector>

#include "t2/kernel/error.hpp"
#include "t2/kernel/point.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "t2/triangulation/quadedge.hpp"
#include "t2/triangulation/triangulate.hpp"
#include "t2/triangulation/triangulation.hpp"

namespace t2 {

namespace detail {

/// The recursion of the divide and conquer on the sorted distinct points `p` (vertex v is
/// p[v]), building into the quad-edge `q`.
template <class K>
class DivideAndConquer {
 public:
  using Edge = QuadEdge::Edge;
  using Vertex = QuadEdge::Vertex;

  /// The algorithm's state: the kernel, the points and the subdivision to fill.
  DivideAndConquer(const K& kernel, const std::vector<Point>& points, QuadEdge& quad)
      : k_(kernel), p_(points), q_(quad) {}

  /// Triangulates the points lo..hi−1 (at least two); returns the counter-clockwise hull edge
  /// out of the leftmost point and the clockwise hull edge out of the rightmost one.
  std::pair<Edge, Edge> build(Vertex lo, Vertex hi) {
    if (hi - lo == 2) {
      const Edge a = q_.make_edge(lo, lo + 1);
      return {a, QuadEdge::sym(a)};
    }
    if (hi - lo == 3) {
      const Edge a = q_.make_edge(lo, lo + 1), b = q_.make_edge(lo + 1, lo + 2);
      q_.splice(QuadEdge::sym(a), b);
      const Sign o = k_.orient(p_[lo], p_[lo + 1], p_[lo + 2]);
      if (o == POSITIVE) {
        q_.connect(b, a);
        return {a, QuadEdge::sym(b)};
      }
      if (o == NEGATIVE) {
        const Edge c = q_.connect(b, a);
        return {QuadEdge::sym(c), c};
      }
      return {a, QuadEdge::sym(b)};  // collinear: a path of two edges
    }
    const Vertex mid = lo + (hi - lo) / 2;
    auto [ldo, ldi] = build(lo, mid);
    auto [rdi, rdo] = build(mid, hi);
    return merge(ldo, ldi, rdi, rdo);
  }

 private:
  using Q = QuadEdge;
  // v strictly to the right of e (GS's RightOf), strictly to its left.
  bool right_of(Vertex v, Edge e) const {
    return k_.orient(p_[v], p_[q_.dest(e)], p_[q_.org(e)]) == POSITIVE;
  }
  bool left_of(Vertex v, Edge e) const {
    return k_.orient(p_[v], p_[q_.org(e)], p_[q_.dest(e)]) == POSITIVE;
  }
  // d strictly inside the circle of the counter-clockwise a, b, c (perturbed); a point of the
  // triangle itself is not inside (it comes up when an end of basel has no other neighbour).
  bool in_circle(Vertex a, Vertex b, Vertex c, Vertex d) const {
    if (d == a || d == b || d == c) return false;
    return perturbed_in_circle(k_, p_[a], p_[b], p_[c], p_[d]) == POSITIVE;
  }

  //> divide-merge
  std::pair<Edge, Edge> merge(Edge ldo, Edge ldi, Edge rdi, Edge rdo) {
    for (;;) {  // the lower common tangent: walk down both hulls
      if (left_of(q_.org(rdi), ldi)) ldi = q_.lnext(ldi);
      else if (right_of(q_.org(ldi), rdi)) rdi = q_.rprev(rdi);
      else break;
    }
    Edge basel = q_.connect(Q::sym(rdi), ldi);  // from the right half to the left one
    if (q_.org(ldi) == q_.org(ldo)) ldo = Q::sym(basel);
    if (q_.org(rdi) == q_.org(rdo)) rdo = basel;
    auto valid = [&](Edge e) { return right_of(q_.dest(e), basel); };  // above basel
    for (;;) {
      const Vertex l = q_.dest(basel), r = q_.org(basel);
      Edge lc = q_.onext(Q::sym(basel));  // the left candidate, counter-clockwise at l
      bool lv = valid(lc);
      while (lv && in_circle(l, r, q_.dest(lc), q_.dest(q_.onext(lc)))) {
        const Edge t = q_.onext(lc);
        q_.delete_edge(lc);
        lc = t;
        lv = valid(lc);
      }
      Edge rc = q_.oprev(basel);  // the right candidate, clockwise at r
      bool rv = valid(rc);
      while (rv && in_circle(l, r, q_.dest(rc), q_.dest(q_.oprev(rc)))) {
        const Edge t = q_.oprev(rc);
        q_.delete_edge(rc);
        rc = t;
        rv = valid(rc);
      }
      if (!lv && !rv) break;  // basel is the upper common tangent
      if (!lv || (rv && in_circle(q_.dest(lc), l, r, q_.dest(rc))))
        basel = q_.connect(rc, Q::sym(basel));  // the right candidate wins
      else
        basel = q_.connect(Q::sym(basel), Q::sym(lc));
    }
    return {ldo, rdo};
  }
  //< divide-merge

  const K& k_;
  const std::vector<Point>& p_;
  QuadEdge& q_;
};

/// The flat triangle arrays of the triangulated subdivision `q` whose outer face is on the
/// left of `outer`: an infinite triangle (org, dest, v∞) per outer edge, then one triangle per
/// inner face; moves them into `tr` (q's vertices are its vertex indices; `vertices` of them).
/// Frees q.
inline void assign_from_quadedge(QuadEdge& q, QuadEdge::Edge outer, std::size_t vertices, Triangulation& tr) {
  using Index = Triangulation::Index;
  using Edge = QuadEdge::Edge;
  constexpr Index none = Triangulation::none;
  // slot[e / 2]: the half-edge 3t + i of the primal quarter-edge e in the flat arrays.
  std::vector<Index> slot(2 * q.quads(), none), v, n;
  v.reserve(3 * (2 * vertices - 2));  // 2(V + 1) − 4 triangles with v∞
  Index h = 0;  // the outer face's length
  for (Edge e = outer; h == 0 || e != outer; e = q.lnext(e)) slot[e >> 1] = 3 * h++ + 2;
  n.resize(3 * h);
  for (Index j = 0; j < h; ++j) {
    n[3 * j] = 3 * ((j + 1) % h) + 1;      // across (dest, v∞): the next infinite triangle
    n[3 * j + 1] = 3 * ((j + h - 1) % h);  // across (v∞, org): the previous one
  }
  for (Edge e = outer, j = 0; j < h; e = q.lnext(e), ++j)
    v.insert(v.end(), {q.org(e), q.dest(e), Triangulation::infinite});
  for (Edge e = 0; e < 4 * q.quads(); e += 2) {
    if (q.is_deleted(e) || slot[e >> 1] != none) continue;
    const Edge e1 = q.lnext(e), e2 = q.lnext(e1);
    const Index t = static_cast<Index>(v.size() / 3);
    v.insert(v.end(), {q.org(e), q.org(e1), q.org(e2)});
    slot[e >> 1] = 3 * t + 2;  // e = v0 → v1 is opposite v2, and so on
    slot[e1 >> 1] = 3 * t;
    slot[e2 >> 1] = 3 * t + 1;
  }
  q = QuadEdge();  // the slots are all the twins need
  n.resize(v.size());
  for (std::size_t k = 0; k < slot.size(); ++k)
    if (slot[k] != none) n[slot[k]] = slot[k ^ 1];
  tr.assign(std::move(v), std::move(n));
}

}  // namespace detail

//> divide
/// The Delaunay triangulation of front points (w > 0) by Guibas and Stolfi's divide and
/// conquer with the predicates of traits K (see the file comment): the same triangles, hull
/// and duplicates as `delaunay_with<K>`. Throws `Undefined` for a point with w ≤ 0,
/// `BadInput` for more than 715 827 882 points.
template <class K = DelaunayTraits>
Triangulation delaunay_divide_with(std::span<const Point> input, K kernel = {}) {
  using Index = Triangulation::Index;
  for (std::size_t k = 0; k < input.size(); ++k)
    if (input[k].w() <= 0)
      throw Undefined("delaunay (divide and conquer): point " + std::to_string(k) + " = " +
                      to_string(input[k]) + " is not on the front side (w > 0); use the "
                      "incremental algorithm for T2 input");
  if (input.size() > Triangulation::none / 6)
    throw BadInput("delaunay: more than " + std::to_string(Triangulation::none / 6) + " points");
  Triangulation dups;  // sorted_distinct records the duplicates here
  std::vector<Index> u = detail::sorted_distinct(input, dups);
  std::vector<Point> sorted = detail::in_order(input, u);
  std::size_t c = 2;  // the first point off the line of the first two
  while (c < u.size() && kernel.orient(sorted[0], sorted[1], sorted[c]) == ZERO) ++c;
  Triangulation tr;  // its points come with `renumber`, once the quad-edge is freed
  if (c < u.size()) {
    QuadEdge q(3 * u.size());
    detail::DivideAndConquer<K> dc(kernel, sorted, q);
    const QuadEdge::Edge le = dc.build(0, static_cast<Index>(u.size())).first;
    std::vector<Point>().swap(sorted);  // not needed by the conversion: the peak is lower
    detail::assign_from_quadedge(q, QuadEdge::sym(le), u.size(), tr);  // the hull is on le's left
  } else {
    tr.set_dimension(u.empty() ? -1 : u.size() == 1 ? 0 : 1);
  }
  tr.renumber(std::move(u), input);
  for (auto [d, k] : dups.duplicates()) tr.add_duplicate(d, k);
  tr.finish();
  return tr;
}
//< divide

/// The Delaunay triangulation of front points by divide and conquer, exact predicates.
inline Triangulation delaunay_divide(std::span<const Point> points) {
  return delaunay_divide_with(points);
}
/// The same for a vector of points.
inline Triangulation delaunay_divide(const std::vector<Point>& points) {
  return delaunay_divide(std::span<const Point>(points));
}

// The default instantiation is compiled once, in lib/src/triangulation/delaunay.cpp.
#ifndef T2_FILTER_STATS  // a program that counts the exact stages compiles its own copy
/// @cond INSTANTIATIONS
extern template Triangulation delaunay_divide_with<DelaunayTraits>(std::span<const Point>, DelaunayTraits);
/// @endcond
#endif

}  // namespace t2
