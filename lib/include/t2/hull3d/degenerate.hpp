#pragma once
/// @file degenerate.hpp
/// @brief The affine dimension of a set of points of R³, exactly: equal, collinear and coplanar
/// points, and the first four affinely independent points (the start of every 3-D hull).
///
/// Three points of R³ are collinear iff their projections to the three coordinate planes are
/// collinear (the cross product (q − p) × (r − p) has those three orientations as components), so
/// collinearity costs three exact planar orientations and no construction.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "t2/kernel/orient3d.hpp"
#include "t2/kernel/detail/orient_double.hpp"

namespace t2 {

/// True when p and q have the same coordinates (so 0 and −0 are the same).
inline bool same_point(const Point3& p, const Point3& q) { return p.x == q.x && p.y == q.y && p.z == q.z; }

/// True when p, q, r lie on one line (or two of them are equal): exact.
inline bool collinear(const Point3& p, const Point3& q, const Point3& r) {
  using detail::orient2;
  return orient2(p.x, p.y, q.x, q.y, r.x, r.y) == ZERO && orient2(p.y, p.z, q.y, q.z, r.y, r.z) == ZERO &&
         orient2(p.z, p.x, q.z, q.x, r.z, r.x) == ZERO;
}

/// The first four affinely independent points of `points`, visited in the order `order`
/// (indices into points): the first point, the first one different from it, the first one off
/// their line, the first one off their plane. Throws `Undefined` when there is no such
/// quadruple, saying why: no point, all points equal, all collinear, all coplanar.
std::array<std::uint32_t, 4> first_simplex(std::span<const Point3> points, std::span<const std::uint32_t> order);

/// The indices of the distinct points, each the smallest index among the points equal to it,
/// sorted lexicographically by (x, y, z). O(n log n).
std::vector<std::uint32_t> distinct_points(std::span<const Point3> points);

/// Throws `BadInput` naming the first point with a NaN or infinite coordinate.
void require_finite(std::span<const Point3> points);

}  // namespace t2
