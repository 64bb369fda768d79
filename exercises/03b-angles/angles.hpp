#pragma once
// Exercise 03b: the API you implement in angles.cpp. Do not change this file.
#include <t2/kernel/point.hpp>

namespace ex03b {

/// Compares the angle ∠abc (at b, between the rays from b through a and through c, in [0, π])
/// with the angle ∠def. All six points are on the front (w > 0), with a, c ≠ b and d, f ≠ e as
/// points of the plane; their weights may be any positive doubles. NEGATIVE when ∠abc < ∠def,
/// ZERO when they are equal, POSITIVE when ∠abc > ∠def. Exact for every finite double.
t2::Sign compare_angles(const t2::Point& a, const t2::Point& b, const t2::Point& c, const t2::Point& d,
                        const t2::Point& e, const t2::Point& f);

}  // namespace ex03b
