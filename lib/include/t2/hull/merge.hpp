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
    const Point& p = P[i];
    const Sign lex =
        p.w() != 0 ? sign_of(p.w()) : (p.x() != 0 ? sign_of(p.x()) : sign_of(p.y()));
    if (lex > 0) {
      pos.push_back(i);
    } else {
      neg.push_back(i);
      flipped.push_back(antipode(p));
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
  for (std::size_t q : H2) insert_into_hull<K>(P, H, q, trace);  // the bridges
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
