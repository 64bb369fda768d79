#pragma once
/// @file monotone.hpp
/// @brief Andrew's monotone chain in a chart of T², and the Akl–Toussaint throw-away.

#include <algorithm>
#include <span>
#include <vector>

#include "t2/hull/kernel.hpp"

namespace t2 {

namespace detail {

// One chain of the monotone chain: pops the points that do not turn left, pushes the next.
template <class K, class Tr>
void chain_step(std::span<const Point> P, std::vector<std::size_t>& h, std::size_t floor, std::size_t i, Tr& trace) {
  while (h.size() >= floor + 2 && K::orient(P[h[h.size() - 2]], P[h.back()], P[i]) <= 0) {
    trace(HullStep::pop, h.back(), h);
    h.pop_back();
  }
  h.push_back(i);
  trace(HullStep::push, i, h);
}

}  // namespace detail

/// Andrew's monotone chain on the points P[i], i in `idx`, in the chart `chart` (kernel.hpp):
/// the indices of the strict hull vertices, counter-clockwise, starting at the first in the
/// chart's order. O(n log n). The points must lie where the chart is valid.
template <class K = ExactKernel, class Tr = NoTrace>
std::vector<std::size_t> monotone_chain(std::span<const Point> P, std::vector<std::size_t> idx, const Chart& chart,
                                        Tr&& trace = {}) {
  //> hull-monotone
  const ChartOrder<K> order{chart};
  std::sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return order.less(P[a], P[b]); });
  idx.erase(std::unique(idx.begin(), idx.end(),
                        [&](std::size_t a, std::size_t b) { return order.compare(P[a], P[b]) == ZERO; }),
            idx.end());
  if (idx.size() < 3) return idx;  // no point, one point, or a segment
  std::vector<std::size_t> h;
  h.reserve(idx.size() + 1);
  for (std::size_t i : idx) detail::chain_step<K>(P, h, 0, i, trace);  // lower chain, left to right
  const std::size_t lower = h.size() - 1;                               // the upper chain keeps it
  for (auto it = idx.rbegin() + 1; it != idx.rend(); ++it) detail::chain_step<K>(P, h, lower, *it, trace);
  h.pop_back();  // the first point again
  //< hull-monotone
  return h;
}

/// The Akl–Toussaint throw-away before the monotone chain: the extreme points in x and y
/// (in the chart's order) span a quadrilateral; the points strictly inside it are no hull
/// vertices and are dropped in one pass of four Δ each. Same answer as `monotone_chain`.
template <class K = ExactKernel, class Tr = NoTrace>
std::vector<std::size_t> akl_toussaint(std::span<const Point> P, const Chart& chart, Tr&& trace = {}) {
  const ChartOrder<K> order{chart};
  std::vector<std::size_t> keep;
  if (P.empty()) return keep;
  // The extremes: least and greatest in (x, y), least and greatest in (y, x).
  std::size_t e[4] = {0, 0, 0, 0};
  const auto yx = [&](const Point& p, const Point& q) {
    // (y, x) order: y by Δ(q, p, X∞), then x.
    const Sign s = chart.front && p.w() == 1 && q.w() == 1
                       ? (p.y() < q.y() ? NEGATIVE : (p.y() > q.y() ? POSITIVE : ZERO))
                       : orient_to<K>(p, q, chart.x_inf);
    return s != ZERO ? s : order.compare(p, q);
  };
  for (std::size_t i = 1; i < P.size(); ++i) {
    if (order.less(P[i], P[e[0]])) e[0] = i;
    if (order.less(P[e[2]], P[i])) e[2] = i;
    if (yx(P[i], P[e[1]]) < 0) e[1] = i;
    if (yx(P[e[3]], P[i]) < 0) e[3] = i;
  }
  // Counter-clockwise: leftmost, lowest, rightmost, highest; repeated corners dropped.
  std::vector<std::size_t> q;
  for (std::size_t c : e)
    if (q.empty() || !K::equal(P[q.back()], P[c])) q.push_back(c);
  while (q.size() > 1 && K::equal(P[q.back()], P[q.front()])) q.pop_back();
  keep.reserve(P.size() / 2);
  if (q.size() < 3) {
    for (std::size_t i = 0; i < P.size(); ++i) keep.push_back(i);
  } else {
    for (std::size_t i = 0; i < P.size(); ++i) {
      bool inside = true;
      for (std::size_t k = 0; k < q.size() && inside; ++k)
        inside = K::orient(P[q[k]], P[q[(k + 1) % q.size()]], P[i]) > 0;
      if (!inside) keep.push_back(i);
    }
  }
  return monotone_chain<K>(P, std::move(keep), chart, trace);
}

}  // namespace t2
