#pragma once
/// @file fortune.hpp
/// @brief Fortune's sweep (seed 001): the front half of the Voronoi diagram of T² for sites on
/// the front side, by a sweep line, a beach line of parabolic arcs and an event queue, exact.
///
/// **What it builds, against `t2::voronoi`.** For sites on the front side (w > 0; any positive
/// weight), `voronoi` (voronoi.hpp) is the dual of the whole-sphere Delaunay complex: its front
/// vertices are the nearest-point Voronoi vertices, its back vertices the antipodes of the
/// farthest-point ones, and each unbounded edge of the plane is an edge from a front vertex
/// across Ω to a back vertex. Fortune's sweep sees the plane only. It gives
///  - the same front vertices (`vertex(v)`, the same exact circumcentres, from `circumcentre`),
///    each with the sites of its cells counter-clockwise around it;
///  - the same edges between two front vertices (`edges`);
///  - for each edge of `voronoi` that leaves the front side, the ray from its front vertex to the
///    point where it crosses Ω (`rays`: the pole of the hull edge s t, the point of Ω to the left
///    of s → t where t → s is a counter-clockwise hull edge);
///  - the bisectors without a vertex (`lines`: two sites, or collinear sites);
/// and nothing of the back half (the farthest-point diagram), which the sweep does not meet.
/// tests/test_fortune.cpp checks that it is exactly `voronoi` restricted to the front side.
///
/// **The sweep.** The sweep line y = L moves up; the sites below it are processed. The beach
/// line is the upper envelope of the parabolas of points as far from a processed site as from
/// the sweep line: x-monotone, so its arcs are kept left to right in a balanced tree (a treap).
/// A site event splits the arc above the site; a circle event removes an arc whose neighbours'
/// breakpoints meet, at the top of the circle through three consecutive sites, and makes a
/// Voronoi vertex there.
///
/// **Exact decisions.** Sites are read as rationals x/w, y/w (exact: a double is a rational).
///  - Event order: by y, then x; a circle event before a site at the same point. A circle event
///    is at y = c_y + √R (c the centre, R the squared radius): against a site, the sign of
///    (c_y − y_s) + √R; against another circle event, the sign of d + √R₁ − √R₂ (d = c_y₁ −
///    c_y₂), which is −1 when d + √R₁ < 0, and else the sign of (d² + R₁ − R₂) + 2d√R₁.
///  - Breakpoint of the arcs of p (left) and q (right) against the site abscissa a: with
///    d_p = y_p − L, d_q = y_q − L, the breakpoint is x = (d_q x_p − d_p x_q − √(d_p d_q |pq|²))
///    / (d_q − d_p) when d_p ≠ d_q (the midpoint of x_p, x_q when d_p = d_q), so sign(x − a) =
///    sign(d_q − d_p) · sign(A − √C) with A = d_q x_p − d_p x_q − a(d_q − d_p), C = d_p d_q |pq|².
///  All A + B√C signs are exact: on the sites' doubles as polynomials (fortune_exact.hpp), or
///  through `sign_of_root_sum` (sign_sqrt.hpp) on integers (rationals times their positive
///  denominators), after filters that decide most of them (**Cost**). Three consecutive arcs
///  make a circle event exactly when their sites turn counter-clockwise (`orient` > 0).
///
/// **Degeneracies** (seed 001). Duplicate sites are reduced to the first of each group (listed in
/// `duplicates` as (dropped, kept)). The first row of sites (the lowest y, several of them)
/// starts the beach line as vertical rays, left to right, with vertical bisectors. A site on a
/// breakpoint splits the arc on the right: the left half has length zero, and its circle event
/// is at the site itself, processed next: a vertex at the breakpoint. Cocircular sites give
/// several circle events at one point; the vertices they make are joined by edges of length
/// zero, which are contracted, so four or more cells meet at one vertex and no edge has length
/// zero. Collinear sites give no circle event: only `lines`.
///
/// **Cost.** O(n log n) expected (O(n) events, each with O(log n) queue and treap steps). Each
/// predicate is first evaluated in interval arithmetic with certified bounds (doubles). The
/// arc above a site is guessed by a search in rounded doubles and certified by its two exact
/// breakpoint comparisons. The queue keeps each event's enclosure beside its number. When an
/// enclosure does not decide, for sites with w = 1: a tight enclosure of the event's y (the
/// circle's coefficients exact as expansions), then the exact signs of the polynomials on the
/// doubles (the kernel's filter: expansions, GMP out of their range); equal circles (translates
/// in lattices, mirror images in symmetric input, one circle of cocircular sites, kept in
/// classes) are found by in_circle. GMP rationals are made only for sites with w ≠ 1, or for
/// two events whose order none of these decides.

#include <array>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "t2/kernel/point.hpp"
#include "t2/trace/hook.hpp"
#include "t2/voronoi/voronoi.hpp"

namespace t2 {

/// The front half of the Voronoi diagram of front sites, as Fortune's sweep builds it.
struct FortuneDiagram {
  using Index = VoronoiDiagram::Index;  ///< site and vertex indices
  using Edge = VoronoiDiagram::Edge;    ///< an edge between two vertices and two sites
  /// An unbounded edge: from vertex `a` to the point `end` of Ω, between sites `s` and `t`.
  struct Ray {
    Index a;          ///< the vertex it starts from
    ExactPoint end;   ///< where it crosses Ω (w = 0)
    Index s;          ///< the site on one side
    Index t;          ///< the site on the other side
  };
  std::vector<Point> sites;  ///< the sites, as given
  /// Three sites of each Voronoi vertex, counter-clockwise: the vertex is their circumcentre.
  std::vector<std::array<Index, 3>> circles;
  /// The cells at vertex v, counter-clockwise around it, are cells[first[v] .. first[v + 1]).
  std::vector<Index> first;
  std::vector<Index> cells;                         ///< the sites at each vertex, one after the other
  std::vector<Edge> edges;                          ///< between two vertices
  std::vector<Ray> rays;                            ///< from a vertex to Ω
  std::vector<std::pair<Index, Index>> lines;       ///< bisectors without a vertex
  std::vector<std::pair<Index, Index>> duplicates;  ///< (dropped, kept): sites owning no cell

  /// The number of Voronoi vertices.
  std::size_t size() const { return circles.size(); }
  /// Vertex v (w > 0): its exact homogeneous coordinates, `circumcentre` of `circles[v]`
  /// (constructed on each call: GMP integers, as `VoronoiDiagram::vertex`).
  ExactPoint vertex(Index v) const {
    return circumcentre(sites[circles[v][0]], sites[circles[v][1]], sites[circles[v][2]]);
  }
  /// The sites whose cells meet at vertex v, counter-clockwise around it.
  std::span<const Index> vertex_sites(Index v) const {
    return std::span<const Index>(cells).subspan(first[v], first[v + 1] - first[v]);
  }
};

/// Fortune's sweep on `sites` (file comment). Throws `Undefined` when a site is not on the front
/// side (w ≤ 0): the sweep works in the plane of the front side only.
FortuneDiagram fortune(std::span<const Point> sites);

/// The same, telling `hook` (trace/hook.hpp) each event of the sweep in input indices, with the
/// beach line after it as the report's chain: `site` (the site and the arc it splits), `circle`
/// (the three sites whose circle's centre becomes a vertex; the middle arc goes), `schedule` and
/// `false_alarm` (a circle event queued, and dropped before its time), and each `breakpoint`
/// comparison of the search for the arc above a site, with its sign. Duplicate sites are
/// dropped before the sweep and never reported. Only this overload carries trace code; the one
/// above has none.
FortuneDiagram fortune(std::span<const Point> sites, const trace::AnyHook& hook);

}  // namespace t2
