#pragma once
// Exercise 09b: the API you implement in insert.cpp. Do not change this file.
#include <vector>

#include <t2/kernel/point.hpp>

namespace ex09b {

/// The infinite vertex v∞ in a triangle list.
inline constexpr long kInfinite = -1;

/// Inserts P[q] into the triangulation T (chapter 09, section 3, Algorithm 9). P: points of T²
/// in one open hemisphere (a set with a hull: front points with any w > 0, but also back points
/// and points of Ω, when some line has them all strictly on one side; chapter 09, section 6).
/// T: a triangulation with the infinite vertex of the points of P
/// other than q — a flat list, three indices per triangle, each finite triangle
/// counter-clockwise (t2::orient > 0), and for each hull edge a -> b (counter-clockwise around
/// the hull) the infinite triangle (b, a, kInfinite) — so that every directed edge occurs once
/// and its reverse once (a triangulated sphere). The triangles' order and rotations are free.
///
/// Returns T with P[q] inserted, by these rules, which make the answer unique:
/// - P[q] equal to a vertex (t2 equality, exact): T unchanged;
/// - inside a finite triangle (a, b, c): (a, b, q), (b, c, q), (c, a, q) replace it;
/// - inside the edge a -> b of the finite triangle (a, b, c), whose other triangle is
///   (b, a, d), finite or infinite: (a, q, c), (q, b, c), (b, q, d), (q, a, d) replace them;
/// - outside the hull: each infinite triangle (a, b, kInfinite) with P[q] strictly to the left
///   of a -> b (t2::orient(a, b, q) > 0) becomes (a, b, q), and the two new hull edges get their
///   infinite triangles. A hull edge whose line passes through P[q] is not seen.
/// The order of the triangles and the rotation of each are free.
std::vector<long> insert(const std::vector<t2::Point>& P, const std::vector<long>& T, long q);

}  // namespace ex09b
