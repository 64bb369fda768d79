#pragma once
/// @file graham.hpp
/// @brief Graham's scan in a chart of T²: sort around a vertex, then pop the right turns.

#include <algorithm>
#include <span>
#include <vector>

#include "t2/hull/traits.hpp"

namespace t2 {

/// Graham's scan on the points P[i], i in `idx`, in `chart`: the strict hull vertices,
/// counter-clockwise from the first in the chart's order. O(n log n).
///
/// The pivot o, the first point in the chart's order, is a hull vertex, and every other point
/// lies in the half-turn of directions (−90°, 90°] from it in the chart's image, so Δ(o, a, b)
/// orders them by angle (a before b when b lies left of o → a). Points on one ray from o come
/// nearest first, except on the last ray, where they come farthest first: then the scan pops
/// every point inside a hull edge, including those of the closing edge back to o.
template <class K = HullTraits, class Tr = NoTrace>
std::vector<std::size_t> graham(std::span<const Point> P, const std::vector<std::size_t>& idx, const Chart& chart,
                                Tr&& trace = {}) {
  const ChartOrder<K> order{chart};
  if (idx.empty()) return {};
  std::size_t o = idx[0];
  for (std::size_t i : idx)
    if (order.less(P[i], P[o])) o = i;
  std::vector<std::size_t> rest;
  for (std::size_t i : idx)
    if (!K::equal(P[i], P[o])) rest.push_back(i);
  //> hull-graham
  const Point& O = P[o];
  std::sort(rest.begin(), rest.end(), [&](std::size_t a, std::size_t b) {
    const Sign s = K::orient(O, P[a], P[b]);
    return s != ZERO ? s > 0
                     : order.farther(O, P[a], P[b]);  // by angle, then nearest first
  });
  auto last = rest.end();  // the last ray from o: farthest first
  while (last != rest.begin() && K::orient(O, P[*(last - 1)], P[rest.back()]) == ZERO)
    --last;
  if (last != rest.begin()) std::reverse(last, rest.end());
  std::vector<std::size_t> stack{o};
  for (std::size_t i : rest) {
    tell(trace, trace::Event::consider, {i}, stack);
    while (stack.size() >= 2 &&
           K::orient(P[stack[stack.size() - 2]], P[stack.back()], P[i]) <= 0) {
      tell(trace, trace::Event::pop, {stack.back()}, stack);
      stack.pop_back();
    }
    stack.push_back(i);
    tell(trace, trace::Event::push, {i}, stack);
  }
  while (stack.size() >= 3 &&
         K::orient(P[stack[stack.size() - 2]], P[stack.back()], O) <= 0) {
    tell(trace, trace::Event::pop, {stack.back()}, stack);  // closing edge
    stack.pop_back();
  }
  //< hull-graham
  return stack;
}

}  // namespace t2
