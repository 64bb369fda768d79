#pragma once
// Exercise 09: the API you implement in triangulate.cpp. Do not change this file.
#include <vector>

#include <t2/kernel/point.hpp>

namespace ex09 {

/// A triangulation of the front points P (w > 0; no two equal; not all on one line): a flat list
/// of point indices, three per triangle, each triangle counter-clockwise (t2::orient > 0, exact),
/// the triangles covering the convex hull of P exactly once, and every point of P a vertex —
/// also a point inside a hull edge. Any triangulation is accepted, in any order.
std::vector<long> triangulate(const std::vector<t2::Point>& P);

}  // namespace ex09
