// The affine dimension of a point set of R³: the first simplex, the distinct points.
#include "t2/hull3d/degenerate.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "t2/kernel/error.hpp"

namespace t2 {

std::array<std::uint32_t, 4> first_simplex(std::span<const Point3> P, std::span<const std::uint32_t> order) {
  const auto n = std::to_string(order.size());
  if (order.empty()) throw Undefined("no 3-D hull: there is no point");
  const std::uint32_t a = order[0];
  auto it = std::find_if(order.begin(), order.end(), [&](std::uint32_t q) { return !same_point(P[q], P[a]); });
  if (it == order.end()) throw Undefined("no 3-D hull: all " + n + " points are equal");
  const std::uint32_t b = *it;
  it = std::find_if(it, order.end(), [&](std::uint32_t q) { return !collinear(P[a], P[b], P[q]); });
  if (it == order.end()) throw Undefined("no 3-D hull: all " + n + " points are collinear");
  const std::uint32_t c = *it;
  it = std::find_if(it, order.end(), [&](std::uint32_t q) { return orient3d(P[a], P[b], P[c], P[q]) != ZERO; });
  if (it == order.end()) throw Undefined("no 3-D hull: all " + n + " points are coplanar");
  return {a, b, c, *it};
}

std::vector<std::uint32_t> distinct_points(std::span<const Point3> P) {
  std::vector<std::uint32_t> id(P.size());
  std::iota(id.begin(), id.end(), 0u);
  auto key = [&](std::uint32_t i) { return std::array<double, 3>{P[i].x, P[i].y, P[i].z}; };
  std::sort(id.begin(), id.end(), [&](std::uint32_t i, std::uint32_t j) {
    const auto a = key(i), b = key(j);
    return a != b ? a < b : i < j;
  });
  id.erase(std::unique(id.begin(), id.end(), [&](std::uint32_t i, std::uint32_t j) { return same_point(P[i], P[j]); }),
           id.end());
  return id;
}

void require_finite(std::span<const Point3> P) {
  for (std::size_t i = 0; i < P.size(); ++i)
    if (!std::isfinite(P[i].x) || !std::isfinite(P[i].y) || !std::isfinite(P[i].z))
      throw BadInput("point " + std::to_string(i) + " has a coordinate that is not a finite number");
}

}  // namespace t2
