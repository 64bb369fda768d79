#pragma once
// Exercise 12: the API you implement in nearest.cpp. Do not change this file.
#include <vector>

#include <t2/kernel/point.hpp>

namespace ex12 {

/// All nearest neighbours (chapter 12, section 3). P: at least two sites of T², no two equal as
/// points of T² ([2, 2, 0] = [1, 1, 0]), no two sites of Ω exactly 90° apart. E: pairs of site
/// indices, flat (E[2k], E[2k + 1]): a graph that holds every edge of the Delaunay triangulation
/// of the front sites and every edge of that of the back sites (each side on its own, the back
/// sites by their drawn positions; a side of two sites has their edge). It may hold more pairs of
/// one side, never a pair across sides nor one with a site on Ω.
///
/// Returns nearest[i]: the site j != i nearest to site i, sites compared from i by the exact
/// t2::compare_distance(P[j], P[k], P[i]); among equally near sites the smallest index.
/// Throws t2::Undefined when some site has no nearest: a site z of Ω, no other site of Ω less
/// than 90° from z, and sites on both sides (t2::compare_distance cannot order a front and a back
/// site seen from z).
std::vector<long> nearest_neighbours(const std::vector<t2::Point>& P, const std::vector<long>& E);

}  // namespace ex12
