#pragma once
/// @file complex.hpp
/// @brief The Delaunay complex of T²: for every set of sites, the complete dual of the T²
/// Voronoi diagram — a triangulated sphere — where `delaunay` (delaunay_t2.hpp) stops at the
/// hull and puts v∞ beyond it.
///
/// **Definition.** Let S be a finite set of sites of T² (duplicates merged: a site equal to an
/// earlier one is recorded in `duplicates` and is no vertex). The T² Voronoi diagram of S
/// divides T² into the cells {q : no site is nearer to q than s} under the distances of
/// distance.hpp (seed 000, §4.3.1). A *Voronoi vertex* is a point of T² in the closed cells of
/// at least three sites. The Delaunay complex has one vertex per site and, for each Voronoi
/// vertex v, one polygon: the sites of the cells at v in counter-clockwise order around v (seen
/// on the sphere from outside, the front drawn as the plane). Each polygon of k ≥ 4 sites
/// (cocircular sites, in T²'s sense) is cut into k − 2 triangles by a fan; which fan is left
/// free. Every face (a, b, c) is stored in that counter-clockwise order; the faces glue edge to
/// edge (each directed edge a → b once, its reverse once) into a closed orientable surface of
/// genus 0: V − E + F = 2, with V the distinct sites.
///
/// **What the dual needs.** Voronoi's vertex of a face is its *circumcentre* in T², the point
/// equidistant from its three sites with no site nearer (voronoi.hpp constructs it): the
/// Euclidean circumcentre of the drawn positions for three sites of one side, on that side when
/// they turn counter-clockwise in T² and on the other when clockwise; the pole [0, ℓ_x, ℓ_y] of
/// ℓ = a ∨ b, on Ω, for a face (a, b, c) whose consecutive sites a, b lie on one side and c does
/// not, or whose three sites are collinear. Adjacent faces with the same circumcentre are one
/// Voronoi vertex (the fan above); the edges of the complex between faces of different
/// circumcentres are the Voronoi edges, each on the bisector of its two sites.
///
/// **The parts, with the reason each is the dual** (the proofs of (1)–(3) are delaunay_t2.hpp's):
///  1. *Front-only sites, not collinear.* The front hemisphere is the Euclidean Voronoi diagram:
///     its vertices are the Delaunay triangles (delaunay.hpp; cocircular ones split by the
///     symbolic perturbation, which is a fan of the cocircular polygon up to flips). A back
///     point x, drawn at X̄, is nearer to a site the *farther* X̄ is from it (beyond infinity),
///     so the back hemisphere is the farthest-point Voronoi diagram of the drawn sites: its
///     vertex at X̄ = V is x = ¬[1, V], the antipode of the farthest-point Voronoi vertex V.
///     Its dual is the farthest-point Delaunay triangulation of the strict hull corners
///     (triangles whose circumcircle holds every site), each face reversed: clockwise in the
///     plane, counter-clockwise around its back vertex. A site strictly inside a hull edge
///     c₁ c₂ with outer normal n owns a strip that reaches Ω at the single point [0, n], where
///     the cells of all the sites of that edge meet: a Voronoi vertex on Ω, whose polygon is
///     the flat chain c₁ … c₂ back to c₁ (flat faces, orient 0).
///  2. *Back-only sites.* The antipodal map ¬ keeps T² distances and reverses orientation: the
///     complex of S is that of ¬S with every face reversed.
///  3. *Sites on both sides, or on Ω with sites on both sides.* delaunay_t2.hpp's faces before
///     v∞ replaces the clockwise ones: the planar Delaunay triangles of each side and the ring
///     of faces whose vertices lie on Ω. That construction follows the owners of Ω around the
///     whole circle, hull or not, so its faces are all the Voronoi vertices; with a hull the
///     ones beyond it are clockwise (their short-arc triangle is not the face's region, which
///     reaches round the back), and are kept. Antipodal pairs give the flat faces of seed
///     000's figure 5.18.
///  4. *Collinear sites, k ≥ 3 distinct, all in front* (or all behind, by 2). The cells are
///     slabs whose closures all meet at the two points of Ω perpendicular to the line: two
///     Voronoi vertices, two flat k-gons a₁ … a_k and a_k … a₁ (fans from different apexes).
///  5. *Fewer than three distinct sites:* no Voronoi vertex and no face (`dimension` < 2): one
///     site owns T², two split it by their bisector line (two antipodal sites by Ω).
/// *Undefined* (`Undefined` is thrown): a side of T² without sites while two or more distinct
/// sites lie on Ω — that hemisphere would be shared among them by angles seen from a proper
/// point, which depend on the origin (seed 000, figure 4.16) — and the ties on Ω that
/// delaunay_t2.hpp rejects (a flat face without an antipodal pair).
/// *Not built yet* (`std::runtime_error`, issue 24): collinear sites not all on one side; one
/// site on Ω with the sites of one side collinear.
///
/// **Cost.** One `delaunay` (or delaunay_t2), whose triangles and twins are copied as they are
/// (no search), and, for (1), `farthest_delaunay` on the h hull corners: Chew's randomized
/// insertion, O(h) expected (the upper lifted hull stands in for lawson.hpp's lower one). The
/// faces beyond the hull (and the flat fans of collinear sites) are linked to their twins
/// through a hash of their edges.

#include <array>
#include <span>
#include <utility>
#include <vector>

#include "t2/kernel/point.hpp"
#include "t2/triangulation/triangulation.hpp"

namespace t2 {

/// The Delaunay complex of T² (see the file comment).
struct DelaunayComplex {
  using Index = Triangulation::Index;  ///< site indices
  std::vector<Point> points;           ///< the sites, as given
  std::vector<std::array<Index, 3>> faces;  ///< counter-clockwise around their Voronoi vertex
  /// The adjacency, as triangulation.hpp stores it: `twins[3f + i]` = 3g + j when the edge of
  /// face f opposite slot i (from faces[f][i + 1] to faces[f][i + 2], indices mod 3) is the edge
  /// of face g opposite slot j, in reverse. An involution without fixed points.
  std::vector<Index> twins;
  /// The turn of each face: for a *proper* face — three sites on one side of T², not collinear —
  /// the sign of orient(a, b, c) (homogeneous, so for back sites the opposite of their drawn
  /// turn); ZERO for the others (a site on Ω, sites on both sides, or collinear). Kept from the
  /// construction where it is known (the front triangles turn counter-clockwise, the farthest
  /// ones clockwise, the fans are flat), computed by `orient` elsewhere.
  std::vector<Sign> turns;
  std::vector<std::pair<Index, Index>> duplicates;  ///< (dropped, kept), sorted by dropped
  int dimension = -1;  ///< −1 no site, 0 one distinct site, 1 two distinct sites, 2 faces exist
};

/// The Delaunay complex of `points` (see the file comment). Throws `Undefined` where the T²
/// Voronoi diagram is undefined.
DelaunayComplex delaunay_complex(std::span<const Point> points);

/// The farthest-point Delaunay triangulation of front points in strictly convex position,
/// given counter-clockwise: triangles (indices into `corners`) counter-clockwise, each circle
/// holding every corner (inside or on). Chew's randomized insertion (a fixed seed: the same
/// output every run), expected O(h) time for h corners (chapter 11).
std::vector<std::array<Triangulation::Index, 3>> farthest_delaunay(std::span<const Point> corners);

}  // namespace t2
