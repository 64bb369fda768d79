#pragma once
/// @file facets.hpp
/// @brief From a triangulated convex surface to the facets of the hull: coplanar neighbours
/// merged, points inside facets and edges dropped, and the canonical form that makes the
/// answers of different algorithms comparable.
///
/// **The rule for degenerate input** (every 3-D hull of the library follows it). The hull of
/// points not all coplanar is a convex polyhedron; its *vertices* are the strict extreme points
/// (a point inside a facet or in the interior of an edge is none), of equal points the one of
/// smallest index; its *facets* are the maximal planar faces, each a strictly convex polygon
/// listed counter-clockwise seen from outside. The *canonical form* rotates each facet to start at
/// its smallest index and sorts the facets; a facet with more than three vertices is then
/// triangulated as the fan from its first vertex, so the triangles are canonical too.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "t2/hull3d/polyhedron.hpp"

namespace t2 {

/// Facets of a 3-D hull: index cycles into the input points, counter-clockwise from outside.
using Facets = std::vector<std::vector<std::uint32_t>>;
/// A triangle of a 3-D hull: three indices, counter-clockwise from outside.
using Triangle3 = std::array<std::uint32_t, 3>;

/// The facets of a closed convex surface given as outward triangles on `points`: triangles
/// across an edge whose four points are coplanar (exact) are merged, and polygon vertices
/// collinear with their two neighbours are dropped. The result is in canonical form.
Facets merge_coplanar(std::span<const Point3> points, const std::vector<Triangle3>& triangles);

/// Rotates each facet to its smallest index and sorts the facets (the canonical form).
void canonicalize(Facets& facets);

/// The fan triangulation of canonical facets, sorted: (f₀, f_k, f_{k+1}) for each facet f.
std::vector<Triangle3> fan_triangles(const Facets& facets);

/// The polyhedron of the facets: its vertices are the points the facets use, in increasing
/// index order, and the faces are renumbered accordingly.
Polyhedron polyhedron_of(std::span<const Point3> points, const Facets& facets);

}  // namespace t2
