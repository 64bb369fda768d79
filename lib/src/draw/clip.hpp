#pragma once
// Clipping in the picture plane: lines and polygons against the unit disk (the shown part of
// the planar model, the outline of the sphere) and against half-planes.
#include <vector>

#include "t2/draw/vec.hpp"

namespace t2::draw {

/// Clips the parametric line P + tD, t in [t0, t1] (possibly infinite), to the unit disk:
/// false when nothing is left, else the ends of what is left in `a` and `b`.
bool clip_disk(Vec2 P, Vec2 D, double t0, double t1, Vec2& a, Vec2& b);

/// The disk of radius r as a polygon of n vertices.
std::vector<Vec2> disk_polygon(double r = 1, int n = 180);

/// Sutherland–Hodgman: the part of polygon `poly` where k + n·x ≥ 0.
std::vector<Vec2> clip_half(const std::vector<Vec2>& poly, double k, Vec2 n);

/// Clips a polygon to the unit disk (convex: clipped by each edge of a circumscribed polygon).
std::vector<Vec2> clip_poly_disk(std::vector<Vec2> poly);

}  // namespace t2::draw
