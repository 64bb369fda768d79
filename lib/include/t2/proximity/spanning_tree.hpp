#pragma once
/// @file spanning_tree.hpp
/// @brief The minimum spanning tree of sites of T² (seed 000 §5.4, Algorithm 12): Kruskal with
/// union–find on the Delaunay edges of each side, then the edges at +∞ and beyond infinity.
///
/// **Minimum, for an order without sums.** The weights (pair_distance.hpp) are points of T¹,
/// which have an order but no sum; a spanning tree is *minimum* when its weights, sorted, are
/// no larger term by term than those of any other spanning tree — for real weights this is
/// the usual minimum (Kruskal's tree is such for every increasing change of the weights), and it
/// depends on the order only. Every minimum tree has the same sorted weights (matroid theory),
/// which is what the tests compare against brute force.
///
/// **Which tree** (ties): Kruskal on all n(n−1)/2 pairs in the order of `pair_before` (weight,
/// then the pair (min, max) lexicographic) — one tree, which `minimum_spanning_tree` returns
/// exactly, the tests checking it edge for edge against that brute force. Equal sites are
/// joined first (weight 0), each to the first of them.
///
/// **Is the tree in the T² Delaunay complex?** Kruskal, in that strict order, takes a pair ab only
/// if no site c comes before it on both sides (ac and bc before ab), since both would already
/// have joined a and b. Hence:
///  - its *finite* edges are Gabriel edges of their side, in the Delaunay triangulation of that
///    side (sites.hpp, 1): the seed's proof, which carries over because every site off the side
///    is at +∞ or beyond from the diametral disk;
///  - its *beyond-infinity* edge (only when no site is on Ω and both sides have sites: the tree
///    then has exactly one) is the pair maximizing |A − B̄|, whose cells share an arc of Ω of
///    positive length (sites.hpp, 2): an edge of the complex's band;
///  - its edges *at +∞* are where the seed's proof stops holding: every pair with a site on Ω
///    weighs +∞, so the strict |bc| < |ab| of the planar proof fails and the tree by indices
///    takes pairs that are not Delaunay edges (a site on Ω is joined to the first site that is
///    not yet connected to it). And with sites on Ω and an empty side the complex is undefined
///    (delaunay_t2.hpp) while this tree is not.
/// So the tree is built from the two planar triangulations, the pairs at +∞ by their indices and
/// the beyond-infinity pair from the hull vertices.
///
/// **Cost.** The triangulations, O(n log n); the finite edges radix-sorted by their double keys
/// (pair_distance.hpp), the exact order settling near ties (spanning_tree.cpp); the pairs at +∞ in O(n·k) for k
/// sites on Ω, in practice a few steps; the beyond-infinity pair over the hull vertices of the
/// two sides, O(h_F·h_B) (a calipers walk would be linear: not done).

#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "t2/kernel/point.hpp"
#include "t2/trace/hook.hpp"
#include "t2/triangulation/triangulation.hpp"

namespace t2 {

/// The minimum spanning tree of `points` under the T² distances of pair_distance.hpp, as
/// n − 1 pairs (i, j), i < j, in the order Kruskal takes them (see the file comment); empty for
/// fewer than two points. Never undefined; throws `BadInput` for more than 715 827 882 points.
std::vector<std::pair<Triangulation::Index, Triangulation::Index>> minimum_spanning_tree(std::span<const Point> points);

/// The same, telling `hook` (trace/hook.hpp), in input indices: each side's Delaunay
/// triangulation (`Event::candidates`), then every edge Kruskal takes (`Event::tree_edge`: the
/// equal sites, the Delaunay edges, the pairs at +∞, the pair beyond infinity) or drops
/// (`Event::cycle_edge`), with the union–find forest after it. Only this overload carries trace
/// code; the one above has none.
std::vector<std::pair<Triangulation::Index, Triangulation::Index>> minimum_spanning_tree(
    std::span<const Point> points, const trace::AnyHook& hook);

}  // namespace t2
