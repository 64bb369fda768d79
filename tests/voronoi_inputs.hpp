#pragma once
// Random sites for the Delaunay complex and Voronoi tests (test_delaunay_complex.cpp,
// test_voronoi.cpp), on one side w of T².
#include <random>
#include <vector>

#include "t2/kernel/point.hpp"

namespace t2::testing {

/// n sites on an even grid of 2·side + 1 values a coordinate, on side w: duplicates, collinear
/// and cocircular sites are frequent.
inline std::vector<Point> grid_sites(std::size_t n, int side, double w, std::mt19937& rng) {
  std::uniform_int_distribution<int> d(-side, side);
  std::vector<Point> p;
  for (std::size_t k = 0; k < n; ++k) p.push_back(Point(w, w * 2 * d(rng), w * 2 * d(rng)));
  return p;
}

/// n sites with random double coordinates in [−1, 1]² on side w (general position in practice).
inline std::vector<Point> scattered_sites(std::size_t n, double w, std::mt19937& rng) {
  std::uniform_real_distribution<double> d(-1, 1);
  std::vector<Point> p;
  for (std::size_t k = 0; k < n; ++k) p.push_back(Point(w, w * d(rng), w * d(rng)));
  return p;
}

}  // namespace t2::testing
