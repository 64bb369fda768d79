#pragma once
// Exercise 03: the API you implement in mid.cpp. Do not change this file.
#include <t2/kernel/point.hpp>

namespace ex03 {

/// The midpoint of the segment pq of T², exactly (integer coordinates: no division, ever).
/// - p, q on the same side: the point of that side halfway between them;
/// - p, q on opposite sides: the point of Ω where the segment crosses infinity;
/// - one of them on Ω: that point (it is infinitely far from the other);
/// - p = q: p.
/// Throws t2::Undefined when q = ¬p (no segment) and when p, q are distinct points of Ω
/// (the halfway point of an arc of Ω needs lengths, i.e. square roots).
t2::ExactPoint midpoint(const t2::ExactPoint& p, const t2::ExactPoint& q);

}  // namespace ex03
