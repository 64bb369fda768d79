#pragma once
/// @file walk.hpp
/// @brief Point location in a subdivision of T² (subdivision.hpp): the walk of seed 000's
/// Algorithm 15 along the segment from a vertex q to the query p, exact, and the brute-force
/// test of every face that the tests use as its oracle.
///
/// **The walk.** Two states. *At a vertex v* of the segment qp (first v = q): if v = p, done; if
/// p lies on an edge at v, done; if the segment runs along an edge v → w with w before p, go
/// to w; otherwise exactly one corner of a face at v holds the direction of p (`in_corner`), or
/// none does and the segment leaves v into the complement, `outside`. *In a region R*, entered
/// at a point X of the segment: among the edges of R (a face's own, or every boundary edge for
/// `outside`) find the first point Y of the segment after X where it meets one. None: p is
/// inside R. Y = p: p is on that edge or vertex. Y a vertex: go to it. Otherwise cross the edge
/// into the region on its other side. Nothing assumes that a face is convex or on one side of
/// T²: crossing Ω is one more crossing of an edge, and the complement is a region like the
/// faces, so the walk goes on after it leaves the map.
///
/// **Exactness.** Only signs are used. The segment qp and the arc ab meet when the signs of
/// Δ(q, p, a), Δ(q, p, b) differ (or one is 0), those of Δ(a, b, q), Δ(a, b, p) differ (or
/// one is 0), and Δ(a, b, q) agrees with Δ(q, p, b) — on the sphere two arcs can each straddle
/// the other's great circle and yet cross it at antipodal points, and this last sign tells the
/// two apart. The meeting point is Y = α q + β p with (α, β) = s·(D_p, −D_q), D_x = det(a, b, x)
/// and s = ±1 making α, β ≥ 0, so two meeting points compare along the segment by the sign of
/// β₁α₂ − β₂α₁ = s₁s₂ (D_q² D_p¹ − D_q¹ D_p²), one degree-6 polynomial (sign_of_poly).
///
/// **Triangles.** A convex triangle (Δ > 0) is crossed by the plane's straight walk, two to
/// four orientations a step, where the general step above tests every edge. Entered through
/// the interior of its edge ab, the segment leaves by bc when the third vertex c is on a's
/// side of the line qp, by ca when on b's, through c when on the line; started at a point
/// inside, by the edge whose ends the line separates with the first on its right. p is inside
/// when it is on the inner side of that edge. It holds on the sphere because the segment is
/// shorter than a half turn: after it leaves by an edge, it stays on that edge's outer side.

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "t2/location/subdivision.hpp"
#include "t2/trace/hook.hpp"

namespace t2 {

/// Where a point lies in a subdivision. For a point on an edge or a vertex, the face of least
/// index that has it (the output of `t2 locate`).
struct Location {
  /// What the point hits.
  enum class Kind {
    face,    ///< strictly inside face `face`
    edge,    ///< inside the edge from vertex k of `face` to vertex k + 1
    vertex,  ///< equal to vertex k of `face`
    outside  ///< in the complement of the closed faces
  } kind = Kind::outside;                 ///< what the point hits
  Subdivision::Index face = Subdivision::outside;  ///< the face (not for `outside`)
  Subdivision::Index k = 0;               ///< the slot of the edge or vertex in `face`
  /// Same kind, face and slot.
  friend bool operator==(const Location&, const Location&) = default;
};

/// The answer written as `t2 locate` prints it: `face F`, `edge F K`, `vertex F K` or `outside`.
std::string to_string(const Location& l);

/// The answer for a point equal to vertex v of S: `vertex F k`, F the least face at v.
/// @param S the subdivision
/// @param v the vertex (an index into S.points())
Location at_vertex(const Subdivision& S, Subdivision::Index v);

/// The answer for a point inside the edge of half-edge h: `edge F k`, F the lesser of the
/// faces of h and of its twin.
/// @param S the subdivision
/// @param h the half-edge
Location at_edge(const Subdivision& S, Subdivision::Index h);

/// Locates p by walking from vertex q (an index into S.points()) along the segment qp; when
/// p = ¬q it starts from a neighbour of q instead. Appends to `crossed`, when given, each region
/// the walk passes through, in order (`Subdivision::outside` for the complement). Exact. The
/// segment meets each edge and each vertex at most once (both are straight), so the walk enters
/// at most e + v + 1 regions; a convex face is entered at most once, so on a map of convex
/// faces the walk costs O(e) (plus the boundary edges for each pass through `outside`); a
/// non-convex face can be entered once per edge it has, O(e²) in the worst case.
Location walk(const Subdivision& S, const Point& p, Subdivision::Index q,
              std::vector<Subdivision::Index>* crossed = nullptr);

/// The same walk, telling `hook` (trace/hook.hpp) each vertex of the segment it stands at
/// (`Event::reach_vertex`: its start, and each vertex the segment passes through) and each
/// region it enters (`Event::enter_region`: the region, and the edge crossed or the vertex
/// left), in the order the walk meets them; the answer is the untraced walk's. Only this
/// overload carries trace code; the one above has none.
/// @param S the subdivision
/// @param p the query point
/// @param q the starting vertex (an index into S.points())
/// @param hook hears the reports
Location walk(const Subdivision& S, const Point& p, Subdivision::Index q,
              const trace::AnyHook& hook);

/// Locates p by walking from the point `from`, which must be strictly inside face `face` (the
/// last answer of a run of queries, say), along the segment to p; when p = ¬from it starts
/// from a vertex of the face instead. The same walk without its first vertex, whose corners
/// cost more predicates than a step across a triangle. Exact. Without `crossed` it first tries
/// the visibility walk (Devillers, Pion and Teillaud): from triangle to triangle across any
/// edge with p strictly beyond it, one orientation an edge, the edge order flipped by a coin;
/// it gives up at a face that is not a convex triangle, at the boundary, or after as many steps
/// as there are faces (it may circle on a triangulation that is not Delaunay), and then the
/// walk along the segment answers. The answer is the same either way.
Location walk(const Subdivision& S, const Point& p, const Point& from, Subdivision::Index face,
              std::vector<Subdivision::Index>* crossed = nullptr);

/// Locates p by testing every face in order with the exact point-in-polygon test of T²
/// (point_in_polygon.hpp's `locate`, seed 000 Algorithm 2): the oracle of the walk. O(e).
Location locate_brute(const Subdivision& S, const Point& p);

}  // namespace t2
