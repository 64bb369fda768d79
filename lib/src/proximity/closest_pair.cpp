// The closest pair of T², brute force and from the Delaunay edges (t2/proximity/closest_pair.hpp).
#include "t2/proximity/closest_pair.hpp"

#include <algorithm>
#include <vector>

#include "t2/kernel/error.hpp"
#include "t2/kernel/pair_distance.hpp"
#include "t2/proximity/sites.hpp"
#include "pair_rules.hpp"

namespace t2 {

using Index = Triangulation::Index;
using Pair = std::pair<Index, Index>;

Pair closest_pair_brute(std::span<const Point> P) {
  if (P.size() < 2) throw BadInput("closest_pair: needs at least two sites");
  Pair best{0, 1};
  for (Index i = 0; i < P.size(); ++i)
    for (Index j = i + 1; j < P.size(); ++j)  // pairs in lexicographic order: only a nearer one replaces
      if (compare_pair_distance(P[i], P[j], P[best.first], P[best.second]) == NEGATIVE) best = {i, j};
  return best;
}

//> closest-pair
Pair closest_pair(std::span<const Point> P) {
  if (P.size() < 2) throw BadInput("closest_pair: needs at least two sites");
  const ProximitySites s = proximity_sites(P);
  Pair best = detail::equal_sites_pair(s.kept);
  if (best.first != Triangulation::none) return best;
  // Finite: the Delaunay edges of each side; by their keys first (one pass over the points),
  // where every edge has one; only the keys near the least can be the nearest.
  std::vector<double> keys(s.edges.size());
  double least = -1;
  for (std::size_t m = 0; m < s.edges.size(); ++m) {
    keys[m] = finite_key(P[s.edges[m].first], P[s.edges[m].second]);
    if (keys[m] < 0) {
      least = -1;
      break;
    }
    if (least < 0 || keys[m] < least) least = keys[m];
  }
  for (std::size_t m = 0; m < s.edges.size(); ++m) {
    const Pair& e = s.edges[m];
    if (least < 0 || keys_near(least, keys[m]))
      if (best.first == Triangulation::none || pair_before(P, e.first, e.second, best.first, best.second)) best = e;
  }
  if (best.first != Triangulation::none) return best;
  return detail::pair_without_finite_distance(P, s.omega.empty() ? Triangulation::none : s.omega.front());
}
//< closest-pair

}  // namespace t2
