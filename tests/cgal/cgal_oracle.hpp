#pragma once
// CGAL as the oracle of the tests, behind a plain interface: t2 points in, input indices out.
// CGAL's headers are compiled once, into the library t2_cgal_oracle (cgal_oracle.cpp), and not
// into each test that asks it; no CGAL type crosses this header. CGAL is never a dependency of
// the t2 library itself.
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "t2/hull3d/facets.hpp"
#include "t2/kernel/number.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/segment.hpp"
#include "t2/triangulation/triangulation.hpp"

namespace t2::testing::cgal {

/// CGAL::convex_hull_2 of front points with the exact kernel (Epeck, each point (x/w, y/w) as
/// exact rationals): the strict hull vertices counter-clockwise, each given as the index of the
/// first input point it equals.
std::vector<std::size_t> hull_2(const std::vector<Point>& P);

/// The convex layers of front points by their definition: CGAL's hull (as in hull_2), then every
/// point equal to one of its vertices removed, again and again. Each layer as input indices.
std::vector<std::vector<std::size_t>> layers_2(const std::vector<Point>& P);

/// CGAL's Delaunay_triangulation_2 (Epick) of front points with w = 1: its finite triangles
/// counter-clockwise, smallest index first, sorted; an index dropped by `duplicates` (t2's
/// (dropped, kept) pairs) is written as the kept one.
std::vector<std::array<Triangulation::Index, 3>> delaunay_triangles(
    const std::vector<Point>& pts, const std::vector<std::pair<Triangulation::Index, Triangulation::Index>>& duplicates);

/// What CGAL's `Delaunay_triangulation_2::locate` (Epick, front points with w = 1) answers
/// for one query: the kind (0 in a face, 1 on an edge, 2 on a vertex, 3 outside the hull) and
/// the input indices of the face's, edge's or vertex's vertices, sorted.
struct DelaunayLocation {
  int kind = 3;                                 ///< 0 face, 1 edge, 2 vertex, 3 outside
  std::vector<Triangulation::Index> vertices;  ///< sorted input indices
  /// Same kind and vertices.
  friend bool operator==(const DelaunayLocation&, const DelaunayLocation&) = default;
};

/// CGAL's Delaunay triangulation of distinct front points `pts` (w = 1) and its `locate` of
/// each query (Cartesian x/w, y/w).
std::vector<DelaunayLocation> delaunay_locate(const std::vector<Point>& pts, const std::vector<Point>& queries);

/// CGAL::convex_hull_3 (Epick, into a Surface_mesh) of distinct points: its triangles as input
/// indices, each rotated to start at its smallest index, sorted. Throws std::runtime_error if a
/// face is not a triangle.
std::vector<Triangle3> hull_3(const std::vector<Point3>& P);

/// CGAL::compute_intersection_points (the surface sweep, report_endpoints = false) of front
/// segments with the exact kernel (Epeck, each endpoint (x/w, y/w) as exact rationals): the
/// points where segments meet, as exact Cartesian (X, Y), sorted, each once.
std::vector<std::array<Rational, 2>> intersection_points_2(const std::vector<Segment>& segments);

/// The smallest enclosing circle of front points by CGAL::Min_circle_2 (Min_circle_2_traits_2
/// on the exact kernel Epeck, each point (x/w, y/w) as exact rationals): its centre and squared
/// radius, exactly.
struct MinCircle {
  std::array<Rational, 2> center;  ///< (X, Y)
  Rational radius2;                ///< the squared radius
};
MinCircle min_circle_2(const std::vector<Point>& P);

}  // namespace t2::testing::cgal
