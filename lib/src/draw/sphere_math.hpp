#pragma once
// Great arcs and hemispheres of the unit sphere, for the spherical model and for regions of
// the planar model (which are clipped on the sphere before they are projected).
#include <numbers>
#include <vector>

#include "t2/draw/vec.hpp"
#include "t2/kernel/line.hpp"
#include "t2/kernel/point.hpp"

namespace t2::draw {

inline constexpr double kPi = std::numbers::pi;

/// Points of the shorter great arc from a to b (unit vectors, not antipodal), every ~1.5°.
std::vector<Vec3> slerp_samples(const Vec3& a, const Vec3& b);

/// The dense closed loop of unit vectors along a closed chain of T² segments.
std::vector<Vec3> dense_loop(const std::vector<Point>& pts);

/// The point where the short arc from a to b crosses the great circle ⟂ axis, for a and b on
/// different sides of it (interpolated: a and b are samples a degree or two apart).
Vec3 crossing(const Vec3& a, const Vec3& b, const Vec3& axis);

/// The part of the region bounded by `loop` that lies on the side s · axis ≥ 0, as a closed
/// loop: the loop where it is on that side, and between the point E where it leaves and the
/// point F where it comes back, the shorter arc from E to F of the great circle ⟂ axis. That
/// is exact for the regions drawn here (convex, less than a hemisphere: such a region meets a
/// great circle in one arc shorter than a half circle). Empty when no point of the loop is
/// strictly on that side (a region of less than a hemisphere bounded there has no part on it).
/// Projected by a map that is one-to-one on that hemisphere (orthographic from `axis`, or
/// central for the planar model), the result bounds the visible part.
std::vector<Vec3> clip_to_hemisphere(const std::vector<Vec3>& loop, const Vec3& axis);

/// The middle of the segment of T² from p to q on the sphere (where its label goes).
Vec3 arc_middle(const Point& p, const Point& q);

/// A dense loop (480 points) around the great circle of l, starting at a limb point when
/// there is one.
std::vector<Vec3> great_circle(const Line& l);

}  // namespace t2::draw
