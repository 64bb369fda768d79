#pragma once
// Exercise 12b: the API you implement in tree.cpp. Do not change this file.
#include <vector>

#include <t2/kernel/point.hpp>

namespace ex12b {

/// A minimum spanning tree of the sites P of T² (chapter 12, section 2). P: sites, no two equal
/// as points of T² ([2, 2, 0] = [1, 1, 0]). E: pairs of site indices, flat (E[2k], E[2k + 1]): a
/// graph that holds every edge of the Delaunay triangulation of the front sites and every edge of
/// that of the back sites (each side on its own, the back sites by their drawn positions; a side
/// of two sites has their edge). It may hold more pairs of one side, never a pair across sides
/// nor one with a site on Ω.
///
/// Returns n − 1 pairs of site indices, flat like E (empty for n < 2): a spanning tree whose
/// weights, in the order of pairs of chapter 12, section 1 (t2::compare_pair_distance: 0 <
/// finite < +∞, all level < beyond infinity, the farther drawn the nearer), sorted, are term by
/// term no larger than those of any other spanning tree. Any such tree is accepted, the pairs in
/// any order and either way round. Never undefined.
std::vector<long> spanning_tree(const std::vector<t2::Point>& P, const std::vector<long>& E);

}  // namespace ex12b
