#pragma once
/// @file quickhull.hpp
/// @brief Quickhull in a chart of T²: divide at an extreme point, recurse on the outer parts.
///
/// Seed 000's Algorithm 7 (Quick_Hull_Aux) has two slips: its line 8 follows the `return` of
/// line 7 and is never reached (the two recursive answers must be concatenated, with h between
/// them), and it has no case for an empty set (which every recursion reaches: a side with no
/// point), only for one point. It also picks h by the largest area of the triangle l h r, a
/// Euclidean measure that T² lacks; here h is the extreme point in a direction chosen in the
/// chart, which is a hull vertex whatever the direction, so the answer is exact and only the
/// balance of the division depends on the choice.

#include <cmath>
#include <span>
#include <vector>

#include "t2/hull/traits.hpp"

namespace t2 {

namespace detail {

// The point of S ∪ {a, b} extreme in a direction: `before(p, q)` says q is further than p in
// it (a strict weak order of a linear functional in the chart), ties broken by the chart order
// so that the winner is a strict vertex. Returns an index of S, or npos when a or b wins.
template <class K, class Before>
std::size_t extreme_of(std::span<const Point> P, const std::vector<std::size_t>& S, std::size_t a, std::size_t b,
                       const ChartOrder<K>& order, Before before) {
  std::size_t best = a;
  auto further = [&](std::size_t p, std::size_t q) {
    const Sign s = before(P[p], P[q]);
    return s != ZERO ? s > 0 : order.less(P[p], P[q]);
  };
  if (further(best, b)) best = b;
  bool in_s = false;
  for (std::size_t i : S)
    if (further(best, i)) best = i, in_s = true;
  return in_s && best != a && best != b ? best : static_cast<std::size_t>(-1);
}

// The vertices strictly between a and b of the hull chain right of a → b through S (the
// points strictly right of a → b), in order from a to b.
template <class K, class Tr>
void quickhull_side(std::span<const Point> P, std::size_t a, std::size_t b, const std::vector<std::size_t>& S,
                    const Chart& chart, std::vector<std::size_t>& out, Tr& trace) {
  //> hull-quickhull
  if (S.empty()) return;  // the case the seed forgets
  const ChartOrder<K> order{chart};
  std::size_t h = static_cast<std::size_t>(-1);
  // farthest right of the line a b: with d = b − a (a direction, on Ω), q is farther right
  // than p when q − p turns clockwise from d, i.e. orient(p, q, d) > 0 (p, q in front)
  if (chart.front) {
    // rounded: any direction will do, if finite
    const Point &A = P[a], &B = P[b];
    const double dx = B.x() * A.w() - A.x() * B.w(), dy = B.y() * A.w() - A.y() * B.w();
    if (std::isfinite(dx) && std::isfinite(dy) && (dx != 0 || dy != 0)) {
      const Point d(0, dx, dy);
      h = extreme_of<K>(P, S, a, b, order,
                        [&](const Point& p, const Point& q) {
                          return K::orient(p, q, d);
                        });
    }
  }
  // Extreme in x, −x, y, −y.
  for (int axis = 0; axis < 4 && h == static_cast<std::size_t>(-1); ++axis) {
    h = extreme_of<K>(P, S, a, b, order, [&](const Point& p, const Point& q) {
      const Sign s =
          axis < 2 ? -orient_to<K>(p, q, chart.y_inf) : orient_to<K>(q, p, chart.x_inf);
      return axis % 2 == 0 ? s : -s;
    });
  }
  // A gift-wrapping step from a always finds a vertex.
  if (h == static_cast<std::size_t>(-1)) {
    h = S[0];
    for (std::size_t i : S) {
      const Sign s = K::orient(P[a], P[h], P[i]);
      if (s < 0 || (s == 0 && order.farther(P[a], P[h], P[i]))) h = i;
    }
  }
  tell(trace, trace::Event::vertex, {h}, out);
  std::vector<std::size_t> S1, S2;
  for (std::size_t i : S) {
    if (K::orient(P[a], P[h], P[i]) < 0) S1.push_back(i);
    else if (K::orient(P[h], P[b], P[i]) < 0) S2.push_back(i);
  }
  quickhull_side<K>(P, a, h, S1, chart, out, trace);
  out.push_back(h);
  quickhull_side<K>(P, h, b, S2, chart, out, trace);
  //< hull-quickhull
}

}  // namespace detail

/// Quickhull on the points P[i], i in `idx`, in `chart`: the strict hull vertices,
/// counter-clockwise from the first in the chart's order. O(n log n) on average, O(nh) at worst.
template <class K = HullTraits, class Tr = NoTrace>
std::vector<std::size_t> quickhull(std::span<const Point> P, const std::vector<std::size_t>& idx, const Chart& chart,
                                   Tr&& trace = {}) {
  const ChartOrder<K> order{chart};
  if (idx.empty()) return {};
  std::size_t l = idx[0], r = idx[0];
  for (std::size_t i : idx) {
    if (order.less(P[i], P[l])) l = i;
    if (order.less(P[r], P[i])) r = i;
  }
  if (K::equal(P[l], P[r])) return {l};
  std::vector<std::size_t> below, above;
  for (std::size_t i : idx) {
    const Sign s = K::orient(P[l], P[r], P[i]);
    if (s < 0) below.push_back(i);
    else if (s > 0) above.push_back(i);
  }
  std::vector<std::size_t> hull{l};
  detail::quickhull_side<K>(P, l, r, below, chart, hull, trace);
  hull.push_back(r);
  detail::quickhull_side<K>(P, r, l, above, chart, hull, trace);
  return hull;
}

}  // namespace t2
