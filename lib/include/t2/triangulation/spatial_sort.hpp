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

/// Sorts [begin, end) along a Hilbert curve whose first split is on coordinate `x` in
/// direction `up_x`, the second on the other coordinate in direction `up_y`.
inline void hilbert_sort(SortKey* begin, SortKey* end, int x, bool up_x, bool up_y) {
  if (end - begin <= 4) return;  // CGAL's threshold: tiny runs stay in random order
  const int y = 1 - x;
  auto split = [](SortKey* b, SortKey* e, int coord, bool up) {
    if (b >= e) return b;
    SortKey* m = b + (e - b) / 2;
    if (up)
      std::nth_element(b, m, e, [coord](const SortKey& p, const SortKey& q) { return p.c[coord] < q.c[coord]; });
    else
      std::nth_element(b, m, e, [coord](const SortKey& p, const SortKey& q) { return p.c[coord] > q.c[coord]; });
    return m;
  };
  SortKey* m2 = split(begin, end, x, up_x);
  SortKey* m1 = split(begin, m2, y, up_y);
  SortKey* m3 = split(m2, end, y, !up_y);
  hilbert_sort(begin, m1, y, up_y, up_x);
  hilbert_sort(m1, m2, x, up_x, up_y);
  hilbert_sort(m2, m3, x, up_x, up_y);
  hilbert_sort(m3, end, y, !up_y, !up_x);
}

/// BRIO rounds: sort the last 3/4 along the curve, recurse on the first quarter.
inline void brio_sort(SortKey* begin, SortKey* end) {
  constexpr std::ptrdiff_t threshold = 16;
  SortKey* middle = begin;
  if (end - begin > threshold) {
    middle = begin + (end - begin) / 4;
    brio_sort(begin, middle);
  }
  hilbert_sort(middle, end, 0, true, true);
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

}  // namespace t2
