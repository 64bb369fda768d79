#pragma once
/// @file convex_hull_3d.hpp
/// @brief The convex hull of points of R³: gift wrapping (Chand and Kapur; O(nh) for h hull
/// edges) and the incremental algorithm with conflict lists, in random order (Clarkson and
/// Shor; O(n log n) expected) or in Quickhull's order (the farthest point first), all on the
/// exact orientation of four points (orient3d.hpp, seed 004's Volume6).
///
/// Every algorithm returns the same canonical answer (facets.hpp): strict vertices only, of equal
/// points the smallest index, maximal planar facets counter-clockwise from outside. The hull is
/// *undefined* — `Undefined` is thrown — when the points do not span R³: no point, all equal, all
/// collinear or all coplanar (the hull is then no polyhedron: a polygon, a segment, a point).
/// A NaN or infinite coordinate throws `BadInput`.

#include <span>
#include <string_view>
#include <vector>

#include "t2/hull3d/facets.hpp"

namespace t2 {

/// The 3-D hull algorithms (`t2 hull3d --algorithm`).
enum class Hull3dAlgorithm {
  incremental,  ///< randomized incremental with conflict lists (seed 004 §8)
  quickhull,    ///< the same insertion, farthest point of a conflict list first
  gift_wrap,    ///< gift wrapping (seed 004 §7), O(n) per hull edge
};

/// Every 3-D hull algorithm, the default first: the list the command line's choices come from.
inline constexpr Hull3dAlgorithm hull3d_algorithms[] = {Hull3dAlgorithm::quickhull, Hull3dAlgorithm::incremental,
                                                        Hull3dAlgorithm::gift_wrap};

/// The name of an algorithm ("gift-wrap").
std::string_view name(Hull3dAlgorithm a);

/// The facets of the hull of `points` in canonical form (see the file comment).
Facets hull_facets_3d(std::span<const Point3> points, Hull3dAlgorithm a = Hull3dAlgorithm::quickhull);

/// The hull of `points` as outward triangles: the fan triangulation of its canonical facets.
std::vector<Triangle3> convex_hull_3d(std::span<const Point3> points,
                                      Hull3dAlgorithm a = Hull3dAlgorithm::quickhull);

/// The hull as a polyhedron of its own vertices (polyhedron_of the facets).
Polyhedron hull_polyhedron(std::span<const Point3> points, Hull3dAlgorithm a = Hull3dAlgorithm::quickhull);

/// Gift wrapping (see convex_hull_3d.hpp); the facets in canonical form.
Facets gift_wrap_3d(std::span<const Point3> points);

/// The incremental algorithm with conflict lists; `farthest_first` picks Quickhull's order,
/// otherwise a fixed pseudo-random order. The facets in canonical form.
Facets incremental_3d(std::span<const Point3> points, bool farthest_first);

}  // namespace t2
