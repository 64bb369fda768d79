#pragma once
/// @file jarvis.hpp
/// @brief Jarvis's march (gift wrapping) in a chart of T²: O(nh).
///
/// The seed (000, Algorithm 5) picks the next vertex by the smallest angle with the horizontal;
/// comparing angles with its Algorithm 1 fails for angles of π, and no angle is needed: q is the
/// next vertex after u when no point lies strictly right of u → q, and, among points on the
/// line u q, q is the farthest (so points inside hull edges are no vertices).

#include <span>
#include <vector>

#include "t2/hull/traits.hpp"

namespace t2 {

/// Jarvis's march on the points P[i], i in `idx`, in `chart`: the strict hull vertices,
/// counter-clockwise from the first in the chart's order. The trace hears each vertex, and each
/// point considered with the candidate before and after it and the sign Δ(u, before, point).
template <class K = HullTraits, class Tr = NoTrace>
std::vector<std::size_t> jarvis(std::span<const Point> P, const std::vector<std::size_t>& idx, const Chart& chart,
                                Tr&& trace = {}) {
  const ChartOrder<K> order{chart};
  std::vector<std::size_t> hull;
  if (idx.empty()) return hull;
  std::size_t start = idx[0];
  for (std::size_t i : idx)
    if (order.less(P[i], P[start])) start = i;  // the first in the order is a vertex
  //> hull-jarvis
  std::size_t u = start;
  do {
    hull.push_back(u);
    tell(trace, trace::Event::vertex, {u}, hull);
    std::size_t q = u;  // no candidate yet
    for (std::size_t i : idx) {
      if (K::equal(P[i], P[u])) continue;
      if (q == u) {
        q = i;
        tell(trace, trace::Event::consider, {i, trace::Report::none, q}, hull);
        continue;
      }
      const Sign s = K::orient(P[u], P[q], P[i]);
      const std::size_t before = q;
      if (s < 0 || (s == 0 && order.farther(P[u], P[q], P[i])))
        q = i;  // i right of u → q, or beyond q
      tell(trace, trace::Event::consider, {i, before, q}, hull, s);  // with Δ(u, before, i)
    }
    u = q;
  } while (!K::equal(P[u], P[start]) && hull.size() <= idx.size());
  //< hull-jarvis
  return hull;
}

}  // namespace t2
