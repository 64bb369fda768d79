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

}  // namespace t2cli::algorithms
