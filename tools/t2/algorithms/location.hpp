#pragma once
// The input of `t2 bench locate` beyond the points (location.cpp): the query points, the same
// for t2's walk and for the peers.

#include <cstdint>
#include <span>
#include <vector>

#include "t2/kernel/point.hpp"

namespace t2cli::algorithms {

/// As many queries as points, uniform in the points' bounding box (a fixed seed), in random
/// order or, with `sorted`, in t2's spatial order (spatial_sort.hpp, BRIO rounds of Hilbert
/// order), so that each query lies near the one before.
std::vector<t2::Point> locate_queries(std::span<const t2::Point> points, bool sorted);

/// The queries of `t2 animate walk` and `t2 animate trapezoid`, seven: q0 to q3 uniform in the
/// bounding box of the proper points' drawn positions (a fixed seed), q4 the middle input point
/// p[n/2] (a vertex of the map, unless a duplicate), q5 the antipode of q0 (on the back side) and
/// q6 = [0, 1, 0] on Omega.
std::vector<t2::Point> animation_queries(std::span<const t2::Point> points);

}  // namespace t2cli::algorithms
