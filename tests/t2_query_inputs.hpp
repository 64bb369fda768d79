#pragma once
// Inputs of the T² query tests (test_locate_t2.cpp, test_nearest_t2.cpp): random points with
// small integer coordinates on the sides asked for.
#include <cstddef>
#include <random>
#include <vector>

#include "t2/kernel/point.hpp"

namespace t2::testing {

/// n points [w, x, y] with w drawn from `ws` (1 front, −1 back, 0 on Ω) and x, y in
/// [−side, side]: small grids give duplicates, antipodal pairs, collinear and cocircular points.
inline std::vector<Point> side_points(std::size_t n, const std::vector<int>& ws, int side, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> d(-side, side);
  std::uniform_int_distribution<std::size_t> pick(0, ws.size() - 1);
  std::vector<Point> p;
  while (p.size() < n) {
    const int w = ws[pick(rng)], x = d(rng), y = d(rng);
    if (w == 0 && x == 0 && y == 0) continue;  // not a point
    p.emplace_back(w, x, y);
  }
  return p;
}

}  // namespace t2::testing
