#pragma once
/// @file spatial_sort.hpp
/// @brief An insertion order for incremental constructions: a biased randomized insertion order
/// (BRIO, Amenta, Choi and Rote 2003) whose rounds are sorted along a Hilbert curve, as CGAL's
/// `spatial_sort` does (Delage's median Hilbert sort inside Multiscale_sort).
///
/// The points are shuffled (a fixed seed: the order is deterministic), then the last 3/4 of the
/// sequence is sorted along a Hilbert curve and the first 1/4 is treated the same way,
/// recursively. Consecutive points are then near each other, so the walk that locates the next
/// point from the last triangle is short, and each round is still a random sample of the whole,
/// which keeps the expected O(n log n) bound of the randomized incremental construction.
///
/// The *median* Hilbert sort splits at medians (std::nth_element) instead of at the middle of a
/// box, so that clustered input splits as evenly as uniform input. The sort uses rounded
/// Cartesian coordinates: the order only affects speed, never the result.

#include <algorithm>
#include <cstdint>
#include <random>
#include <span>
#include <vector>

#include "t2/point.hpp"

namespace t2 {

namespace detail {

/// A point of the spatial sort: coordinates rounded to float (12 bytes a key, so the sort moves
/// half the memory of double keys; the order only affects speed) and the input index.
struct SortKey {
  float c[2];           ///< rounded Cartesian (or normalized) coordinates
  std::uint32_t index;  ///< the input index
};

/// The median of [b, e) in coordinate `coord`, ascending if `up`: nth_element, returns the middle.
template <int coord, bool up>
SortKey* hilbert_split(SortKey* b, SortKey* e) {
  if (b >= e) return b;
  SortKey* m = b + (e - b) / 2;
  std::nth_element(b, m, e, [](const SortKey& p, const SortKey& q) {
    return up ? p.c[coord] < q.c[coord] : p.c[coord] > q.c[coord];
  });
  return m;
}

/// Sorts [begin, end) along a Hilbert curve whose first split is on coordinate `x` in
/// direction `up_x`, the second on the other coordinate in direction `up_y` (CGAL's
/// Hilbert_sort_median_2, with the directions as template arguments).
template <int x, bool up_x, bool up_y>
void hilbert_sort(SortKey* begin, SortKey* end) {
  constexpr int y = 1 - x;
  if (end - begin <= 4) return;  // CGAL's threshold: tiny runs stay in random order
  SortKey* m2 = hilbert_split<x, up_x>(begin, end);
  SortKey* m1 = hilbert_split<y, up_y>(begin, m2);
  SortKey* m3 = hilbert_split<y, !up_y>(m2, end);
  hilbert_sort<y, up_y, up_x>(begin, m1);
  hilbert_sort<x, up_x, up_y>(m1, m2);
  hilbert_sort<x, up_x, up_y>(m2, m3);
  hilbert_sort<y, !up_y, !up_x>(m3, end);
}

/// BRIO rounds: sort the last 3/4 along the curve, recurse on the first quarter.
inline void brio_sort(SortKey* begin, SortKey* end) {
  constexpr std::ptrdiff_t threshold = 16;
  SortKey* middle = begin;
  if (end - begin > threshold) {
    middle = begin + (end - begin) / 4;
    brio_sort(begin, middle);
  }
  hilbert_sort<0, true, true>(middle, end);
}

}  // namespace detail

//> spatial-order
/// The BRIO–Hilbert insertion order of `points` (a permutation of their indices). Front points
/// are sorted by their Cartesian coordinates, others by their normalized ones.
inline std::vector<std::uint32_t> spatial_order(std::span<const Point> points, std::uint64_t seed = 0x7432u) {
  std::vector<detail::SortKey> keys(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Point& p = points[k];
    const double s = p.w() != 0 ? p.w() : std::max(std::fabs(p.x()), std::fabs(p.y()));
    keys[k] = {{static_cast<float>(p.x() / s), static_cast<float>(p.y() / s)}, static_cast<std::uint32_t>(k)};
  }
  std::mt19937_64 rng(seed);
  for (std::size_t k = keys.size(); k > 1; --k)  // Fisher–Yates, the same on every platform
    std::swap(keys[k - 1], keys[rng() % k]);
  detail::brio_sort(keys.data(), keys.data() + keys.size());
  std::vector<std::uint32_t> order(keys.size());
  for (std::size_t k = 0; k < keys.size(); ++k) order[k] = keys[k].index;
  return order;
}
//< spatial-order

/// Moves the points back from an insertion `order` (a permutation of their indices), in place:
/// afterwards points[order[m]] is the old points[m]; `order` is used as scratch space.
///
/// Following the cycles of the permutation would need no memory, but it is a chase through a
/// random permutation, one cache miss after the other (50 to 110 ms at 10⁶ points against 18). Instead
/// the destinations are cut into 8 ranges, filled from the top: the points bound for the lowest
/// range go to a buffer (1/8 of the points, 3 bytes a point), the others are compacted to the
/// front, which frees the top range; then, while points remain, those bound for the free range
/// are written there (sources and destinations never overlap) and the rest compacted again,
/// which frees the next range down; the buffer goes last. Each pass reads the remaining points
/// in order and scatters one range: about 2.5 reads and one write per point, all independent.
inline void unpermute(std::vector<Point>& points, std::vector<std::uint32_t>& order) {
  const std::size_t n = points.size();
  if (n == 0) return;
  const std::size_t lo = (n + 7) / 8;  // destinations [0, lo) go through the buffer
  std::vector<Point> low(lo, points.front());
  std::size_t live = 0;  // points[0, live) are still to place, bound for order[0, live)
  for (std::size_t m = 0; m < n; ++m) {
    const std::uint32_t d = order[m];
    if (d < lo) {
      low[d] = points[m];
    } else {
      points[live] = points[m];
      order[live++] = d;
    }
  }
  // Invariant: the points bound for [lo, hi) are points[0, live), live = hi − lo, and
  // points[live, n) is free or final; the free range [live, hi) receives its own points.
  for (std::size_t hi = n; hi > lo;) {
    const std::size_t from = std::max(lo, live);
    std::size_t keep = 0;
    for (std::size_t m = 0; m < live; ++m) {
      const std::uint32_t d = order[m];
      if (d >= from) {
        points[d] = points[m];
      } else {
        points[keep] = points[m];
        order[keep++] = d;
      }
    }
    hi = from;
    live = keep;
  }
  std::copy(low.begin(), low.end(), points.begin());
}

}  // namespace t2
