#pragma once
/// @file voronoi.hpp
/// @brief The Voronoi diagram of sites of T² (seed 000, §5.3.2, Algorithm 11) as the dual of
/// the Delaunay complex (complex.hpp): one cell per distinct site, covering all of T².
///
/// **Vertices.** One per Voronoi vertex: the T² circumcentre of a face of the complex
/// (`circumcentre`, below), in exact homogeneous integer coordinates (no division): w > 0 in
/// front, w < 0 behind, w = 0 on Ω. Adjacent faces with the same circumcentre (cocircular
/// sites) are one vertex, where four or more cells meet; `vertex_sites(v)` lists the sites of
/// its cells counter-clockwise around it (the boundary of its polygon in the complex).
/// `voronoi` itself is combinatorial and uses filtered predicates only: `vertex(v)` constructs
/// the exact centre (GMP integers) when it is asked for.
///
/// **When two faces are one vertex** (the proof behind the merge). Call a face *proper* when
/// its three sites are on one side of T² and not collinear; its centre is [2A, −B, −C] with
/// A ≠ 0 (below), so not on Ω, while the centre of any other face is on Ω. Two adjacent proper
/// faces f = (a, b, c) and g, sharing the edge b c with d the other site of g, have the same
/// centre exactly when in_circle(a, b, c, d) = 0 and orient(f) = orient(g): equal centres
/// have equal distances to b and c, hence one circle through a, b, c, d; conversely one circle
/// gives coefficient vectors (A, B, C, D) of f and g that are multiples of each other, and the
/// factor is positive exactly when A_f and A_g = w³ · orient have the same sign (the sites of
/// f and g are on one side, so w³ has one sign) — with opposite signs the centres are
/// antipodal (the front and back vertices of cocircular front sites). Two adjacent faces of
/// which one only is proper never share their centre; two adjacent faces that are not proper
/// (few: along Ω, the hull's flat fans, collinear sites) compare their exact centres.
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

#include <array>
#include <span>
#include <utility>
#include <vector>

#include "t2/kernel/point.hpp"
#include "t2/voronoi/complex.hpp"

namespace t2 {

/// The Voronoi diagram of T² (see the file comment), as `voronoi` fills it.
struct VoronoiDiagram {
  using Index = Triangulation::Index;  ///< site and vertex indices
  /// A Voronoi edge from vertex `a` to vertex `b` between the cells of sites `s` and `t`.
  struct Edge {
    Index a;  ///< the first vertex
    Index b;  ///< the second vertex
    Index s;  ///< the site on one side
    Index t;  ///< the site on the other side
  };
  std::vector<Point> sites;  ///< the sites, as given
  /// The cells at vertex v, counter-clockwise around it, are cells[first[v] .. first[v + 1]);
  /// `first` is empty when every vertex has three cells: they are cells[3v .. 3v + 3).
  std::vector<Index> first;
  std::vector<Index> cells;  ///< the sites at each vertex, one vertex after the other
  /// (v, a face of the complex at v) for each vertex where several faces meet, sorted by v: the
  /// three sites whose circumcentre is v. Any other vertex is the circumcentre of its cells.
  std::vector<std::pair<Index, std::array<Index, 3>>> fans;
  std::vector<Edge> edges;                          ///< between two vertices
  std::vector<std::pair<Index, Index>> lines;       ///< bisectors without a vertex (two sites)
  std::vector<std::pair<Index, Index>> duplicates;  ///< (dropped, kept): sites owning no cell
  /// Where each site's vertices start in `site_vertices`: those of site s are
  /// site_vertices[site_first[s] .. site_first[s + 1]). Filled by `voronoi`, so that `cell`
  /// costs the size of the cell; empty in a diagram filled by hand (`cell` scans every vertex).
  std::vector<Index> site_first;
  /// The vertices of each site's cell, unordered, one site after the other (`site_first`).
  std::vector<Index> site_vertices;

  /// The number of Voronoi vertices.
  std::size_t size() const { return first.empty() ? cells.size() / 3 : first.size() - 1; }
  /// The sites whose cells meet at vertex v, counter-clockwise around it.
  std::span<const Index> vertex_sites(Index v) const {
    if (first.empty()) return std::span<const Index>(cells).subspan(3 * std::size_t(v), 3);
    return std::span<const Index>(cells).subspan(first[v], first[v + 1] - first[v]);
  }
  /// Vertex v: its exact homogeneous coordinates (constructed on each call: GMP integers).
  ExactPoint vertex(Index v) const;
  /// The cell of site s as a polygon of T²: the vertices on its boundary, counter-clockwise
  /// around s (consecutive ones joined by an edge between s and a neighbour; `vertex(v)` gives
  /// their coordinates). Empty for a dropped duplicate or without vertices (fewer than three
  /// distinct sites). O(the size of the cell) with `site_first`, else O(cells.size()).
  std::vector<Index> cell(Index s) const;
};

/// The T² circumcentre of the face (a, b, c) of a Delaunay complex (file comment), exact.
ExactPoint circumcentre(const Point& a, const Point& b, const Point& c);

/// The Voronoi diagram of the complex `dc`.
VoronoiDiagram voronoi(const DelaunayComplex& dc);

/// The Voronoi diagram of `sites` (Algorithm 11). Throws `Undefined` where it is undefined in
/// T² (complex.hpp).
VoronoiDiagram voronoi(std::span<const Point> sites);

}  // namespace t2
