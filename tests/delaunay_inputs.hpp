#pragma once
// Point sets for the Delaunay tests (front points, w = 1): t2::gen's kinds, and the exact
// degeneracies gen does not make (a full grid without repetition, many integer points exactly on
// one circle, Kettner et al.'s classroom example).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "t2/gen/generate.hpp"
#include "t2/kernel/point.hpp"

namespace t2::testing {

/// n points of a t2::gen kind (uniform, normal with `clusters` clusters, rounded circle...).
inline std::vector<Point> gen_points(gen::Kind kind, std::size_t n, std::uint64_t seed, std::size_t clusters = 4) {
  gen::Options o;
  o.n = n;
  o.seed = seed;
  o.clusters = clusters;
  o.cartesian = true;  // circle: rounded Cartesian points, w = 1, the same points for CGAL
  return gen::points(kind, o);
}

/// The integer grid of about n points (side ⌈√n⌉), shuffled: massively cocircular.
inline std::vector<Point> grid_points(std::size_t n, std::uint64_t seed) {
  const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(double(n))));
  std::vector<Point> out;
  out.reserve(side * side);
  for (std::size_t i = 0; i < side; ++i)
    for (std::size_t j = 0; j < side; ++j) out.push_back(Point::cartesian(double(i), double(j)));
  std::shuffle(out.begin(), out.end(), std::mt19937_64(seed));
  return out;
}

/// Every integer point on the circle x² + y² = 5²·13²·17²·29² (4·3⁴ = 324 points, exactly
/// cocircular), plus `inner` integer points strictly inside, shuffled.
inline std::vector<Point> lattice_circle_points(std::size_t inner, std::uint64_t seed) {
  const std::int64_t r2 = 5LL * 5 * 13 * 13 * 17 * 17 * 29 * 29, r = std::llround(std::sqrt(double(r2)));
  std::vector<Point> out;
  for (std::int64_t x = -r; x <= r; ++x) {
    const std::int64_t y2 = r2 - x * x;
    const auto y = static_cast<std::int64_t>(std::llround(std::sqrt(double(y2))));
    if (y * y != y2) continue;
    out.push_back(Point::cartesian(double(x), double(y)));
    if (y != 0) out.push_back(Point::cartesian(double(x), double(-y)));
  }
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::int64_t> u(-r / 2, r / 2);
  for (std::size_t k = 0; k < inner; ++k) {
    const double x = double(u(rng));
    out.push_back(Point::cartesian(x, double(u(rng))));
  }
  std::shuffle(out.begin(), out.end(), rng);
  return out;
}

/// The "classroom example" of Kettner, Mehlhorn, Pion, Schirra and Yap ("Classroom examples of
/// robustness problems in geometric computations", 2008): a k×k grid of points a few ulps apart
/// near (0.5, 0.5), with (12, 12) and (24, 24) on their diagonal line — floating-point orient and
/// in-circle tests give inconsistent answers on it.
inline std::vector<Point> classroom_points(int k) {
  std::vector<Point> out;
  const double ulp = std::nextafter(0.5, 1.0) - 0.5;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) out.push_back(Point::cartesian(0.5 + i * ulp, 0.5 + j * ulp));
  out.push_back(Point::cartesian(12, 12));
  out.push_back(Point::cartesian(24, 24));
  out.push_back(Point::cartesian(24, 12));  // one point off the line, so that triangles exist
  return out;
}

}  // namespace t2::testing
