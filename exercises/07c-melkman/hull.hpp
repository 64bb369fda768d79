#pragma once
// Exercise 07c: the API you implement in hull.cpp. Do not change this file.
#include <vector>

#include <t2/kernel/point.hpp>

namespace ex07c {

/// The hull of the simple polygon P of T² (vertices in order along its boundary, either
/// orientation), in linear time, by Melkman's deque (chapter 07, section 1): the indices of its
/// *strict* vertices (no vertex inside a hull edge), counter-clockwise in T² (`t2::orient` > 0
/// for three consecutive ones), starting anywhere.
/// Preconditions (the tests keep them): P is simple and lies in an open hemisphere of T² — on
/// the front side, on the back side, or across Ω; repeated vertices only next to each other
/// (cyclically: the last may repeat the first), possibly at another scale. A repeated vertex is
/// named by the smallest index it has. A polygon on one line gives the two ends of its segment
/// (in either order), one point gives {i}, no point gives {}.
std::vector<long> hull(const std::vector<t2::Point>& P);

}  // namespace ex07c
