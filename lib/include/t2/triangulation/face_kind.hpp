#pragma once
/// @file face_kind.hpp
/// @brief The one record of what a face of a triangulation of T² is (`FaceKind`) and of its
/// antipodal edges (`AntipodalEdge`), shared by both T² constructions: the T² Delaunay
/// (delaunay_t2.hpp) and Algorithm 9 (triangulate_t2.hpp), and read by the exact queries of
/// triangulation.hpp (`side`, `locate`, `nearest_vertex`).
///
/// **Design.** A face's kind is a function of its three vertices alone, so it is *computed*
/// (`face_kind`, exact: signs of w and `orient`), never stored: no construction can forget it or
/// get it out of date after a flip. What the vertices do not determine is the embedding of an
/// edge between antipodes z and ¬z: every half great circle from z to ¬z has orient(z, ¬z, p)
/// = 0 for all p. That one fact is stored, in the triangulation itself
/// (`Triangulation::antipodal_edges()`), so that every triangulation carries what its exact
/// walk needs, whichever construction made it.
///
/// **The rule of the antipodal edge** (antipodal_edge.hpp proves it keeps the faces a tiling):
/// the edge z → ¬z leaves z along the bisector, in the sphere model, of the angle u z w, outwards,
/// where (z, u, ¬z) is the lune to its right and (w, z, ¬z) the lune to its left *when the edge
/// is made*. Algorithm 9 makes it when ¬z arrives at the hull vertex z (u → z → w along the
/// hull); the T² Delaunay, which joins an antipodal pair only between two lunes, records the
/// third vertices of those two lunes. Later insertions (Algorithm 9) may change the lunes'
/// third vertices; the record keeps the ones the edge was made with, and so the edge never
/// moves. Any meridian strictly inside the angle of the two lunes would tile as well; the
/// bisector is the seed's choice (figure 5.18) and does not depend on the coordinates. One rule,
/// one record: the two constructions speak the same dialect. (The T² Delaunay is a combinatorial
/// dual; its antipodal edge may be drawn along any such meridian, and this is the one it uses.)
///
/// **Kinds** (of a face (a, b, c) turning counter-clockwise or flat; exact):
///  - `infinite`: v∞ is a vertex (the open region beyond a hull edge);
///  - orient(a, b, c) > 0, a *proper* face, the closed cone {αa + βb + γc : α, β, γ ≥ 0}:
///    `front` (all three w > 0), `back` (all w < 0), `omega` (a vertex on Ω — the Ω-site faces
///    of delaunay_ring.hpp), `band` (both sides, none on Ω: the faces across Ω);
///  - orient = 0 with two antipodal vertices: `lune`, the region between two half great circles;
///  - orient = 0 otherwise: `flat`, three vertices on one great circle, no area (figure 5.19).

#include <cstdint>

#include "t2/kernel/orient.hpp"
#include "t2/kernel/point.hpp"

namespace t2 {

class Triangulation;

/// What a face of a triangulation of T² is (see the file comment).
enum class FaceKind {
  infinite,  ///< v∞ is a vertex
  front,     ///< proper, all three vertices in front (w > 0)
  back,      ///< proper, all three behind (w < 0)
  band,      ///< proper, vertices on both sides and none on Ω: a face across Ω
  omega,     ///< proper, a vertex on Ω (w = 0)
  lune,      ///< orient 0, two antipodal vertices: the region between two half great circles
  flat       ///< orient 0, three vertices on one great circle, no two antipodal: no area
};

/// True for the kinds with orient > 0: the face is the closed cone of its vertices.
constexpr bool is_proper(FaceKind k) {
  return k == FaceKind::front || k == FaceKind::back || k == FaceKind::band || k == FaceKind::omega;
}

/// The kind of the finite face (a, b, c) (counter-clockwise or flat; exact).
inline FaceKind face_kind(const Point& a, const Point& b, const Point& c) {
  if (orient(a, b, c) == ZERO) {
    const bool lune = a == antipode(b) || b == antipode(c) || c == antipode(a);
    return lune ? FaceKind::lune : FaceKind::flat;
  }
  const int pos = (a.w() > 0) + (b.w() > 0) + (c.w() > 0), neg = (a.w() < 0) + (b.w() < 0) + (c.w() < 0);
  if (pos == 3) return FaceKind::front;
  if (neg == 3) return FaceKind::back;
  return pos + neg == 3 ? FaceKind::band : FaceKind::omega;
}

/// The kind of face t of tr (`infinite` when v∞ is a vertex).
FaceKind face_kind(const Triangulation& tr, std::uint32_t t);

/// An edge z → ¬z between antipodes: the half great circle leaving z along the sphere-model
/// bisector of the angle u z w, outwards (file comment; antipodal_edge.hpp has the exact side).
/// Indices are vertex indices of the triangulation that holds the record.
struct AntipodalEdge {
  std::uint32_t z;   ///< one end
  std::uint32_t nz;  ///< the other end, ¬z
  std::uint32_t u;   ///< the third vertex of the lune (z, u, ¬z) to the right of z → ¬z (hull edge u → z)
  std::uint32_t w;   ///< the third vertex of the lune (w, z, ¬z) to its left (hull edge z → w)
};

/// The exact side of p of the edge opposite slot i of the finite face t of tr: `orient` for an
/// edge between points that are not antipodal, the recorded bisector (`side_of_antipodal_edge`)
/// for an edge z → ¬z. POSITIVE: p is on the side of t. Throws std::logic_error for an
/// antipodal edge that tr has no record of.
Sign side_of_edge(const Triangulation& tr, std::uint32_t t, int i, const Point& p);

}  // namespace t2
