#pragma once
// Exercise 05: the API you implement in locate.cpp. Do not change this file.
#include <vector>

#include <t2/kernel/point.hpp>
#include <t2/kernel/sign.hpp>

namespace ex05 {

/// Where q lies with respect to the simple polygon P of T²: at least 3 vertices, anywhere in T²
/// (front, back, on Ω, on both sides); its edges are the T² segments of consecutive vertices
/// (never equal nor antipodal), and they meet only at the common vertex of consecutive edges.
/// The boundary of P splits T² into two regions: POSITIVE when q is in the region on the left of
/// the edges (the inside of a counter-clockwise front polygon), NEGATIVE in the other region,
/// ZERO on the boundary. Exact for every finite double.
t2::Sign locate(const std::vector<t2::Point>& P, const t2::Point& q);

}  // namespace ex05
