#pragma once
// Exercise 06b: the API you implement in hull.cpp. Do not change this file.
#include <vector>

#include <t2/kernel/point.hpp>

namespace ex06b {

/// The convex hull of the points P of T² (front, back, Ω; P not empty): the indices (0-based) of
/// its *strict* vertices — a point inside a hull edge is not one — counter-clockwise in T²
/// (Δ(v_i, v_{i+1}, v_{i+2}) > 0), starting at any vertex. A vertex that occurs several times in
/// P, also with another scale ([2, 2, 4] is [1, 1, 2]), is listed once, under any of its indices.
/// A hull that is a segment is its two ends, in either order; a single point, its index.
/// Throws t2::Undefined when P lies in no open hemisphere (then it has no hull).
std::vector<long> hull(const std::vector<t2::Point>& P);

}  // namespace ex06b
