#pragma once
// Exercise 02b: the API you implement in clip.cpp. Do not change this file.
#include <vector>

#include <t2/kernel/point_type.hpp>

namespace ex02b {

/// The part of the segment pq of T² (the points αp + βq, α, β ≥ 0) on the closed positive side
/// of the line l = ⟨W, X, Y⟩ (the points r with W·r.w + X·r.x + Y·r.y ≥ 0; W, X, Y not all 0),
/// exactly, given by its endpoints in order from p to q:
/// - no point: an empty vector;
/// - a single point (p = q, or the segment only touches the side): one point;
/// - otherwise its two endpoints.
/// The caller guarantees q ≠ ¬p. With l = ⟨1, 0, 0⟩ this is the clipping of chapter 01,
/// section 8: the front part of the segment.
std::vector<t2::ExactPoint> clip(const t2::Point& p, const t2::Point& q, double W, double X, double Y);

}  // namespace ex02b
