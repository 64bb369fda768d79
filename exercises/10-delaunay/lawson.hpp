#pragma once
// Exercise 10: the API you implement in lawson.cpp. Do not change this file.
#include <vector>

#include <t2/kernel/point.hpp>

namespace ex10 {

/// Lawson's algorithm. P: front points (w > 0), no two equal, not all on one line. T: a
/// triangulation of P as a flat list of point indices, three per triangle, each triangle
/// counter-clockwise. Returns a Delaunay triangulation of P in the same form, reached by flipping
/// edges of T: the same points and the same hull, every triangle counter-clockwise, and every
/// edge shared by two triangles (a, b, c) and (b, a, d) locally Delaunay — d not strictly inside
/// the circle through a, b, c, decided exactly (t2::in_circle). The order of the triangles and
/// the rotation of each are free; with four cocircular points either diagonal is accepted.
std::vector<long> delaunay_flips(const std::vector<t2::Point>& P, const std::vector<long>& T);

}  // namespace ex10
