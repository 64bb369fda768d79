#pragma once
// Exercise 08: the API you implement in horizon.cpp. Do not change this file.
#include <vector>

#include <t2/kernel/orient3d.hpp>

namespace ex08 {

/// One step of the incremental hull (chapter 08, section 7). H: a closed convex surface of
/// triangles on points of P, a flat list of indices, three per triangle, each counter-clockwise
/// seen from outside (t2::orient3d(a, b, c, q) <= 0 for every vertex q of H); its triangles
/// need not be maximal facets (two neighbours may be coplanar). p: an index into P.
///
/// Returns the surface after inserting P[p], by this rule, which makes the answer unique:
/// p *sees* the triangle (a, b, c) when t2::orient3d(a, b, c, p) > 0 (strictly, decided
/// exactly); the triangles p does not see stay as they are; for every *horizon* edge a -> b —
/// an edge of a seen triangle whose other triangle is not seen — the triangle (a, b, p) is
/// added. When p sees no triangle (inside, or on the surface, or equal to a vertex) the answer
/// is H. The order of the triangles and the rotation of each are free.
std::vector<long> insert_point(const std::vector<t2::Point3>& P, const std::vector<long>& H, long p);

}  // namespace ex08
