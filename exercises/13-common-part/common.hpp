#pragma once
// Exercise 13: the API you implement in common.cpp. Do not change this file.
#include <vector>

#include <t2/kernel/point.hpp>

namespace ex13 {

/// The common part of the segments ab and cd of T² (chapter 13, section 1: the segment ab is the
/// set of points αa + βb with α, β ≥ 0 not both zero; a = b gives the one point a). The caller
/// guarantees a ≠ ¬b and c ≠ ¬d. By Lemma 1 the common part is empty, one point, or a piece of
/// one line, and the answer is:
///   - {} when the segments do not meet;
///   - {p} when they meet in one point p, given exactly, as the point of T² on both segments
///     (any positive multiple: a back point keeps w < 0, a point of Ω has w = 0);
///   - {p, q} when they share a piece of one line: its two ends, p ≠ q, in either order.
/// Endpoints may be on the front, on the back, or on Ω. Never throws for valid input.
std::vector<t2::ExactPoint> common(const t2::Point& a, const t2::Point& b, const t2::Point& c, const t2::Point& d);

}  // namespace ex13
