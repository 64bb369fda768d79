#pragma once
// Exercise 10b: the API you implement in incremental.cpp. Do not change this file.
#include <vector>

#include <t2/kernel/point.hpp>

namespace ex10b {

/// A Delaunay triangulation of the front points P (w > 0, not necessarily 1), built by
/// randomized incremental insertion (chapter 10). Returns a flat list of point indices, three
/// per triangle, each counter-clockwise (t2::orient > 0): the triangles tile the convex hull of
/// P exactly once, every point of P is a vertex or equal (in T², exactly: [2, 2, 2] = [1, 1, 1])
/// to one vertex — of equal points one only, any —, and every edge shared by two triangles
/// (a, b, c) and (b, a, d) is locally Delaunay: t2::in_circle(a, b, c, d) <= 0. With four or more
/// cocircular points any of their triangulations is accepted. The order of the triangles and
/// the rotation of each are free. Throws t2::Undefined when P has no three points off one line
/// (there is no triangle).
std::vector<long> delaunay(const std::vector<t2::Point>& P);

}  // namespace ex10b
