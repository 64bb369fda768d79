#pragma once
// Exercise 07b: the API you implement in diameter.cpp. Do not change this file.
#include <vector>

#include <t2/kernel/point.hpp>

namespace ex07b {

/// The diameter of the points P of T² (at least two; front, back, Ω, repeats): the indices
/// {a, b} of a pair at the *largest* distance, in the order of squared distances of T¹
/// (chapter 03): same-side pairs by their Euclidean distance, then +∞ (a proper point and a point
/// of Ω), then the front–back pairs "beyond infinity", where the pair *nearer* as drawn is the
/// farther (a point and its antipode are the farthest of all). Two equal points are at distance 0;
/// a == b only when every point of P is the same. Any pair of the largest distance is accepted.
/// Throws t2::Undefined when two different points of P lie on Ω (their distance is an angle,
/// which no value of T¹ compares with).
std::vector<long> diameter(const std::vector<t2::Point>& P);

}  // namespace ex07b
