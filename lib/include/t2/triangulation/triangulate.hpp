#pragma once
/// @file triangulate.hpp
/// @brief A triangulation of front points of T² that is not Delaunay: the sweep (seed 000,
/// Algorithm 9, with every point inserted outside the hull), the start of Lawson's algorithm
/// (lawson.hpp) and of chapter 09.
///
/// **Algorithm.** Sort the points lexicographically by (x, y). The first three that are not
/// collinear make the first triangle (with v∞, triangulation.hpp); the points skipped before the
/// third, collinear with the first two, lie inside its first edge and are inserted there. Every
/// later point q is larger than every point already inserted, so it lies outside their hull, and
/// the last point inserted, m, is a hull vertex that q sees: q goes into the infinite triangle of
/// a hull edge at m that q sees strictly, and then, exactly as in Algorithm 9 (step 35), each
/// infinite triangle (a, b, v∞) next to q whose hull edge a → b q also sees strictly is flipped
/// into the finite triangle (q, …) — the "reflex angles" at the new point are removed.
///
/// **Running time.** O(n log n) for the sort; every hull edge that a point sees is flipped away
/// once and never comes back, so the insertions cost O(n) in all. No point location is needed.
///
/// **Degenerate input** follows delaunay.hpp: duplicates are merged (the smallest index is the
/// vertex, the others listed in `Triangulation::duplicates()`), all-collinear input has no
/// triangle (dimension 1, 0 or −1), and every point on a hull edge is a vertex. The result does
/// not depend on the order of the input (the sort decides), only on the point set.
///
/// Front points only (w > 0) take the sweep; input with a point on the back side or on Ω goes
/// to the incremental construction of triangulate_t2.hpp (seed 000, Algorithm 9 on T²).
///
/// **Trace.** `triangulate(input, trace)` reports to the hook `trace` (t2/trace/hook.hpp), in
/// input indices (the sweep builds on the input's own indices): `start` with the first triangle,
/// `on_edge` for each point inside its first edge, `insert` for each swept point before its
/// flips (faces[0]: the triangle it went into), `flip` after each flip of step 35 (faces: the new
/// triangles, as `Triangulation::flip` leaves them), and `done`. The default `NoTrace` builds no
/// report; t2/trace/sweep_recorder.hpp records the steps for `t2 animate
/// triangulate`. T² input takes no sweep: its steps are those of `triangulate_t2`
/// (insert_t2.hpp), told to the same hook.

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "t2/kernel/error.hpp"
#include "t2/kernel/lexicographic.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/kernel/point.hpp"
#include "t2/trace/hook.hpp"
#include "t2/triangulation/triangulate_t2.hpp"
#include "t2/triangulation/triangulation.hpp"

namespace t2 {

/// Algorithm 9 on T² with a hook (insert_t2.hpp, included at the end).
template <class Trace>
TriangulationT2 triangulate_t2(std::span<const Point> input, InsertionOrder how, Trace&& trace);

namespace detail {

/// True when the front point p lies strictly outside the hull edge of the infinite triangle f:
/// f = (b, a, v∞) up to rotation holds the hull edge a → b, and p is strictly to its right.
inline bool sees_hull_edge(const Triangulation& tr, Triangulation::Index f, const Point& p) {
  const int k = tr.slot(f, Triangulation::infinite);
  return orient(tr.point(tr.vertex(f, (k + 1) % 3)), tr.point(tr.vertex(f, (k + 2) % 3)), p) > 0;
}

//> sweep-hull-flips
/// Removes the reflex angles at the new hull vertex p (seed 000, Algorithm 9, step 35):
/// t is an infinite triangle with p at slot 0; while p sees strictly the hull edge of the
/// infinite triangle u across the edge opposite p, flip that edge (u's hull edge becomes
/// a finite triangle with p). Returns the infinite triangle at p where the chain stops.
/// Each flip is told to `trace`; vertex v of tr is input point input_of[v] (empty: v).
template <class Trace = NoTrace>
Triangulation::Index flip_hull_chain(Triangulation& tr, Triangulation::Index t,
                                     Trace&& trace = {},
                                     std::span<const std::uint32_t> input_of = {}) {
  // t = (p, a, v∞), else (p, v∞, b)
  const bool backward = tr.vertex(t, 2) == Triangulation::infinite;
  for (;;) {
    const Triangulation::Index u = tr.neighbor(t, 0);
    if (!sees_hull_edge(tr, u, tr.point(tr.vertex(t, 0)))) return t;
    // (p, a, v∞) + (a, x, v∞) -> (p, a, x) + (p, x, v∞), and the mirror image
    tr.flip(t, 0);
    tell(trace, [&] {
      const Triangulation::Index p = tr.vertex(t, 0);
      return trace::about(trace::Event::flip, tr, input_of,
                          {input_of.empty() ? p : input_of[p]}, {t, u});
    });
    if (backward) t = u;
  }
}
//< sweep-hull-flips

/// Sorts the indices of `input` by (x, y), equal points by index, and records every point equal
/// to an earlier one as a duplicate in `tr`; returns the distinct points in order.
inline std::vector<Triangulation::Index> sorted_distinct(std::span<const Point> input, Triangulation& tr) {
  using Index = Triangulation::Index;
  std::vector<Index> s(input.size());
  if (std::all_of(input.begin(), input.end(), [](const Point& p) { return p.w() == 1; })) {
    // Cartesian input (the common case): sort copies of the coordinates, not indices into the
    // points, so that every comparison reads adjacent memory (twice as fast at 10⁶ points).
    struct Key {
      double x, y;
      Index i;
    };
    std::vector<Key> k(input.size());
    for (Index j = 0; j < k.size(); ++j) k[j] = {input[j].x(), input[j].y(), j};
    std::sort(k.begin(), k.end(), [](const Key& a, const Key& b) {
      return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.i < b.i;
    });
    for (std::size_t j = 0; j < k.size(); ++j) s[j] = k[j].i;
  } else {
    std::iota(s.begin(), s.end(), Index(0));
    std::sort(s.begin(), s.end(), [&](Index a, Index b) {
      const Sign c = compare_xy(input[a], input[b]);
      return c != ZERO ? c == NEGATIVE : a < b;
    });
  }
  std::vector<Index> u;
  for (Index k : s) {
    if (!u.empty() && compare_xy(input[u.back()], input[k]) == ZERO)
      tr.add_duplicate(k, u.back());
    else
      u.push_back(k);
  }
  return u;
}

}  // namespace detail

/// A triangulation of the points: front points (w > 0) by the sweep of the file comment, any
/// other input by `triangulate_t2` (its faces may include lunes and flat faces, and its
/// `Undefined` cases apply). Every point is a vertex or a reported duplicate; the proper
/// triangles are counter-clockwise. Throws `BadInput` for more than 715 827 882 points.
/// `trace` sees the steps of the sweep (file comment).
template <class Trace = NoTrace>
Triangulation triangulate(std::span<const Point> input, Trace&& trace = {}) {
  using Index = Triangulation::Index;
  using trace::Event;
  if (!std::all_of(input.begin(), input.end(), [](const Point& p) { return p.w() > 0; })) {
    if constexpr (trace::traced<Trace>)
      return triangulate_t2(input, InsertionOrder::spatial, trace).tr;
    else
      return triangulate_t2(input).tr;
  }
  if (input.size() > Triangulation::none / 6)
    throw BadInput("triangulate: more than " + std::to_string(Triangulation::none / 6) + " points");
  Triangulation tr(std::vector<Point>(input.begin(), input.end()));
  const std::vector<Index> u = detail::sorted_distinct(input, tr);
  std::size_t c = 2;  // the first point off the line of u[0], u[1]
  while (c < u.size() && orient(input[u[0]], input[u[1]], input[u[c]]) == ZERO) ++c;
  if (c >= u.size()) {
    tr.set_dimension(u.empty() ? -1 : u.size() == 1 ? 0 : 1);
    tr.finish();
    return tr;
  }
  //> triangulate
  // The first triangle: u[0], u[c-1] and u[c]; the points u[1..c-2] between the first two
  // (on their line) go into that edge, each into the part left over by the previous one.
  const Index a = u[0], b = u[c - 1], q = u[c];
  const bool ccw = orient(input[a], input[b], input[q]) > 0;
  if (ccw) tr.make_triangle(a, b, q, u.size()); else tr.make_triangle(b, a, q, u.size());
  tell(trace, [&] {
    return trace::about(Event::start, tr, {},
                        {tr.vertex(0, 0), tr.vertex(0, 1), tr.vertex(0, 2)});
  });
  // the edge is opposite slot 2 of t0, then of the newest triangle
  for (std::size_t k = 1; k + 1 < c; ++k) {
    const Index t = k == 1 ? 0 : static_cast<Index>(tr.size() - 1);
    const Index on = u[ccw ? k : c - k - 1];
    tr.insert_on_edge(t, 2, on);
    tell(trace, [&] { return trace::about(Event::on_edge, tr, {}, {on}); });
  }
  // The sweep: each point sees a hull edge at the previous one, m, whose infinite
  // triangles are (m, x, v∞) and (m, v∞, y) (t1 and t2 of make_triangle for m = q).
  Index back = 1, fwd = 2;
  for (std::size_t k = c + 1; k < u.size(); ++k) {
    const Index p = u[k];
    const Index hit = detail::sees_hull_edge(tr, back, input[p]) ? back : fwd;
    if (!detail::sees_hull_edge(tr, hit, input[p]))
      throw std::logic_error("triangulate: no hull edge seen");
    tr.insert_in_face(hit, p);  // p is vertex 0 of hit and of the last two triangles
    tell(trace, [&] { return trace::about(Event::insert, tr, {}, {p}, {hit, 0}); });
    const Index n = static_cast<Index>(tr.size());
    for (Index f : {hit, n - 2, n - 1}) {
      if (tr.vertex(f, 2) == Triangulation::infinite)
        back = detail::flip_hull_chain(tr, f, trace);
      if (tr.vertex(f, 1) == Triangulation::infinite)
        fwd = detail::flip_hull_chain(tr, f, trace);
    }
  }
  //< triangulate
  tell(trace, [&] { return trace::about(Event::done, tr, {}, {}); });
  tr.finish();
  return tr;
}

/// The same for a vector of points.
inline Triangulation triangulate(const std::vector<Point>& points) { return triangulate(std::span<const Point>(points)); }

}  // namespace t2

#include "t2/triangulation/insert_t2.hpp"  // IWYU pragma: export
