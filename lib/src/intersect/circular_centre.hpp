#pragma once
// The centre of the circular sweep (intersect/circular.cpp): a point o off the line of every
// segment and equal to no one-point segment nor to its antipode. Private to lib/src/intersect.
#include <vector>

#include "t2/kernel/point.hpp"
#include "t2/kernel/segment.hpp"

namespace t2::detail {

/// True when o is a valid centre for `segments`: o is on no segment's line, and no one-point
/// segment is o or ¬o. Exact; O(n) predicates.
bool valid_centre(const std::vector<Segment>& segments, const Point& o);

/// A valid centre: the origin [1, 0, 0] when it is valid (the seed's centre), else the first
/// [1, t, t²], t = 1, 2, ..., 2n + 2, that is (found in O(n) exact integer operations: each
/// line and each point rules out at most two values of t; circular_centre.cpp).
Point circular_centre(const std::vector<Segment>& segments);

}  // namespace t2::detail
