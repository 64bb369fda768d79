#pragma once
/// @file voronoi.hpp
/// @brief The Voronoi diagram of sites of T² (seed 000, §5.3.2, Algorithm 11) as the dual of
/// the Delaunay complex (complex.hpp): one cell per distinct site, covering all of T².
///
/// **Vertices.** One per Voronoi vertex: the T² circumcentre of a face of the complex
/// (`circumcentre`, below), in exact homogeneous integer coordinates (no division): w > 0 in
/// front, w < 0 behind, w = 0 on Ω. Adjacent faces with the same circumcentre (cocircular
/// sites) are one vertex, where four or more cells meet; `vertex_sites[v]` lists the sites of
/// its cells counter-clockwise around it (the boundary of its polygon in the complex).
///
/// **Edges.** One per edge of the complex between faces of different vertices: the Voronoi
/// edge from vertex a to vertex b on the bisector of its two sites s and t. No edge has length
/// zero (equal circumcentres are merged). An edge is a T² segment of the bisector: a segment,
/// or a ray or a line of the plane when it crosses Ω. Two distinct sites have no vertex: their
/// bisector is a whole line, listed in `lines` (Ω itself for an antipodal pair).
///
/// **Circumcentres** (the proof is complex.hpp's "what the dual needs"): for three sites of one
/// side, not collinear, the null vector (A, B, C, D) of the rows (x² + y², w x, w y, w²) is the
/// circle A(X² + Y²) + B X + C Y + D = 0 through the drawn positions; its centre is
/// [2A, −B, −C]. A = w_a w_b w_c · orient(a, b, c), so the sign of 2A puts the centre on the
/// side of the sites when they turn counter-clockwise in T², on the other side when clockwise
/// (the farthest-point faces): one formula for front, back and farthest faces. Otherwise take
/// two consecutive sites p → q of the face on one side (for three collinear ones, a pair with
/// the middle site): the centre is the pole [0, ℓ_x, ℓ_y] of ℓ = p ∨ q, the point of Ω to
/// the left of p → q.
/// *Not built yet* (`std::runtime_error`): the faces without two proper sites on one side
/// (two sites on Ω, or a front, an Ω and a back site), whose vertex on Ω is at the middle of an
/// arc of Ω (irrational in general) or at 90° from a site of Ω.

#include <span>
#include <utility>
#include <vector>

#include "t2/kernel/point.hpp"
#include "t2/voronoi/complex.hpp"

namespace t2 {

/// The Voronoi diagram of T² (see the file comment).
struct VoronoiDiagram {
  using Index = Triangulation::Index;  ///< site and vertex indices
  /// A Voronoi edge from vertex `a` to vertex `b` between the cells of sites `s` and `t`.
  struct Edge {
    Index a;  ///< the first vertex
    Index b;  ///< the second vertex
    Index s;  ///< the site on one side
    Index t;  ///< the site on the other side
  };
  std::vector<ExactPoint> vertices;              ///< exact homogeneous circumcentres
  std::vector<std::vector<Index>> vertex_sites;  ///< the cells at each vertex, counter-clockwise
  std::vector<Edge> edges;                       ///< between two vertices
  std::vector<std::pair<Index, Index>> lines;    ///< bisectors without a vertex (two sites)
  std::vector<std::pair<Index, Index>> duplicates;  ///< (dropped, kept): sites owning no cell
};

/// The T² circumcentre of the face (a, b, c) of a Delaunay complex (file comment), exact.
ExactPoint circumcentre(const Point& a, const Point& b, const Point& c);

/// The Voronoi diagram of the complex `dc`.
VoronoiDiagram voronoi(const DelaunayComplex& dc);

/// The Voronoi diagram of `sites` (Algorithm 11). Throws `Undefined` where it is undefined in
/// T² (complex.hpp).
VoronoiDiagram voronoi(std::span<const Point> sites);

}  // namespace t2
