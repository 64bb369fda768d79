#pragma once
/// @file chart_sort.hpp
/// @brief The points of a hull algorithm with their indices, sorted in a chart's order without
/// repeats; a bucket sort first when the order is plain (x, y) on doubles.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "t2/hull/traits.hpp"

namespace t2::detail {

/// A point with its input index: the monotone chain sorts and scans these, contiguous in
/// memory, rather than indices into the input (which cost a cache miss per comparison).
struct Indexed {
  Point p;        ///< the point
  std::size_t i;  ///< its index in the input
};

/// The points P[i], i in `idx`, with their indices, sorted by the chart's order; of equal
/// points the first in the sorted order is kept. O(n log n).
///
/// For front points with w = 1 (the common case) the order is (x, y) on the doubles themselves
/// (`ChartOrder::compare`), and the points are first dealt into k buckets by
/// b(x) = min(k − 1, ⌊(x − x_min)·s⌋) with s = k / (x_max − x_min), computed in doubles; then each
/// bucket is sorted by (x, y). This is exact: every rounded operation (subtraction of x_min,
/// product by s > 0, the floor, the min) is a non-decreasing function of its argument, so b is
/// non-decreasing in x, and x < x' never puts x' in an earlier bucket. Rounding only moves the
/// bucket boundaries; points with equal x share a bucket, where (x, y) decides. (When the
/// range overflows, s is not a positive finite number and one bucket holds everything.) The
/// buckets, about 128 points each for spread input, fit in the cache: on 10⁷ points on a circle,
/// where nothing can be thrown away, this sort takes about two thirds of the time of one
/// `std::sort` (0.85 s against 1.3 s).
template <class K>
std::vector<Indexed> sorted_in_chart(std::span<const Point> P, const std::vector<std::size_t>& idx,
                                     const ChartOrder<K>& order) {
  std::vector<Indexed> s;
  const std::size_t n = idx.size();
  const std::size_t k = std::min<std::size_t>(n / 128, 65536);  // buckets
  const auto plain = [&] {
    return order.chart.front &&
           std::all_of(idx.begin(), idx.end(), [&](std::size_t i) { return P[i].w() == 1; });
  };
  const auto xy = [](const Indexed& a, const Indexed& b) {
    return a.p.x() < b.p.x() || (a.p.x() == b.p.x() && a.p.y() < b.p.y());
  };
  double lo = 0, scale = 0;
  if (k >= 2 && plain()) {
    const auto [a, b] = std::minmax_element(idx.begin(), idx.end(), [&](std::size_t i, std::size_t j) {
      return P[i].x() < P[j].x();
    });
    lo = P[*a].x();
    scale = double(k) / (P[*b].x() - lo);
  }
  if (scale > 0 && std::isfinite(scale)) {
    const auto bucket = [&](double x) {
      const double u = (x - lo) * scale;
      return u < double(k) ? static_cast<std::size_t>(u) : k - 1;
    };
    std::vector<std::size_t> start(k + 1, 0);  // bucket b holds s[start[b]], ..., s[start[b + 1] − 1]
    for (std::size_t i : idx) ++start[bucket(P[i].x()) + 1];
    for (std::size_t b = 0; b < k; ++b) start[b + 1] += start[b];
    std::vector<std::size_t> next(start.begin(), start.end() - 1);
    s.assign(n, Indexed{P[idx[0]], idx[0]});
    for (std::size_t i : idx) s[next[bucket(P[i].x())]++] = {P[i], i};
    for (std::size_t b = 0; b < k; ++b)
      std::sort(s.begin() + static_cast<std::ptrdiff_t>(start[b]),
                s.begin() + static_cast<std::ptrdiff_t>(start[b + 1]), xy);
  } else {
    s.reserve(n);
    for (std::size_t i : idx) s.push_back({P[i], i});
    std::sort(s.begin(), s.end(), [&](const Indexed& a, const Indexed& b) { return order.less(a.p, b.p); });
  }
  const auto same = [&](const Indexed& a, const Indexed& b) { return order.compare(a.p, b.p) == ZERO; };
  s.erase(std::unique(s.begin(), s.end(), same), s.end());
  return s;
}

}  // namespace t2::detail
