#pragma once
/// @file lift.hpp
/// @brief The lifting map (x, y) ↦ (x, y, x² + y²): the lower hull of the lifted points projects
/// to the Delaunay triangulation (chapter 10).
///
/// **Why.** For the circle C of centre (a, b) and radius r, a point lies inside C iff
/// x² + y² < 2ax + 2by + r² − a² − b², i.e. iff its lift lies below the plane
/// z = 2ax + 2by + (r² − a² − b²). The lifts of the points on C lie on that plane. So a triangle
/// has an empty circumcircle iff the plane of its lifted vertices has no lifted point below it:
/// iff it is a facet of the lower hull (the outward normal points down).
///
/// **Exactness.** The lift is a construction: x² + y² must be a double for the 3-D predicates to
/// decide about the true paraboloid. `lift` checks it (with fused multiply-adds, exact) and
/// throws `Undefined` otherwise; coordinates that are integers below 2²⁶ in absolute value, or
/// such integers times one power of two, always lift exactly.

#include <array>
#include <span>
#include <vector>

#include "t2/hull3d/facets.hpp"
#include "t2/kernel/point.hpp"

namespace t2 {

/// The lift (x, y, x² + y²) of a Cartesian point [1, x, y]. Throws `Undefined` when w ≠ 1 or
/// when x² + y² is not exactly a double.
Point3 lift(const Point& p);

/// The Delaunay triangulation of the points by the lifting map: the lower facets of the 3-D
/// hull of the lifts (facets with more than three vertices — cocircular points — fan
/// triangulated), as triangles counter-clockwise in the plane, each rotated to its smallest
/// index, sorted. Throws `Undefined` when a point does not lift exactly or when the lifts are
/// coplanar (all points on one line or one circle).
std::vector<Triangle3> delaunay_by_lifting(std::span<const Point> points);

}  // namespace t2
