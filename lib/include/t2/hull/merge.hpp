#pragma once
/// @file merge.hpp
/// @brief Hull existence and the merge of the hemisphere hulls (seed 000, Algorithms 3 and 4).
///
/// **Theorem.** A finite set A of T² has a convex hull iff it lies in an open hemisphere, i.e.
/// iff no nonnegative combination of its points (as vectors of R³), not all zero, is 0.
///
/// The set is split by the sign of [w, x, y] in the lexicographic order: A₁, the positive points
/// (the front side and the half of Ω with x > 0, or x = 0 < y), and A₂, the negative ones. Both
/// A₁ and ¬A₂ are positive, so both lie in the open hemisphere w + εx + ε²y > 0 (ε > 0 small)
/// and have hulls, built in that symbolic chart (`lex_chart`). The hull of A₂ is the antipode of
/// the hull of ¬A₂, read backwards: the antipodal map reverses Δ. A then has a hull iff the two
/// hulls can be merged (Algorithm 3 tests whether CH(A₁) meets CH(¬A₂): a common point
/// Σλa = Σμ(¬b) is exactly a vanishing combination Σλa + Σμb = 0).
///
/// The merge inserts the vertices of CH(A₂) into CH(A₁) one at a time. A point q joins a convex
/// polygon H (in an open hemisphere) by the signs s_i = Δ(h_i, h_{i+1}, q) of its edges:
/// all s_i ≥ 0: q lies in H, nothing changes; all s_i ≤ 0: ¬q lies in H, so H ∪ {q} has no hull;
/// otherwise the edges with s_i ≤ 0 form one chain, whose inner vertices leave, and q is joined
/// to its two ends: these two edges are the bridges of Algorithm 4 (figure 5.3), here found
/// by orientation tests alone, even when they cross Ω. (Why all s_i ≤ 0 means ¬q ∈ H: a convex
/// polygon of three or more vertices is the intersection of its edges' half-planes.)
///
/// **The bridge walk.** Inserting each q by a scan of every edge costs O(h₁h₂) in all, quadratic
/// for points on a circle on both sides. The merge (`merge_halves`) inserts the vertices
/// q₁, …, q_m of CH(A₂) counter-clockwise, q₁ by a full scan, and then looks at three edges of
/// the hull so far Hₖ = CH(A₁ ∪ {q₁, …, qₖ}), its *anchors*: the two edges between the halves
/// (the run of vertices of A₂ on Hₖ begins after one and ends before the other) and qₖ → q₁
/// when it is an edge of Hₖ. From the first anchor with s ≤ 0 it walks both ways while s ≤ 0.
/// E = ⟨1, ε, ε²⟩ below is the line of Algorithm 3: A₁ strictly on its positive side, A₂ on its
/// negative side.
///
/// *Lemma (anchors).* Let Hₖ have three or more vertices, k ≥ 1, let H_{k+1} exist and
/// q = q_{k+1} ∉ Hₖ. Then the chain of edges with s ≤ 0 contains an anchor. Proof. (i) Hₖ has a
/// vertex in each half: q₁ ∉ CH(A₁), which lies on the other side of E, so some vertex is in A₂;
/// a polygon with vertices in A₂ only lies on the negative side of E and cannot hold A₁ ≠ ∅.
/// (ii) Two vertices of A₂ consecutive on Hₖ are consecutive in q₁, …, qₖ: a q_c between them
/// would lie strictly right of the edge (CH(A₂) is strictly convex), yet it lies in Hₖ. So an
/// edge of Hₖ inside A₂ is an edge of the polygon q₁ … qₖ, and q lies strictly left of all of
/// them but qₖ → q₁ (strict convexity again): their s is positive. (iii) If the chain held no
/// anchor, by (ii) all its edges would join two points of A₁, and so would q's two new edges;
/// the vertices of A₂ on Hₖ, not inner to the chain, stay, and by (i) there is one. Round
/// H_{k+1} the side of E would change at least four times: against the two bridges of the
/// chapter (§7, "why exactly two bridges", for H_{k+1}, which exists). ∎
///
/// *Theorem.* `merge_halves` returns CH(A) when it exists and throws `NoHull` when it does not,
/// after at most 2h₁ + 7h₂ orientation tests (and O(h₁ + h₂) more to name the witnesses). Proof.
/// By induction the ring is Hₖ (with the ends of its run) after step k; step k + 1, for q =
/// q_{k+1}, has three cases. ¬q ∈ Hₖ (H_{k+1} does not exist): every s ≤ 0, so the first anchor
/// qualifies and the walk goes round: `no_hull`. q ∈ Hₖ: every s ≥ 0, so every anchor has s > 0,
/// or the walk from one meets zeros only: nothing changes, as in `insert_into_hull`. Otherwise
/// the edges with s ≤ 0 form one chain (insert_into_hull), which holds an anchor (the lemma), and
/// the walk finds all of it: the same change as `insert_into_hull`. The run: after q joins
/// between x and y, q begins it when x ∈ A₁; else the old beginning stays, for if it had left,
/// the walk would have passed the edge before it and gone back over vertices of A₁ only, to a
/// vertex of A₁ unless all of them left, against (i). Likewise the end. Cost: q₁ costs max(h₁, 6)
/// tests, and so does each insertion while the hull is a point or a segment (`insert_into_hull`
/// on two vertices makes at most 6). Then each step costs at most three tests at the anchors, two
/// that stop the walk and one for each inner vertex of the chain, which leaves for good: at most
/// h₁ + h₂ leave. In all at most max(h₁, 6) + 6(h₂ − 1) + h₁ + h₂ ≤ 2h₁ + 7h₂. ∎
///
/// The degenerate cases need nothing apart. Collinear points: an edge with s = 0 is walked, so a
/// vertex between two edges collinear with q leaves (strict vertices), and a q on the boundary
/// changes nothing; while the hull is a point or a segment `insert_into_hull` decides in O(1).
/// Points on Ω: the split is lexicographic, and the walk uses orientation tests only. Antipodal
/// pairs: ¬q ∈ Hₖ is the first case. One half empty: no merge.

#include <algorithm>
#include <numeric>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "t2/hull/traits.hpp"
#include "t2/hull/monotone.hpp"

namespace t2 {

namespace detail {

// The sign of [w, x, y] in the lexicographic order: the split of Algorithm 3.
inline Sign lex_sign(const Point& p) {
  return p.w() != 0 ? sign_of(p.w()) : (p.x() != 0 ? sign_of(p.x()) : sign_of(p.y()));
}

// A point of {±[1,0,0], ±[0,1,0], ±[0,0,1]} strictly left of u → v (u ≠ ±v): one exists, since
// Δ(u, v, e_k) is the k-th coefficient of the line u ∨ v, which is not zero.
template <class K>
Point left_axis(const Point& u, const Point& v) {
  const Point axes[3] = {Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)};
  for (const Point& e : axes) {
    const Sign s = K::orient(u, v, e);
    if (s != ZERO) return s > 0 ? e : antipode(e);
  }
  throw Undefined("left_axis: the points are equal or antipodal");
}

// Why ¬q lies in the hull polygon H (all edge signs ≤ 0): the points that prove it.
template <class K>
[[noreturn]] void no_hull(std::span<const Point> P, const std::vector<std::size_t>& H, std::size_t q) {
  const Point nq = antipode(P[q]);
  for (std::size_t v : H)
    if (K::equal(P[v], nq))
      throw NoHull(point_name(v) + " and " + point_name(q) + " are antipodal: no open hemisphere holds both", {v, q});
  const std::size_t m = H.size();
  for (std::size_t i = 0; i < m && m >= 3; ++i)
    if (K::orient(P[H[i]], P[H[(i + 1) % m]], nq) == ZERO)
      throw NoHull("the antipode of " + point_name(q) + " lies on the segment " + point_name(H[i]) + " " +
                       point_name(H[(i + 1) % m]) + ": no open hemisphere holds the three",
                   {H[i], H[(i + 1) % m], q});
  if (m == 2)
    throw NoHull("the antipode of " + point_name(q) + " lies on the segment " + point_name(H[0]) + " " +
                     point_name(H[1]) + ": no open hemisphere holds the three",
                 {H[0], H[1], q});
  for (std::size_t k = 1; k + 1 < m; ++k)  // the fan triangle h0 h_k h_{k+1} that holds ¬q
    if (K::orient(P[H[0]], P[H[k]], nq) >= 0 && K::orient(P[H[0]], P[H[k + 1]], nq) <= 0)
      throw NoHull("the antipode of " + point_name(q) + " lies in the triangle " + point_name(H[0]) + " " +
                       point_name(H[k]) + " " + point_name(H[k + 1]) + ": no open hemisphere holds the four",
                   {H[0], H[k], H[k + 1], q});
  throw NoHull("no open hemisphere holds the points", H);
}

// The trace of the chain of ¬A₂, whose indices point into the antipodes: it tells `trace` the
// input indices (`to[k]` for k). The monotone chain's stack changes by one push or one pop
// between two steps, so only its top is renumbered again: O(1) a step. It is made only when a
// trace listens: for NoTrace, `renumbered` is NoTrace again.
template <class Tr>
struct Renumbered {
  Tr& trace;
  std::span<const std::size_t> to;
  std::vector<std::size_t> chain;
  void operator()(const trace::Report& r) {
    chain.resize(r.chain.size());
    if (!r.chain.empty()) chain.back() = to[r.chain.back()];
    trace::Report out = r;
    for (std::size_t& i : out.at)
      if (i != trace::Report::none) i = to[i];
    out.chain = chain;
    trace(out);
  }
};

template <class Tr>
auto renumbered(Tr& trace, std::span<const std::size_t> to) {
  if constexpr (!trace::traced<Tr>)
    return NoTrace{};
  else
    return Renumbered<Tr>{trace, to, {}};
}

}  // namespace detail

/// Adds the point P[q] to the convex polygon H (strict vertices, counter-clockwise, in an
/// open hemisphere; 0, 1 or 2 vertices allowed): H becomes the hull of H ∪ {q}. Throws
/// `NoHull` naming the points when there is none.
template <class K = HullTraits, class Tr = NoTrace>
void insert_into_hull(std::span<const Point> P, std::vector<std::size_t>& H, std::size_t q, Tr&& trace = {}) {
  const Point& Q = P[q];
  if (H.empty()) {
    H.push_back(q);
    return;
  }
  if (H.size() == 1) {
    if (K::equal(P[H[0]], Q)) return;
    if (K::equal(P[H[0]], antipode(Q))) detail::no_hull<K>(P, H, q);
    H.push_back(q);
    return;
  }
  if (H.size() == 2) {
    const Point &U = P[H[0]], &V = P[H[1]];
    const Sign o = K::orient(U, V, Q);
    if (o != ZERO) {
      H.insert(o > 0 ? H.end() : H.begin() + 1, q);
      return;
    }
    // q on the line u v: q = αu + βv with sign α = Δ(q, v, c), sign β = Δ(u, q, c).
    const Point c = detail::left_axis<K>(U, V);
    const Sign a = K::orient(Q, V, c), b = K::orient(U, Q, c);
    if (a >= 0 && b >= 0) return;                   // q on the segment u v
    if (a <= 0 && b <= 0) detail::no_hull<K>(P, H, q);  // ¬q on it
    H[a > 0 ? 0 : 1] = q;                           // u (or v) lies between q and the other
    return;
  }
  //> hull-insert
  const std::size_t m = H.size();
  std::vector<Sign> s(m);
  bool some_positive = false, some_negative = false;
  for (std::size_t i = 0; i < m; ++i) {
    s[i] = K::orient(P[H[i]], P[H[(i + 1) % m]], Q);
    some_positive = some_positive || s[i] > 0;
    some_negative = some_negative || s[i] < 0;
  }
  if (!some_negative) return;                             // q in H
  if (!some_positive) detail::no_hull<K>(P, H, q);         // ¬q in H
  std::size_t i = 0;  // the first edge of the chain s ≤ 0
  while (!(s[(i + m - 1) % m] > 0 && s[i] <= 0)) ++i;
  std::size_t j = i;                                      // the first edge after it
  while (s[j % m] <= 0) ++j;
  std::vector<std::size_t> kept;                          // h_j, ..., h_i, then q
  for (std::size_t k = j; k <= i + m; ++k) kept.push_back(H[k % m]);
  tell(trace, trace::Event::bridge, {q}, kept);
  kept.push_back(q);
  H = std::move(kept);
  //< hull-insert
}

/// Merges the hull of the negative half into the hull of the positive half, in time linear in
/// their sizes (the file comment: the bridge walk). H is CH(A₁), not empty; H2 lists the
/// strict vertices of CH(A₂), counter-clockwise; H becomes the hull of both, or `NoHull` is
/// thrown. The trace hears one `Event::bridge` per vertex of H2 that joins, as
/// `insert_into_hull` tells it.
template <class K = HullTraits, class Tr = NoTrace>
void merge_halves(std::span<const Point> P, std::vector<std::size_t>& H, std::span<const std::size_t> H2,
                  Tr&& trace = {}) {
  // q₁ by a full scan, then the next ones while the hull is a point or a segment: O(h₁ + 1 + …).
  std::size_t k = 0;
  while (k < H2.size() && (k == 0 || H.size() < 3)) insert_into_hull<K>(P, H, H2[k++], trace);
  if (k == H2.size()) return;
  //> hull-bridge-walk
  // The hull so far as a ring: node i < h is the vertex H[i], later nodes the q's to come.
  const std::size_t h = H.size(), none = static_cast<std::size_t>(-1);
  std::vector<std::size_t> pt(H), next(h), prev(h);
  std::vector<char> negative(h), alive(h, 1);
  std::size_t start = none, end = none;  // the first and the last vertex of the run of A₂
  std::size_t tail = none, head = none;  // the nodes of q_k and q₁, when they are in H
  for (std::size_t i = 0; i < h; ++i) {
    next[i] = (i + 1) % h, prev[i] = (i + h - 1) % h;
    negative[i] = detail::lex_sign(P[H[i]]) < 0;
    if (H[i] == H2[k - 1]) tail = i;
    if (H[i] == H2[0]) head = i;
  }
  for (std::size_t i = 0; i < h; ++i) {
    if (negative[i] && !negative[prev[i]]) start = i;
    if (negative[i] && !negative[next[i]]) end = i;
  }
  const auto ring = [&](std::size_t from, std::size_t to) {  // the points from → to
    std::vector<std::size_t> r;
    for (std::size_t v = from;; v = next[v]) {
      r.push_back(pt[v]);
      if (v == to) return r;
    }
  };
  std::size_t size = h, last = none;  // last: the node that joined last
  for (; k < H2.size(); ++k) {
    const Point& Q = P[H2[k]];
    const auto s = [&](std::size_t u) { return K::orient(P[pt[u]], P[pt[next[u]]], Q); };
    const std::size_t q = pt.size();
    pt.push_back(H2[k]), next.push_back(none), prev.push_back(none);
    negative.push_back(1), alive.push_back(0);
    // The anchors, edges u → next[u]: into the run, out of it, and q_k → q₁ if in H.
    const bool closes = tail != none && head != none && tail != head && alive[tail] &&
                        alive[head] && next[tail] == head;
    std::size_t u = none;
    Sign su = ZERO;
    for (std::size_t c : {prev[start], end, closes ? tail : none}) {
      if (c != none && (su = s(c)) <= 0) {
        u = c;
        break;
      }
    }
    tail = q;
    if (u == none) continue;  // every anchor has q on its left: q lies in H
    // The chain of the edges with s ≤ 0 through the anchor: from x to y.
    std::size_t x = u, y = next[u], edges = 1;
    bool outside = su < 0;
    for (Sign t; edges < size && (t = s(prev[x])) <= 0; ++edges) {
      outside = outside || t < 0;
      x = prev[x];
    }
    for (Sign t; edges < size && (t = s(y)) <= 0; ++edges) {
      outside = outside || t < 0;
      y = next[y];
    }
    if (edges == size) detail::no_hull<K>(P, ring(next[x], x), H2[k]);  // ¬q lies in H
    if (!outside) continue;  // q lies on the boundary of H
    if constexpr (trace::traced<Tr>) tell(trace, trace::Event::bridge, {H2[k]}, ring(y, x));
    for (std::size_t v = next[x]; v != y; v = next[v]) {  // the inner vertices leave
      alive[v] = 0;
      --size;
    }
    next[x] = q, prev[q] = x, next[q] = y, prev[y] = q, alive[q] = 1, ++size, last = q;
    if (!negative[x]) start = q;  // else the old start stays (the file comment)
    if (!negative[y]) end = q;
  }
  //< hull-bridge-walk
  if (last != none) H = ring(next[last], last);  // else no q joined: H is unchanged
}

/// The hull of P by Algorithms 3 and 4 (the file comment): hulls of the positive and negative
/// halves in the lexicographic chart, then their merge. The strict vertices, counter-clockwise;
/// throws `NoHull` when the points lie in no open hemisphere. The trace hears the monotone
/// chain of each half (the negative one on the antipodes, with input indices), each half's
/// hull (`Event::positive_half`, `negative_half`, the strict vertices counter-clockwise as the
/// chain) and the bridges.
template <class K = HullTraits, class Tr = NoTrace>
std::vector<std::size_t> merge_hull(std::span<const Point> P, Tr&& trace = {}) {
  //> hull-merge
  std::vector<std::size_t> pos, neg;
  std::vector<Point> flipped;  // ¬A₂, in the order of neg
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (detail::lex_sign(P[i]) > 0) {
      pos.push_back(i);
    } else {
      neg.push_back(i);
      flipped.push_back(antipode(P[i]));
    }
  }
  std::vector<std::size_t> H = monotone_chain<K>(P, pos, lex_chart(), trace);  // CH(A₁)
  tell(trace, trace::Event::positive_half, {}, H);
  std::vector<std::size_t> local(neg.size());
  std::iota(local.begin(), local.end(), std::size_t{0});
  std::vector<std::size_t> H2 =  // CH(¬A₂), traced with input indices
      monotone_chain<K>(flipped, local, lex_chart(), detail::renumbered(trace, neg));
  std::reverse(H2.begin(), H2.end());  // CH(A₂): antipodes, clockwise read backwards
  for (std::size_t& k : H2) k = neg[k];
  tell(trace, trace::Event::negative_half, {}, H2);
  if (H.empty()) return H2;
  merge_halves<K>(P, H, H2, trace);  // the bridges, in O(h₁ + h₂)
  //< hull-merge
  return H;
}

/// A chart (traits.hpp) valid for every point of P: the plain one when all are on the front
/// side, else one built from an edge of the hull found by `merge_hull` (which throws `NoHull`
/// when there is no hull). `hull` receives that hull when it was computed (else it is empty).
template <class K = HullTraits>
Chart chart_for(std::span<const Point> P, std::vector<std::size_t>& hull) {
  hull.clear();
  if (std::all_of(P.begin(), P.end(), [](const Point& p) { return p.w() > 0; })) return front_chart();
  hull = merge_hull<K>(P);
  if (hull.size() < 2) return front_chart();  // one point: no chart is needed
  const Point &v0 = P[hull[0]], &v1 = P[hull[1]];
  return edge_chart(v0, v1, detail::left_axis<K>(v0, v1));
}

// The default instantiations are compiled once, in lib/src/hull/convex_hull.cpp.
#ifndef T2_FILTER_STATS  // a program that counts the exact stages compiles its own copy
/// @cond INSTANTIATIONS
extern template std::vector<std::size_t> merge_hull<HullTraits, NoTrace>(std::span<const Point>, NoTrace&&);
extern template std::vector<std::size_t> merge_hull<HullTraits, NoTrace&>(std::span<const Point>, NoTrace&);
extern template Chart chart_for<HullTraits>(std::span<const Point>, std::vector<std::size_t>&);
/// @endcond
#endif

}  // namespace t2
