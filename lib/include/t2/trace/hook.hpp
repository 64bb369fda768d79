#pragma once
/// @file hook.hpp
/// @brief The one protocol by which every algorithm of the library tells a trace what it does:
/// a `Report` per event, in the algorithm's *input indices*.
///
/// An algorithm that can be traced takes a hook `tr` (a `Hook`: anything callable with a
/// `const Report&`) and calls it at each event: "I consider p7", "p7 is pushed", "the edge
/// opposite p12 flips", "p29 lies inside the circle of p38, p16, p12". A report names the points
/// it concerns by their index in the algorithm's input, never by the algorithm's private
/// numbering: an algorithm that reorders its points (the spatial order of Delaunay, the
/// insertion order of Algorithm 9 on T²) maps them back before it reports. For the state that is
/// too large to copy at each event (a triangulation), the report lends a view of it and the map
/// from its vertices to input indices, so that a recorder reads the state the algorithm has and
/// never rebuilds it.
///
/// **Cost.** The default hook is `NoTrace`. Algorithms build a report only under
/// `if constexpr (traced<Tr>)` (or through `tell`, which does that), so the untraced
/// instantiation contains no trace code at all: bench/bench_hull.cpp and bench_delaunay.cpp
/// time both.

#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <span>
#include <type_traits>

#include "t2/kernel/point_type.hpp"
#include "t2/kernel/sign.hpp"

namespace t2 {

class Triangulation;
class UnionFind;
class TrapezoidMap;
struct EmptyCircle;

namespace trace {

/// What happened. Hull algorithms report the first seven, triangulations the next fourteen,
/// Welzl's smallest enclosing circle the next two, the walk of point location two more, the
/// kd-tree's query two more, Fortune's sweep five more (its `chain` is the beach line after the
/// event: the sites of its arcs left to right, input indices, a site once per arc), the sweeps
/// of segment intersection (chapter 13: Bentley–Ottmann, the circular sweep) four more (a
/// segment sweep names *segments* by their input index), the proximity problems (chapter 12)
/// seven more, Chan's hull two more (with `vertex`, and Graham's events when one group holds
/// every point), and the trapezoidal map of point location (chapter 14) the last four.
enum class Event {
  consider,       ///< the algorithm looks at point at[0] (Jarvis: at[1] is the candidate after it)
  push,           ///< at[0] joins the chain (stack, hull so far)
  pop,            ///< at[0] leaves the chain: it is not a hull vertex
  vertex,         ///< at[0] is a hull vertex (Jarvis, Quickhull)
  bridge,         ///< the merge joins the hull so far to at[0]
  positive_half,  ///< the merge has the hull of the positive half, as the chain
  negative_half,  ///< the merge has the hull of the negative half, as the chain
  start,          ///< the first triangle: at[0..2], counter-clockwise
  insert,         ///< at[0] has joined the triangulation, before its flips (Delaunay, the sweep)
  in_face,        ///< at[0] lies inside a face and splits it in three (Algorithm 9 on T²)
  on_edge,        ///< at[0] lies inside an edge: its two faces split in four (Algorithm 9 on T²)
  duplicate,      ///< at[0] equals the vertex at[1]: one vertex, at[1]
  outside,        ///< at[0] lies outside the hull and is joined to the hull edges it sees
  cover,          ///< at[0] sees every hull edge: it takes v∞'s place and the hull is gone
  antipode,       ///< at[0] is the antipode of a hull vertex: it takes v∞'s place (step 31)
  wait,           ///< at[0]'s antipode lies inside a hull edge: it is inserted later
  join,           ///< at[0], outside the hull, is joined to a hull edge: faces[0] is the new face
  flip,           ///< an edge flips to at[0]: faces[0], faces[1] are the new triangles
  in_circle,      ///< is at[3] inside the circle of at[0..2]? `sign` answers (POSITIVE: inside)
  replace,        ///< at[0] took v∞'s place in the faces `face_list`, in order around it
  done,           ///< the algorithm is finished; `tr` is its result before renumbering
  enclose,        ///< the disk is now the one of at[0..2]: a circumcircle, a diameter (at[2]
                  ///< none) or one point (at[1] none)
  in_disk,        ///< is at[0] in the last `enclose`'s closed disk? `sign` answers (POSITIVE in)
  // Point location (location/walk.hpp); vertices are indices of the subdivision's points(),
  // which are the input points when the map was made from index cycles into them.
  enter_region,   ///< the walk enters region faces[0] (a face, or Subdivision::outside): across
                  ///< the edge at[0] → at[1] (vertices), or from vertex at[2], or (all none)
                  ///< from its starting point inside the face
  reach_vertex,   ///< the walk stands at vertex at[0]: its start, or a vertex its segment
                  ///< passes through
  // Range search (range/kdtree.hpp); positions are into KdTree::tree_order(at[1]).
  kd_enter,       ///< the query enters the kd-tree node of the positions [faces[0], faces[1])
                  ///< of side at[1] at depth at[2]; at[0] is its splitting point (input
                  ///< index), none for a leaf; `sign` POSITIVE when its region lies inside the
                  ///< window (reported whole, no test)
  kd_report,      ///< the query reports point at[0] (input index): it lies in the window
  site,           ///< Fortune: the sweep line reaches site at[0] (y = its y); its arc splits the
                  ///< arc of at[1] (none: at[0] is in the first row, a new arc on the right)
  circle,         ///< Fortune: the arc of at[1] between the arcs of at[0] and at[2] shrinks to a
                  ///< point: a Voronoi vertex at the centre of their circle, the sweep line at
                  ///< its top
  schedule,       ///< Fortune: the circle event of at[0..2] (the arc of at[1]) joins the queue
  false_alarm,    ///< Fortune: the circle event of at[0..2] leaves the queue unprocessed: the arc
                  ///< of at[1] or a neighbour changed first
  breakpoint,     ///< Fortune: where is site at[2] against the breakpoint of the arcs of at[0]
                  ///< (left) and at[1] (right)? `sign` is sign(breakpoint's x − the site's x)
                  ///< (POSITIVE: the site is left of it)
  sweep_start,    ///< the circular sweep begins: `point` is its centre o, `chain` the segments cut at
                  ///< its initial half-line (from o through [0, 1, 0] to ¬o)
  found,          ///< an intersection point is reported: `point`, the segments through it in
                  ///< `chain` (ascending); told before the status changes at it
  sweep,          ///< the sweep has passed the event point `point`: `chain` is the status after it
                  ///< (segments from below, or from the centre out), `through` the segments
                  ///< through the point that go on past it, in their new order
  neighbours,     ///< do the status neighbours at[0] (below) and at[1] (above) cross after the
                  ///< event? `sign`: POSITIVE yes (the crossing is queued), NEGATIVE no, ZERO they
                  ///< lie on one line or are parallel (overlaps are found at their endpoints)
  candidates,     ///< the proximity candidates of one side: `tr` its planar Delaunay triangulation,
                  ///< vertex v the input point input(v) (Kruskal: its edges are the candidates)
  tree_edge,      ///< Kruskal takes the edge at[0] at[1]: it joins two components; `forest` after
  cycle_edge,     ///< Kruskal drops the edge at[0] at[1]: both ends are in one component of
                  ///< `forest`, and the edge would close a cycle
  empty_circle,   ///< a candidate of the largest empty circle: `circle` (its exact centre, squared
                  ///< radius, the sites that define it); at[0..2] a Voronoi vertex's Delaunay
                  ///< triangle, or at[0], at[1] the sites of a Voronoi edge and at[2], at[3] the
                  ///< hull edge it crosses (or at[0], at[1] alone: the midpoint of collinear sites).
                  ///< `sign`: POSITIVE a new best, ZERO no better, NEGATIVE outside the hull
  split,          ///< divide and conquer splits the sites `chain` (sorted by x) at the vertical
                  ///< line through at[0], the first site of the right half
  strip,          ///< the sites `chain` (sorted by y) lie near the line through at[0]: the strip
  compare_pair,   ///< the pair at[0] at[1] is compared with the closest so far; `sign` POSITIVE:
                  ///< it is the new closest
  group_hull,     ///< Chan: the hull of one group of this round is `chain` (Graham's scan of the
                  ///< group's points `through`); the first group of a round holds m points
  tangent,        ///< Chan: from the hull vertex at[0], the tangent to a group's hull touches
                  ///< at[1] (the group's best next vertex for Jarvis); `chain` the hull so far
  // The trapezoidal map (location/trapezoid_map.hpp): `trapezoids` lends the map now; its
  // trapezoids are named by their index in it, points by input index (`input_of` maps the map's
  // own points to them when it is not the identity).
  trapezoid_split, ///< the segment at[0] → at[1] (left to right in the map's x-order) is inserted:
                   ///< it crossed the trapezoids `face_list`, left to right, which are destroyed,
                   ///< and the trapezoids faces[0] to faces[1] − 1 are new
  dag_x,           ///< the query meets the x-node of point at[0]: `sign` is its x-order against it
                   ///< (NEGATIVE: left, ZERO: the query is that point)
  dag_y,           ///< the query meets the y-node of the segment at[0] → at[1]: `sign` is
                   ///< orient(at[0], at[1], query) (POSITIVE: above, ZERO: on it)
  dag_leaf,        ///< the query reaches the leaf of trapezoid faces[0]
};

/// One event, as the algorithm reports it (see the file comment).
struct Report {
  static constexpr std::size_t none = static_cast<std::size_t>(-1);  ///< an unused index

  Event event = Event::consider;                     ///< what happened
  std::array<std::size_t, 4> at{none, none, none, none};  ///< the points concerned, input indices
  std::span<const std::size_t> chain;                ///< the chain or stack (hulls), input indices
  const Triangulation* tr = nullptr;                 ///< the triangulation now (triangulations)
  std::span<const std::uint32_t> input_of;           ///< vertex v of `tr` is input point input_of[v]
                                                     ///< (empty: v is already an input index)
  std::array<std::uint32_t, 2> faces{0, 0};          ///< triangles of `tr` concerned (flip, join)
  std::span<const std::uint32_t> face_list;          ///< more triangles of `tr` (replace)
  Sign sign = ZERO;                                  ///< a predicate's answer (in_circle)
  bool tie = false;  ///< the exact predicate was zero and the symbolic perturbation decided
  const ExactPoint* point = nullptr;       ///< a constructed point, exact (sweeps: the event, a
                                           ///< reported intersection, the centre); lent
  std::span<const std::size_t> through;    ///< a second list of input indices (sweep: see the event)
  const UnionFind* forest = nullptr;   ///< Kruskal's components now, over input indices (emst)
  const EmptyCircle* circle = nullptr; ///< a candidate circle, exact (the largest empty circle)
  const TrapezoidMap* trapezoids = nullptr;  ///< the trapezoidal map now (its events); lent

  /// The input index of vertex v of `tr`.
  std::size_t input(std::uint32_t v) const { return input_of.empty() ? v : input_of[v]; }
  /// The points concerned (the used entries of `at`).
  std::span<const std::size_t> points() const {
    std::size_t n = 0;
    while (n < at.size() && at[n] != none) ++n;
    return {at.data(), n};
  }
};

/// A report about points, with the chain or stack (hull algorithms).
inline Report about(Event e, std::initializer_list<std::size_t> at, std::span<const std::size_t> chain = {}) {
  Report r;
  r.event = e;
  std::size_t k = 0;
  for (std::size_t i : at) r.at[k++] = i;
  r.chain = chain;
  return r;
}

/// A report about a triangulation whose vertex v is input point input_of[v] (`at` already in
/// input indices; faces are triangles of tr).
inline Report about(Event e, const Triangulation& tr, std::span<const std::uint32_t> input_of,
                    std::initializer_list<std::size_t> at, std::array<std::uint32_t, 2> faces = {0, 0}) {
  Report r = about(e, at);
  r.tr = &tr;
  r.input_of = input_of;
  r.faces = faces;
  return r;
}

/// A hook: anything an algorithm can report to.
template <class T>
concept Hook = std::invocable<T&, const Report&>;

/// The hook that hears nothing: the default of every algorithm, free (file comment).
struct NoTrace {
  /// Hears nothing.
  void operator()(const Report&) const noexcept {}
};

/// A hook behind a compiled interface: the traced overload of an algorithm whose body is compiled
/// in the library (the sweeps, Fortune, the walk, the kd-tree, the proximity problems) takes one,
/// so that its traced code is compiled once and any callable converts to it.
using AnyHook = std::function<void(const Report&)>;

/// False for `NoTrace`: the algorithm then builds no report.
template <class T>
inline constexpr bool traced = !std::is_same_v<std::remove_cvref_t<T>, NoTrace>;

/// Calls `hook(make())` when the hook listens; for `NoTrace`, nothing at all (not even `make`).
template <class H, class F>
void tell(H& hook, F&& make) {
  if constexpr (traced<H>) hook(make());
}

/// Calls `hook(about(e, at, chain))`, with `sign`, when the hook listens (hull algorithms).
template <class H>
void tell(H& hook, Event e, std::initializer_list<std::size_t> at, std::span<const std::size_t> chain = {},
          Sign sign = ZERO) {
  if constexpr (traced<H>) {
    Report r = about(e, at, chain);
    r.sign = sign;
    hook(r);
  }
}

}  // namespace trace

using trace::NoTrace;
using trace::tell;

}  // namespace t2
