#pragma once
// Exercise 15b: the API you implement in locus.cpp. Do not change this file.
#include <vector>

#include <t2/kernel/isorect.hpp>
#include <t2/kernel/point.hpp>

namespace ex15b {

/// For each rectangle R[i], the number of points of P (with repetition) in the closed
/// iso-rectangle R[i] of T² (chapter 02 and chapter 15, section 3): its corner a is proper, its
/// extents Δx, Δy are values of T¹ with w ≥ 0, finite (of either sign, or zero) or ±∞. A proper
/// point p is in it when p is on a's side and its drawn coordinates (x/w, y/w) lie between those
/// of a and a + (Δx, Δy) in each axis (an infinite extent leaves that side of the interval open
/// to ±∞). A point of Ω is in it when it lies on the rectangle's part of Ω (Theorem 3): the
/// direction of b when only Δx is infinite, of d when only Δy is, the closed quarter of Ω from b
/// to d when both are, nothing when both are finite. On the back side the drawn directions are
/// mirrored: a back rectangle with Δx = +∞ reaches [0, −1, 0].
///
/// P holds up to 6000 points and R up to 50000 rectangles: preprocess P once (chapter 15's
/// locus method), then answer each rectangle in O(log n).
std::vector<long> count(const std::vector<t2::Point>& P, const std::vector<t2::IsoRect>& R);

}  // namespace ex15b
