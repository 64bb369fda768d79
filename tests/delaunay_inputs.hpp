#pragma once
// Point sets for the Delaunay tests and benchmark (front points, w = 1). Written here because
// the generators module t2::gen of Part II had not landed when these were written.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "t2/point.hpp"

namespace t2::testing {

/// n points whose coordinates are independent draws of `dist`.
template <class Dist>
std::vector<Point> sample_points(std::size_t n, std::uint64_t seed, Dist dist) {
  std::mt19937_64 rng(seed);
  std::vector<Point> out;
  out.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double x = dist(rng);
    out.push_back(Point::cartesian(x, dist(rng)));
  }
  return out;
}

/// n points uniform in the square [-1, 1]².
inline std::vector<Point> uniform_points(std::size_t n, std::uint64_t seed) {
  return sample_points(n, seed, std::uniform_real_distribution<double>(-1, 1));
}

/// n points of a standard normal distribution.
inline std::vector<Point> normal_points(std::size_t n, std::uint64_t seed) {
  return sample_points(n, seed, std::normal_distribution<double>(0, 1));
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

/// n points on the unit circle, rounded (nearly, not exactly, cocircular), shuffled.
inline std::vector<Point> circle_points(std::size_t n, std::uint64_t seed) {
  std::vector<Point> out;
  out.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double a = 2 * M_PI * double(k) / double(n);
    out.push_back(Point::cartesian(std::cos(a), std::sin(a)));
  }
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

/// Clusters: n points in 32 small normal clusters of random centres and spreads.
inline std::vector<Point> clustered_points(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::normal_distribution<double> g(0, 1);
  std::vector<std::array<double, 3>> centres(32);
  for (auto& c : centres) c = {u(rng), u(rng), std::pow(10.0, -1 - 3 * (u(rng) + 1) / 2)};
  std::vector<Point> out;
  out.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const auto& c = centres[k % centres.size()];
    const double x = c[0] + c[2] * g(rng);
    out.push_back(Point::cartesian(x, c[1] + c[2] * g(rng)));
  }
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
