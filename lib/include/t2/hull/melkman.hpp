#pragma once
/// @file melkman.hpp
/// @brief Melkman's algorithm: the hull of a simple polygon in linear time (chapter 07).
///
/// A simple polygon's vertices are no arbitrary set: the boundary never crosses itself, and
/// that order makes the hull a linear-time job (the Ω(n log n) lower bound of chapter 06 is for
/// points in any order). Melkman (1987) keeps the hull of the chain v₀ … v_{i−1} in a deque
/// D = d_b … d_t whose two ends are the same vertex, the last one added.
///
/// **Invariant.** D, read from d_b to d_t, is the hull of v₀ … v_{i−1} counter-clockwise, and
/// d_b = d_t is a vertex of it that the chain reached last.
///
/// **Why a vertex v inside the two end wedges can be skipped.** If v is left of d_{t−1} → d_t
/// and left of d_b → d_{b+1} (or on those segments), it lies in the hull so far or in a pocket
/// behind one of those two edges (the region between the chain and a hull edge): the pocket is
/// closed off by the chain, and a simple polygon cannot leave it except through d_t, so every
/// later vertex until the chain comes out again is inside too. Otherwise v sees the hull from
/// outside; the edges it sees form one chain around d_t = d_b, popped from both ends (Graham's
/// test, on the top and on the bottom), and v is pushed on both ends. Each vertex is pushed at
/// most twice and popped at most twice: O(n).
///
/// Only orientation tests are used, so it runs unchanged on any polygon of T² that lies in an
/// open hemisphere (the antipodal map reverses Δ, so a polygon on the back side comes out
/// counter-clockwise in T², which is clockwise as drawn).

#include <cstddef>
#include <span>
#include <vector>

#include "t2/hull/traits.hpp"
#include "t2/hull/merge.hpp"

namespace t2 {

namespace detail {

// For collinear u, v, p (u ≠ ±v): p lies on the closed segment u v of T². With c off the line,
// p = αu + βv has sign α = Δ(p, v, c) and sign β = Δ(u, p, c).
template <class K>
bool on_collinear_segment(const Point& u, const Point& v, const Point& p) {
  const Point c = left_axis<K>(u, v);
  return K::orient(p, v, c) >= 0 && K::orient(u, p, c) >= 0;
}

}  // namespace detail

/// The hull of a simple polygon P (vertices in order, either orientation) by Melkman's
/// algorithm: the indices of the strict hull vertices, counter-clockwise in T². O(n).
/// Preconditions: P is simple and lies in an open hemisphere (every front-only polygon does;
/// `polygon_hull` checks the hemisphere). Repeated consecutive vertices are allowed. Degenerate
/// polygons (fewer than three distinct vertices, or all collinear) give their point or segment.
template <class K = HullTraits, class Tr = NoTrace>
std::vector<std::size_t> melkman(std::span<const Point> P, Tr&& trace = {}) {
  std::vector<std::size_t> v;  // the vertices, repeated neighbours dropped
  for (std::size_t i = 0; i < P.size(); ++i)
    if (v.empty() || !K::equal(P[v.back()], P[i])) v.push_back(i);
  while (v.size() > 1 && K::equal(P[v.back()], P[v.front()])) v.pop_back();
  std::size_t k = 2;  // the first vertex off the line v0 v1
  while (k < v.size() && K::orient(P[v[0]], P[v[1]], P[v[k]]) == ZERO) ++k;
  if (k >= v.size()) {  // a point or a segment: the extremes of a line, by insertion
    std::vector<std::size_t> H;
    for (std::size_t i : v) insert_into_hull<K>(P, H, i);
    return H;
  }
  //> melkman
  // A simple chain along one line is monotone: v0 and v[k-1] are the ends of the first run.
  const std::size_t a = v[0], b = v[k - 1], c = v[k];
  std::vector<std::size_t> D(2 * v.size() + 1);
  // D[bot..top], d_bot = d_top = the last vertex
  std::size_t bot = v.size(), top = bot + 3;
  if (K::orient(P[a], P[b], P[c]) > 0) {
    D[bot] = c, D[bot + 1] = a, D[bot + 2] = b, D[top] = c;
  } else {
    D[bot] = c, D[bot + 1] = b, D[bot + 2] = a, D[top] = c;
  }
  const auto deque = [&] {
    return std::span<const std::size_t>(D.data() + bot, top - bot + 1);
  };
  // p is inside the hull as seen from edge u → w: strictly left of it, or on the segment.
  const auto inside = [&](std::size_t u, std::size_t w, std::size_t p) {
    const Sign s = K::orient(P[u], P[w], P[p]);
    return s > 0 || (s == 0 && detail::on_collinear_segment<K>(P[u], P[w], P[p]));
  };
  for (std::size_t i = k + 1; i < v.size(); ++i) {
    const std::size_t p = v[i];
    tell(trace, trace::Event::consider, {p}, deque());
    // in a pocket
    if (inside(D[top - 1], D[top], p) && inside(D[bot], D[bot + 1], p)) continue;
    while (K::orient(P[D[top - 1]], P[D[top]], P[p]) <= 0) {
      tell(trace, trace::Event::pop, {D[top]}, deque());
      --top;
    }
    D[++top] = p;
    tell(trace, trace::Event::push, {p}, deque());
    while (K::orient(P[p], P[D[bot]], P[D[bot + 1]]) <= 0) {
      tell(trace, trace::Event::pop, {D[bot]}, deque());
      ++bot;
    }
    D[--bot] = p;
    tell(trace, trace::Event::push, {p}, deque());
  }
  //< melkman
  return {D.begin() + static_cast<std::ptrdiff_t>(bot), D.begin() + static_cast<std::ptrdiff_t>(top)};
}

/// The hull of a simple polygon: `melkman` after checking that P lies in an open hemisphere
/// when some vertex is not on the front side (that check is `merge_hull`, O(n log n); front-only
/// polygons skip it and take O(n)). Throws `NoHull` when there is no hemisphere.
template <class K = HullTraits>
std::vector<std::size_t> polygon_hull(std::span<const Point> P) {
  for (const Point& p : P)
    if (p.w() <= 0) {
      merge_hull<K>(P);  // throws NoHull naming the points
      break;
    }
  return melkman<K>(P);
}

}  // namespace t2
