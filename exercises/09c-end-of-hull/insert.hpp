#pragma once
// Exercise 09c: the API you implement in insert.cpp. Do not change this file.
#include <vector>

#include <t2/kernel/point.hpp>

namespace ex09c {

/// The infinite vertex v∞ in a triangle list.
inline constexpr long kInfinite = -1;

/// What a face of a triangulation of T² is (chapter 09, section 6).
enum class Kind {
  infinite,  ///< v∞ is a vertex
  front,     ///< orient > 0, all three vertices in front (w > 0)
  back,      ///< orient > 0, all three behind (w < 0)
  band,      ///< orient > 0, vertices on both sides of Ω and none on Ω: a face across Ω
  omega,     ///< orient > 0, at least one vertex on Ω (w = 0)
  lune,      ///< orient = 0, two of the vertices antipodal: the region between two half great circles
  flat       ///< orient = 0, no two vertices antipodal: three points of one great circle, no area
};

/// The kind of each face of T (three indices into P per face, kInfinite for v∞), in the order of
/// T: `infinite` when a vertex is kInfinite; otherwise from the signs of t2::orient and of the
/// three weights w, as the comments of Kind say. The faces of T are counter-clockwise
/// (orient > 0) or have orient = 0; the points of a face are pairwise different in T².
std::vector<Kind> kinds(const std::vector<t2::Point>& P, const std::vector<long>& T);

/// Inserts P[q], any point of T², into T (chapter 09, section 6, INSERT-T2). T: a triangulation
/// with the infinite vertex of points of P other than q, in an open hemisphere (so they have a
/// hull H): a flat list, three indices per triangle, each finite triangle counter-clockwise
/// (t2::orient > 0), and for each hull edge a -> b (counter-clockwise around H) the infinite
/// triangle (b, a, kInfinite); every directed edge occurs once and its reverse once. A vertex of
/// T on the boundary of H is a hull vertex, also where H is straight.
///
/// Returns T with P[q] inserted, by these rules, which make the answer unique:
/// - P[q] equal to a vertex of T (t2 equality, exact): T unchanged;
/// - P[q] in H (no hull edge a -> b has t2::orient(a, b, q) < 0): as in exercise 09b, inside a
///   finite triangle (a, b, c) it is replaced by (a, b, q), (b, c, q), (c, a, q); inside the edge
///   a -> b of (a, b, c), whose other triangle is (b, a, d) (d may be kInfinite), those two are
///   replaced by (a, q, c), (q, b, c), (b, q, d), (q, a, d);
/// - ¬P[q] outside H (some hull edge has orient(a, b, q) > 0): the hull survives, as in 09b:
///   each infinite triangle (a, b, kInfinite) with orient(a, b, q) > 0 becomes (a, b, q), and
///   the two new hull edges get their infinite triangles;
/// - ¬P[q] strictly inside H, or equal to a vertex of T (on the hull: its two faces with q
///   become lunes): the hull is destroyed: q replaces kInfinite in every infinite triangle;
/// - ¬P[q] inside a hull edge, at no vertex: throws t2::Undefined (no triangulation exists).
/// The order of the triangles and the rotation of each are free.
std::vector<long> insert(const std::vector<t2::Point>& P, const std::vector<long>& T, long q);

}  // namespace ex09c
