#pragma once
/// @file triangulate_t2.hpp
/// @brief A triangulation of points anywhere in T² (front, back, on Ω) by the incremental
/// insertion of seed 000, §5.3, Algorithm 9: inside a face, on an edge, outside the hull; the
/// point that destroys the hull takes the place of v∞; the antipode of a hull vertex z joins z
/// by the half great circle along the bisector of the hull angle at z (figures 5.18–5.20).
///
/// **Order.** The points are inserted in `sphere_order` (spatial_sort.hpp: BRIO rounds, each
/// along a Hilbert curve over the six faces of a cube around the sphere), or in input order on
/// request (`InsertionOrder::input`: the seed's order, which its figures 5.18–5.20 are about; a
/// plain triangulation is not unique, and the two orders give different ones). In that order:
/// the first point a, the first point b ≠ ±a, the first point c off the great circle of a and b
/// make the first triangle (with v∞, triangulation.hpp); then every other point, except that a
/// point p whose antipode ¬p lies inside a hull edge waits (see *Undefined*) until the hull is
/// gone, and is inserted right after the point that destroyed it. Of equal points the one of
/// smallest input index is the vertex, whichever comes first.
///
/// **While the hull exists** (the points inserted lie in an open hemisphere, v∞ is a vertex),
/// the walk below locates a new point p from the face of the point before; if it steps into an
/// infinite face, p is strictly outside the hull, and p is compared with every hull edge a → b
/// (interior to its left): let `pos` count the edges with orient(a, b, p) > 0. The closed hull is
/// the intersection of those closed half-planes, so ¬p lies in the closed hull iff pos = 0.
///  - p in the closed hull (the walk ends in a finite face): insert in the face, on the edge, or
///    merge a duplicate.
///  - pos > 0 and p sees some edge strictly: the hull survives. Insert p in the infinite face of
///    such an edge and flip away the reflex angles at p (step 35, `detail::flip_hull_chain`).
///  - pos = 0, ¬p strictly inside the hull: p sees every hull edge strictly; p replaces v∞ in
///    every infinite face (b, a, v∞), which becomes the triangle (b, a, p), counter-clockwise.
///    The triangles now cover the sphere and v∞ is gone for good.
///  - pos = 0, ¬p a hull vertex z (step 31): the same replacement; the two faces (z, u, ¬z) and
///    (w, z, ¬z) at the hull edges u → z and z → w have orient 0 (*lunes*): their common edge
///    z → ¬z is the half great circle leaving z along the bisector of the hull angle u z w,
///    outwards (`AntipodalEdge`; antipodal_edge.hpp proves that this keeps the subdivision
///    planar). A hull edge collinear with z but not at z gives a *flat* face (three vertices on
///    one great circle, no two antipodal, no area), as does every later point inserted on a
///    hull edge of a lune (figure 5.19).
///  - pos = 0, ¬p inside a hull edge: the face (b, a, p) would be bounded by a whole great
///    circle; p waits for the hull to disappear.
///
/// **Once the hull is gone** every point falls inside a face (a proper triangle or a lune), on
/// an edge, or on a vertex; a point on the antipodal edge z → ¬z splits both lunes into four
/// proper triangles (figure 5.20). Point location is a visibility walk with the exact side of
/// every edge (the bisector side for z → ¬z); on the sphere a visibility walk may circle, so
/// after 4·(faces) + 64 steps it gives way to a scan of all faces (which also settles points on
/// flat faces, whose edges overlap). A lune is the intersection of two open hemispheres (its
/// angle is below 180°, antipodal_edge.hpp), so "left of its three edges" is its interior.
///
/// **Running time.** O(n) per point in the worst case (the hull test, a walk of O(n) faces,
/// O(n) flips), O(n²) in all, as the seed says, and in input order that is what random input
/// shows: each walk starts at the previous point, anywhere on the sphere, across the long thin
/// triangles that insertion without flips leaves. In the spatial order a walk starts next to its
/// point, the hull test runs only for points outside the hull, and the walks stay short: 10⁶
/// points in about 1.2–1.7 s, growing as n^1.1–1.2 (bench/bench_triangulate_t2.cpp).
///
/// **Undefined** (throws `t2::Undefined`, exit status 3 of `t2 triangulate`), naming the points:
/// all points on one great circle and in no open half of it (no triangle, and the circle is no
/// hull either); and a point whose antipode lies inside a hull edge of all the others, with no
/// antipodal pair among them: every other point lies in the closed hemisphere of that edge's
/// great circle, the open other half holds no vertex, and no proper triangle or lune with
/// vertices on the circle covers it — the face there would be a hemisphere bounded by the
/// whole circle, which Algorithm 9 cannot make.

#include <span>
#include <vector>

#include "t2/kernel/point.hpp"
#include "t2/triangulation/face_kind.hpp"
#include "t2/triangulation/triangulation.hpp"

namespace t2 {

/// A triangulation of T² input by Algorithm 9. Its antipodal edges are recorded in the
/// triangulation itself (`tr.antipodal_edges()`, face_kind.hpp), as the T² Delaunay's are.
struct TriangulationT2 {
  Triangulation tr;  ///< the faces (lunes and flat faces included) and the antipodal edges
};

/// The order in which `triangulate_t2` inserts the points.
enum class InsertionOrder {
  spatial,  ///< `sphere_order` (spatial_sort.hpp): BRIO rounds along a Hilbert curve on the sphere
  input     ///< the input order, as the seed's Algorithm 9 and its figures 5.18–5.20 take them
};

/// The triangulation of any points of T² by Algorithm 9 (see the file comment), the points
/// inserted in the order `how`: every point is a vertex or a reported duplicate (the vertex is
/// the equal point of smallest input index). Throws `Undefined` in the cases of the file
/// comment, `BadInput` for more than 715 827 882 points.
TriangulationT2 triangulate_t2(std::span<const Point> input, InsertionOrder how = InsertionOrder::spatial);

}  // namespace t2
