#pragma once
/// @file nearest_neighbors.hpp
/// @brief All nearest neighbours of sites of T² (seed 000 §5.6, Algorithm 14): each site's
/// nearest other site, from the Delaunay neighbours of its side.
///
/// **The order.** Site i's neighbours are compared by the kernel's three-point
/// `compare_distance(a, b, i)` (distance.hpp): the reference point is fixed, which is what
/// Algorithm 14 asks ("the angle from the origin when a site is improper"). For a proper i: the
/// other sites of its side by Euclidean distance, then the sites of Ω by their angle with i at
/// the origin of R³, then the other side, the farthest drawn the nearest. For i on Ω: the other
/// directions under 90° from i, then the proper sites by the sweep rule, then the directions
/// beyond 90° (the 90° convention of distance.hpp). Equal sites are at distance 0.
///
/// **Ties.** Among equally near sites the one of smallest index. (Every site equally nearest to
/// a proper i on its side is a Delaunay neighbour of i: the Gabriel argument of sites.hpp, 1,
/// applied to i and that site — a third site in their diametral disk would be strictly nearer
/// to i. So the smallest index among them is found from the triangulation.)
///
/// **Undefined** (`Undefined`): a site z on Ω with sites on both sides and no other direction at
/// 90° or less from z: its nearest are the front site and the back site extreme towards z,
/// which the kernel cannot compare (approaching z from the front or from the back gives
/// opposite answers). When a direction at exactly 90° ties with them it is the answer (it is
/// no farther than any site), and so is it with one side only when its index is the smaller.
///
/// **Cost.** The two planar Delaunay triangulations and one comparison per edge end; a proper
/// site alone on its side scans the sites of Ω or the other side's hull vertices; each site of
/// Ω scans the sites of Ω and the hull vertices of both sides: O(n log n + k(k + h)).

#include <span>
#include <string>
#include <vector>

#include "t2/kernel/error.hpp"
#include "t2/kernel/point.hpp"
#include "t2/triangulation/triangulation.hpp"

namespace t2 {

/// The `Undefined` of `all_nearest_neighbors`, naming the site on Ω whose nearest is undefined.
class UndefinedNearest : public Undefined {
 public:
  /// @param site the site on Ω; @param rule what the message says
  UndefinedNearest(Triangulation::Index site, const std::string& rule) : Undefined(rule), site(site) {}
  Triangulation::Index site;  ///< the input index of that site
};

/// nearest[i]: the nearest site to site i other than i itself (see the file comment). Throws
/// `BadInput` for fewer than two sites, `UndefinedNearest` where the file comment
/// says.
std::vector<Triangulation::Index> all_nearest_neighbors(std::span<const Point> points);

}  // namespace t2
