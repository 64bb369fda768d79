#pragma once
// Exercise 07: the API you implement in width.cpp. Do not change this file.
#include <vector>

#include <t2/kernel/point.hpp>

namespace ex07 {

/// The width of the points P of T²: a narrowest *strip* holding them all, as indices {i, j, k}.
/// A strip is the region between two different parallel lines, closed, on one side of T²: its
/// two lines meet at a pair ±d of Ω, which the strip holds (its ends), and no other point of Ω.
/// The answer's strip has one line through P[i] and P[j] (two different points: P[j] may be a
/// point of Ω, then the line is the parallel to that direction through P[i]), and the other
/// through P[k], parallel to it; its width is the drawn distance between them, and no strip
/// holding P is narrower. P has at least two different proper points, not all on one line; it
/// may repeat points, also at another scale. Throws t2::Undefined when no strip holds P: proper
/// points on both sides, or points of Ω that are not all ±d for one d.
std::vector<long> width(const std::vector<t2::Point>& P);

}  // namespace ex07
