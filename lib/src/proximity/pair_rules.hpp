#pragma once
// The two rules that closest_pair and closest_pair_divide share (t2/proximity/closest_pair.hpp),
// written once: equal sites come first, and where no side has two distinct sites the pair is
// the first of the least distance class there is. Private to lib/src/proximity.
#include <span>
#include <utility>
#include <vector>

#include "t2/kernel/point.hpp"
#include "t2/triangulation/triangulation.hpp"

namespace t2::detail {

using SitePair = std::pair<Triangulation::Index, Triangulation::Index>;

/// The smallest pair (first, another) of equal sites, where kept[i] is the smallest index of a
/// site equal to site i; {none, none} when the sites are distinct.
inline SitePair equal_sites_pair(const std::vector<Triangulation::Index>& kept) {
  SitePair best{Triangulation::none, Triangulation::none};
  for (Triangulation::Index i = 0; i < kept.size(); ++i)
    if (kept[i] != i) best = std::min(best, SitePair{kept[i], i});
  return best;
}

/// The pair when the distinct sites have no finite distance (no side holds two of them):
/// with a site on Ω every pair holding one is +∞, all level, and nearer than a front site and a
/// back site (beyond infinity), so the smallest such pair, (0, 1) when site 0 is on Ω, else
/// (0, the first site on Ω); without one, the sites are one front and one back site: (0, 1).
/// `first_omega`: the smallest index of a site on Ω, or none.
inline SitePair pair_without_finite_distance(std::span<const Point> P, Triangulation::Index first_omega) {
  if (first_omega != Triangulation::none) return {0, P[0].w() == 0 ? 1 : first_omega};
  return {0, 1};
}

}  // namespace t2::detail
