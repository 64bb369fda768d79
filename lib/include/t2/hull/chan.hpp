#pragma once
/// @file chan.hpp
/// @brief Chan's output-sensitive hull in a chart of T²: O(n log h).
///
/// The points are dealt into groups of m; Graham's scan gives each group's hull; then Jarvis's
/// march wraps the whole set, asking each group hull for its tangent from the current vertex u
/// by a binary search, O(log m) orientation tests. If the wrap has not closed after m vertices,
/// h > m: m is squared (m = 2^(2^t)) and all starts again. Round t costs O(n log m_t) =
/// O(n 2^t), and the rounds stop once m_t ≥ h, so the total is O(n log h) (chapter 06).
///
/// **The tangent.** From u, a strict vertex of the whole set, the next hull vertex is the point q
/// with no point strictly right of u → q, the farthest on the line u q if several (Jarvis's
/// rule). On a group hull C = c_0 … c_{k−1} (strict, counter-clockwise) it is the least vertex
/// for the *key* order "c before d when Δ(u, c, d) > 0, or Δ(u, c, d) = 0 and c is farther from
/// u", with a vertex equal to u last of all. All of C other than u lies in an open half-plane
/// through u (u is a strict vertex), so this is a strict total order on C's vertices, and the keys
/// are cyclically unimodal along C: they rise along the edges with u strictly left (and along the
/// edge of the far tangent through u), fall along the others. `detail::tangent` finds the least
/// key by a binary search over 1 … k−1 on a predicate that the unimodality makes monotone.

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

#include "t2/hull/graham.hpp"
#include "t2/hull/traits.hpp"

namespace t2 {

namespace detail {

/// The vertex of the convex polygon C (strict vertices, counter-clockwise, in `order`'s chart)
/// that Jarvis's march goes to from u: the least in the key order of chan.hpp's comment; u must
/// be a strict vertex of the hull of C ∪ {u}. Returns an index into C, or C.size() when C has
/// no vertex but u. O(log |C|) orientation tests.
template <class K>
std::size_t tangent(std::span<const Point> P, const std::vector<std::size_t>& C, const Point& u,
                    const ChartOrder<K>& order) {
  const std::size_t k = C.size();
  if (k == 0 || (k == 1 && K::equal(P[C[0]], u))) return k;
  if (k == 1) return 0;
  //> chan-tangent
  // before(a, b): the key of c_a comes before that of c_b (u's own vertex comes last)
  const auto before = [&](std::size_t a, std::size_t b) {
    const Point &c = P[C[a % k]], &d = P[C[b % k]];
    if (K::equal(c, u)) return false;
    if (K::equal(d, u)) return true;
    const Sign s = K::orient(u, c, d);
    return s != ZERO ? s > 0 : order.farther(u, d, c);  // one ray: the farther first
  };
  const auto down = [&](std::size_t i) { return before(i + 1, i); };  // edge i falls
  const bool down0 = down(0);
  // after(i): c_i is the least key or comes after it along 1 … k−1 (monotone in i)
  const auto after = [&](std::size_t i) {
    return down0 ? !down(i) || before(0, i) : !down(i) && before(i, 0);
  };
  std::size_t lo = 1, hi = k;  // the first i in [lo, hi) with after(i), or hi
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (after(mid)) hi = mid;
    else lo = mid + 1;
  }
  return lo == k ? 0 : lo;
  //< chan-tangent
}

}  // namespace detail

/// Chan's algorithm on the points P[i], i in `idx`, in `chart`: the strict hull vertices,
/// counter-clockwise from the first in the chart's order (as `graham` and `jarvis`). O(n log h)
/// for h hull vertices. The trace hears each group's hull (`group_hull`), then each vertex of the
/// round's wrap and the tangents from it (a round that fails is followed by the next round's
/// groups), or Graham's steps when a round has one group (m ≥ n: that group's hull is all).
template <class K = HullTraits, class Tr = NoTrace>
std::vector<std::size_t> chan(std::span<const Point> P, const std::vector<std::size_t>& idx, const Chart& chart,
                              Tr&& trace = {}) {
  const ChartOrder<K> order{chart};
  const std::size_t n = idx.size();
  if (n == 0) return {};
  const std::size_t start = *std::min_element(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) {
    return order.less(P[a], P[b]);  // the first in the chart's order is a vertex
  });
  std::vector<std::size_t> hull;
  //> chan-wrap
  for (std::size_t m = 4;; m = m >= n / m ? n : m * m) {  // m = 2^(2^t), at most n
    if (m >= n) return graham<K>(P, idx, chart, trace);  // one group: its hull is all
    std::vector<std::vector<std::size_t>> groups;        // each group's hull
    for (std::size_t g = 0; g < n; g += m) {
      const auto first = idx.begin() + static_cast<std::ptrdiff_t>(g);
      const auto last = idx.begin() + static_cast<std::ptrdiff_t>(std::min(n, g + m));
      groups.push_back(graham<K>(P, std::vector<std::size_t>(first, last), chart));
      tell(trace, [&] {
        trace::Report r = trace::about(trace::Event::group_hull, {}, groups.back());
        r.through = {&*first, static_cast<std::size_t>(last - first)};  // its points
        return r;
      });
    }
    hull.clear();
    std::size_t u = start;
    for (std::size_t step = 0; step < m; ++step) {  // at most m vertices this round
      hull.push_back(u);
      tell(trace, trace::Event::vertex, {u}, hull);
      std::size_t q = u;  // the best tangent point so far (none while q = u)
      for (const auto& C : groups) {
        const std::size_t j = detail::tangent<K>(P, C, P[u], order);
        if (j == C.size()) continue;  // this group is u alone
        const std::size_t c = C[j];
        tell(trace, trace::Event::tangent, {u, c}, hull);
        if (q == u) {
          q = c;
          continue;
        }
        const Sign s = K::orient(P[u], P[q], P[c]);
        if (s < 0 || (s == 0 && order.farther(P[u], P[q], P[c])))
          q = c;  // Jarvis's rule
      }
      if (q == u || K::equal(P[q], P[start]))
        return hull;  // the wrap closed
      u = q;
    }
  }  // h > m: square m
  //< chan-wrap
}

}  // namespace t2
