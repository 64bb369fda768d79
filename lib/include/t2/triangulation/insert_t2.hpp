#pragma once
/// @file insert_t2.hpp
/// @brief The incremental insertion of Algorithm 9 on T² (seed 000, §5.3), with a trace:
/// triangulate_t2.hpp has the cases, the order, the proofs and the untraced entry point.
///
/// **Trace.** `triangulate_t2(input, how, trace)` reports every step to the hook `trace`
/// (t2/trace/hook.hpp), in input indices; each report lends the triangulation, whose vertex m is
/// input point order[m]. `start` when the first triangle is made; then, for every later point,
/// once its insertion is complete, `in_face`, `on_edge`, `duplicate`, `outside`, `cover` or
/// `antipode` (or `wait` when it has to wait; it is inserted later and reported again). Before
/// that, a point outside the hull reports `join` when it is put into the infinite face of a hull
/// edge it sees (faces[0]: its finite face) and `flip` after each flip of step 35 (as
/// `triangulate.hpp`'s sweep does); a point that destroys the hull reports `replace` once v∞ is
/// gone, with the faces where it took v∞'s place, in order around it (`face_list`). At the end,
/// `done`. `NoTrace` builds no report (bench/bench_triangulate_t2.cpp measures it);
/// t2/trace/triangulate_t2_recorder.hpp records the steps for `t2 animate triangulate`.

#include <algorithm>
#include <array>
#include <initializer_list>
#include <numeric>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "t2/kernel/error.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/kernel/point.hpp"
#include "t2/triangulation/antipodal_edge.hpp"
#include "t2/triangulation/spatial_sort.hpp"
#include "t2/triangulation/triangulate.hpp"
#include "t2/triangulation/triangulate_t2.hpp"
#include "t2/triangulation/triangulation.hpp"

namespace t2 {

namespace detail {

/// All points on the great circle of the first two distinct ones: no triangle (dimension 1 or
/// 0) if they lie in an open half of it, else Undefined (triangulate_t2.cpp).
void collinear_t2(std::span<const Point> input, Triangulation& tr, bool one_point);
/// Throws the Undefined of a point p whose antipode lies inside the hull edge a → b of all the
/// others (input indices; triangulate_t2.cpp).
[[noreturn]] void undefined_t2(std::span<const Point> input, Triangulation::Index p, Triangulation::Index a,
                               Triangulation::Index b);

/// The incremental construction (Algorithm 9) on one triangulation, reporting to `Trace`.
template <class Trace>
class T2Builder {
  using Index = Triangulation::Index;
  static constexpr Index kInf = Triangulation::infinite, kNone = Triangulation::none;

 public:
  /// `order[v]` is the input index of point v of tr (the points are in insertion order).
  T2Builder(Triangulation& tr, const std::vector<Index>& order, Trace& trace)
      : tr_(tr), order_(order), trace_(trace) {}

  /// Inserts the point p (an index into tr's points); returns false when p must wait.
  bool insert(Index p) {
    return hull_ ? insert_with_hull(p) : insert_located(p, locate(P(p)));
  }
  /// True while the points inserted have a hull (v∞ is a vertex).
  bool hull() const { return hull_; }
  /// The hull edge whose inside holds ¬p (after insert returned false).
  std::pair<Index, Index> blocking_edge() const { return blocking_; }

 private:
  /// Where a point is: inside face t, on the edge opposite slot i of t, or on vertex i of t.
  struct Where {
    enum Kind { none, face, edge, vertex, outside } kind = none;  // outside: beyond the hull
    Index t = 0;
    int i = 0;
  };

  const Point& P(Index v) const { return tr_.point(v); }
  Sign side(Index t, int i, const Point& p) const { return side_of_edge(tr_, t, i, p); }

  /// What p is in the closed face t (finite), or `none` (outside it, or t is flat).
  Where classify(Index t, const Point& p) const {
    Sign s[3];
    for (int i = 0; i < 3; ++i)
      if ((s[i] = side(t, i, p)) == NEGATIVE) return {};
    const int zeros = (s[0] == ZERO) + (s[1] == ZERO) + (s[2] == ZERO);
    if (zeros == 0) return {Where::face, t, 0};
    const FaceKind kind = face_kind(tr_, t);
    if (kind == FaceKind::flat) return {};
    for (int i = 0; i < 3; ++i)
      if (P(tr_.vertex(t, i)) == p) return {Where::vertex, t, i};
    if (is_proper(kind)) {  // one zero: the edge; two: the vertex, handled above
      for (int i = 0; i < 3; ++i)
        if (s[i] == ZERO) return on_edge(t, i, p);
    }
    // A lune: p on its antipodal edge (one zero), or on its half circle through the third
    // vertex (two zeros), in one of the two arcs.
    for (int i = 0; i < 3; ++i) {
      if (s[i] != ZERO) continue;
      const Point &a = P(tr_.vertex(t, (i + 1) % 3)), &b = P(tr_.vertex(t, (i + 2) % 3));
      if (a == antipode(b) ? zeros == 1 : inside_arc(a, b, p)) return on_edge(t, i, p);
    }
    throw std::logic_error("triangulate_t2: a point on a lune's boundary and on none of its edges");
  }

  /// p inside the edge opposite slot i of t — unless p is a vertex hidden inside that edge: the
  /// middle vertex of a flat face across it, or of a flat face across the edge of that one
  /// whose arc holds p (flat faces may lie on one another), and so on.
  Where on_edge(Index t, int i, const Point& p) const {
    Index f = t;
    int k = i;
    for (std::size_t guard = tr_.size(); guard > 0; --guard) {
      const Index e = tr_.twin(f, k), u = e / 3;
      const int j = static_cast<int>(e % 3);
      if (tr_.is_infinite(u) || face_kind(tr_, u) != FaceKind::flat) break;
      if (P(tr_.vertex(u, j)) == p) return {Where::vertex, u, j};
      int next = -1;  // the other edge of u whose arc holds p
      for (int m : {(j + 1) % 3, (j + 2) % 3})
        if (inside_arc(P(tr_.vertex(u, (m + 1) % 3)), P(tr_.vertex(u, (m + 2) % 3)), p)) next = m;
      if (next < 0) break;
      f = u;
      k = next;
    }
    return {Where::edge, t, i};
  }

  //> t2-walk
  /// The visibility walk from the face last_ (finite) with the exact sides; it stops
  /// at an infinite face (p is strictly outside the hull: `outside`); after 4·(faces)
  /// + 64 steps (it may circle on the sphere) or at a flat face, a scan of the finite
  /// faces (`none` when p is in none of them, outside the hull).
  Where locate(const Point& p) {
    Index t = last_;
    int from = -1;
    for (std::size_t steps = 4 * tr_.size() + 64; steps > 0; --steps) {
      rng_ ^= rng_ << 13, rng_ ^= rng_ >> 17, rng_ ^= rng_ << 5;
      const int r = static_cast<int>(rng_ % 3);
      int cross = -1;
      for (int k = 0; k < 3 && cross < 0; ++k) {
        const int i = (r + k) % 3;
        if (i != from && side(t, i, p) == NEGATIVE) cross = i;
      }
      if (cross < 0) {
        const Where w = classify(t, p);
        if (w.kind != Where::none) return w;
        break;  // a flat face
      }
      from = static_cast<int>(tr_.twin(t, cross) % 3);
      t = tr_.neighbor(t, cross);
      if (tr_.is_infinite(t)) return {Where::outside, t, 0};
    }
    for (Index f = 0; f < tr_.size(); ++f)
      if (!tr_.is_infinite(f))
        if (const Where w = classify(f, p); w.kind != Where::none) return w;
    if (hull_) return {};
    throw std::logic_error("triangulate_t2: a point in no face");
  }
  //< t2-walk

  bool insert_located(Index p, Where w) {
    if (w.kind == Where::vertex) {  // the kept point is the one of smaller input index
      const Index v = tr_.vertex(w.t, w.i);
      if (order_[p] > order_[v]) {
        tr_.add_duplicate(p, v);
        report(trace::Event::duplicate, {order_[p], order_[v]});
        return true;
      }
      tr_.rename_vertex(w.t, v, p);  // in the antipodal-edge records too
      tr_.add_duplicate(v, p);
      report(trace::Event::duplicate, {order_[v], order_[p]});
      return true;
    }
    if (w.kind == Where::face) {
      tr_.insert_in_face(w.t, p);
    } else {
      const Index a = tr_.vertex(w.t, (w.i + 1) % 3), b = tr_.vertex(w.t, (w.i + 2) % 3);
      if (a != kInf && b != kInf && P(a) == antipode(P(b))) drop_antipodal_edge(a, b);  // figure 5.20
      tr_.insert_on_edge(w.t, w.i, p);  // an infinite neighbour stays infinite: inf_ holds
    }
    last_ = w.t;
    report(w.kind == Where::face ? trace::Event::in_face : trace::Event::on_edge, {order_[p]});
    return true;
  }

  //> t2-outside
  bool insert_with_hull(Index p) {
    const Point& q = P(p);
    // Most points fall inside the hull: the walk finds them.
    if (const Where w = locate(q); w.kind != Where::outside && w.kind != Where::none)
      return insert_located(p, w);
    // The hull edges a → b, from the infinite triangles (b, a, v∞) around v∞.
    int pos = 0;
    Index seen = kNone, t = inf_;
    std::vector<std::pair<Index, Index>> zero;  // edges whose circle holds p
    std::vector<Index> around;                  // the infinite faces, in order
    do {
      around.push_back(t);
      const int k = tr_.slot(t, kInf);
      const Index b = tr_.vertex(t, (k + 1) % 3), a = tr_.vertex(t, (k + 2) % 3);
      const Sign o = orient(P(a), P(b), q);
      if (o > 0) ++pos;
      if (o < 0) seen = t;
      if (o == 0) zero.emplace_back(a, b);
      t = tr_.neighbor(t, (k + 1) % 3);
    } while (t != inf_);
    if (seen == kNone)
      throw std::logic_error("triangulate_t2: the walk left the hull for a point in it");
    if (pos > 0) {  // the hull survives (step 34, 35)
      tr_.insert_in_face(seen, p);
      const Index n = static_cast<Index>(tr_.size());
      for (Index f : {seen, n - 2, n - 1})
        if (!tr_.is_infinite(f)) last_ = f;  // (p, b, a): finite for good, flips keep it
      report(trace::Event::join, {order_[p]}, {last_, 0});
      for (Index f : {seen, n - 2, n - 1}) {
        if (tr_.vertex(f, 2) == kInf) inf_ = flip_hull_chain(tr_, f, trace_, order_);
        if (tr_.vertex(f, 1) == kInf) inf_ = flip_hull_chain(tr_, f, trace_, order_);
      }
      report(trace::Event::outside, {order_[p]});
      return true;
    }
    // ¬p is in the closed hull: the hull is destroyed. Where is ¬p?
    const Point np = antipode(q);
    std::pair<Index, Index> before{kNone, kNone}, after = before;
    for (auto [a, b] : zero) {
      if (P(b) == np) before = {a, b};  // u → z
      if (P(a) == np) after = {a, b};   // z → w
    }
    if (!zero.empty() && before.first == kNone) {  // ¬p inside a hull edge: wait
      for (auto [a, b] : zero)
        if (inside_arc(P(a), P(b), np)) blocking_ = {a, b};
      report(trace::Event::wait, {order_[p]});
      return false;
    }
    tr_.rename_vertex(inf_, kInf, p);  // p replaces v∞ everywhere
    last_ = inf_;
    if (before.first != kNone)  // step 31: the antipode of the hull vertex z
      tr_.add_antipodal_edge({before.second, p, before.first, after.second});
    hull_ = false;
    report(trace::Event::replace, {order_[p]}, {0, 0}, around);
    report(before.first != kNone ? trace::Event::antipode : trace::Event::cover,
           {order_[p]});
    return true;
  }
  //< t2-outside

  // Tells the hook about the points `at` (input indices) and the faces of tr.
  void report(trace::Event e, std::initializer_list<std::size_t> at, std::array<Index, 2> faces = {0, 0},
              std::span<const Index> face_list = {}) {
    if constexpr (trace::traced<Trace>) {
      trace::Report r = trace::about(e, tr_, order_, at, faces);
      r.face_list = face_list;
      trace_(r);
    }
  }

  /// Forgets the record of the antipodal edge a–b, which a point inside it splits (figure 5.20).
  void drop_antipodal_edge(Index a, Index b) {
    std::vector<AntipodalEdge> kept;
    for (const AntipodalEdge& e : tr_.antipodal_edges())
      if (!((e.z == a && e.nz == b) || (e.z == b && e.nz == a))) kept.push_back(e);
    tr_.set_antipodal_edges(std::move(kept));
  }

  Triangulation& tr_;
  const std::vector<Index>& order_;
  Trace& trace_;
  bool hull_ = true;
  Index inf_ = 1;   // an infinite triangle while the hull exists
  Index last_ = 0;  // a finite triangle near the last insertion
  std::uint32_t rng_ = 2463534242u;
  std::pair<Index, Index> blocking_{};
};

}  // namespace detail

/// The triangulation of any points of T² by Algorithm 9, the points inserted in the order `how`,
/// every step reported to `trace` (file comment); otherwise as `triangulate_t2(input, how)`.
//> triangulate-t2
template <class Trace>
TriangulationT2 triangulate_t2(std::span<const Point> input, InsertionOrder how, Trace&& trace) {
  using Index = Triangulation::Index;
  if (input.size() > Triangulation::none / 6)
    throw BadInput("triangulate: more than " + std::to_string(Triangulation::none / 6) + " points");
  const Index n = static_cast<Index>(input.size());
  // Built on a copy of the points in insertion order (point m is the m-th inserted), so that
  // the walks touch memory in order; the input indices come back at the end.
  std::vector<Index> order(n);
  if (how == InsertionOrder::spatial) order = sphere_order(input);
  else std::iota(order.begin(), order.end(), Index(0));
  std::vector<Point> sorted;
  sorted.reserve(n);
  for (Index m : order) sorted.push_back(input[m]);
  TriangulationT2 out;
  if (n == 0) return out;
  Triangulation tr(std::move(sorted));
  const std::vector<Point>& P = tr.points();
  // the first triangle: P[0], b the first point ≠ ±P[0], c the first off their circle
  Index b = 1, c = 0;
  while (b < n && (P[b] == P[0] || P[b] == antipode(P[0]))) ++b;
  for (Index k = b + 1; k < n && c == 0; ++k)
    if (orient(P[0], P[b], P[k]) != ZERO) c = k;
  if (c == 0) {  // all on one great circle
    auto same = [&](const Point& p) { return p == P[0]; };
    out.tr = Triangulation({input.begin(), input.end()});
    detail::collinear_t2(input, out.tr, std::all_of(input.begin(), input.end(), same));
    out.tr.finish();
    return out;
  }
  if (orient(P[0], P[b], P[c]) > 0) tr.make_triangle(0, b, c, n);
  else tr.make_triangle(b, 0, c, n);
  tell(trace, [&] {
    const std::size_t u = order[tr.vertex(0, 0)], v = order[tr.vertex(0, 1)];
    return trace::about(trace::Event::start, tr, order, {u, v, order[tr.vertex(0, 2)]});
  });
  detail::T2Builder<std::remove_reference_t<Trace>> builder(tr, order, trace);
  std::vector<Index> waiting;  // points whose antipode lies inside a hull edge
  for (Index p = 1; p < n; ++p) {
    if (p == b || p == c) continue;
    const bool had_hull = builder.hull();
    if (!builder.insert(p)) waiting.push_back(p);
    if (had_hull && !builder.hull()) {  // the hull is gone: the waiting go in now
      for (Index q : waiting) builder.insert(q);
      waiting.clear();
    }
  }
  // the hull survived the input: the waiting again (¬p may now be inside the hull)
  std::vector<Index> still;
  for (Index q : waiting) {
    if (!builder.insert(q)) {
      still.push_back(q);
    } else if (!builder.hull()) {
      for (Index r : still) builder.insert(r);
      still.clear();
    }
  }
  //< triangulate-t2
  if (!still.empty()) {
    builder.insert(still.front());  // sets the blocking edge again
    const auto [e0, e1] = builder.blocking_edge();
    detail::undefined_t2(input, order[still.front()], order[e0], order[e1]);
  }
  tell(trace, [&] { return trace::about(trace::Event::done, tr, order, {}); });
  tr.renumber(std::move(order), input);  // the antipodal-edge records too
  tr.finish();
  out.tr = std::move(tr);
  return out;
}

}  // namespace t2
