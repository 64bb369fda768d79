// Algorithm 14 in T² (t2/proximity/nearest_neighbors.hpp).
#include "t2/proximity/nearest_neighbors.hpp"

#include <algorithm>
#include <string>

#include "t2/kernel/distance.hpp"
#include "t2/kernel/error.hpp"
#include "t2/kernel/filter.hpp"
#include "t2/kernel/pair_distance.hpp"
#include "t2/proximity/sites.hpp"

namespace t2 {
namespace {

using Index = Triangulation::Index;
constexpr Index none = Triangulation::none;

/// The nearest to c of `best` and j by the three-point order, the smaller index on a tie.
Index nearer(std::span<const Point> P, Index c, Index best, Index j) {
  if (best == none) return j;
  const Sign s = compare_distance(P[j], P[best], P[c]);
  return s == NEGATIVE || (s == ZERO && j < best) ? j : best;
}

/// The nearest to c among `cands` (c itself left out), or none.
Index nearest_of(std::span<const Point> P, Index c, const std::vector<Index>& cands) {
  Index best = none;
  for (Index j : cands)
    if (j != c) best = nearer(P, c, best, j);
  return best;
}

/// The nearest site to z on Ω (no site equal to z): see the file comment for the rule and the
/// one undefined case.
Index nearest_to_direction(std::span<const Point> P, const ProximitySites& s, Index z) {
  const Index bz = nearest_of(P, z, s.omega);
  Sign angle = NEGATIVE;  // the sign of cos of bz's angle to z: POSITIVE under 90°
  if (bz != none)  // exact: the filtered sign of the dot product of two directions
    angle = sign_of_poly([](const auto& p, const auto& q) { return p.x * q.x + p.y * q.y; }, P[bz], P[z]);
  if (bz != none && angle == POSITIVE) return bz;
  const Index bf = nearest_of(P, z, s.front_extremes), bb = nearest_of(P, z, s.back_extremes);
  if (bz != none && angle == ZERO) {  // ties with every proper site
    if (bf != none && bb != none) return bz;
    const Index bp = bf != none ? bf : bb;
    return bp != none && bp < bz ? bp : bz;
  }
  if (bf != none && bb != none)
    throw UndefinedNearest(z, "all_nearest_neighbors: the nearest sites to the site " + std::to_string(z) +
                    " on Omega are the front site " + std::to_string(bf) + " and the back site " + std::to_string(bb) +
                    ", which no distance of T2 orders (approaching Omega from either side gives opposite answers)");
  if (bf != none) return bf;
  if (bb != none) return bb;
  return bz;
}

}  // namespace

//> all-nearest-neighbors
std::vector<Index> all_nearest_neighbors(std::span<const Point> P) {
  if (P.size() < 2) throw BadInput("all_nearest_neighbors: needs at least two sites");
  const ProximitySites s = proximity_sites(P);
  std::vector<Index> nearest(P.size(), none);
  // Equal sites: distance 0; the first of them is nearest to the others, the second to it.
  for (Index i = 0; i < P.size(); ++i) {
    const Index k = s.kept[i];
    if (k == i) continue;
    nearest[i] = k;
    if (nearest[k] == none) nearest[k] = i;  // i ascending: the smallest other equal site
  }
  std::vector<char> equal(P.size(), 0);
  for (Index i = 0; i < P.size(); ++i) equal[i] = nearest[i] != none;
  // Algorithm 14: the Delaunay neighbours on each side, every edge offered to both ends —
  // by the edges' keys (pair_distance.hpp) where every edge has one, the exact order deciding
  // between near keys; otherwise exactly.
  std::vector<double> key(s.edges.size());
  bool keyed = true;
  for (std::size_t m = 0; m < s.edges.size() && keyed; ++m) {
    key[m] = finite_key(P[s.edges[m].first], P[s.edges[m].second]);
    keyed = key[m] >= 0;
  }
  std::vector<double> best_key(keyed ? P.size() : 0);
  const auto offer = [&](Index v, Index u, double k) {
    if (equal[v]) return;
    if (!keyed) {
      nearest[v] = nearer(P, v, nearest[v], u);
      return;
    }
    if (nearest[v] == none || (k < best_key[v] && !keys_near(k, best_key[v]))) {
      nearest[v] = u, best_key[v] = k;
    } else if (keys_near(std::min(k, best_key[v]), std::max(k, best_key[v]))) {
      const Index w = nearer(P, v, nearest[v], u);
      if (w != nearest[v]) nearest[v] = w, best_key[v] = k;
    }
  };
  for (std::size_t m = 0; m < s.edges.size(); ++m) {
    offer(s.edges[m].first, s.edges[m].second, key[m]);
    offer(s.edges[m].second, s.edges[m].first, key[m]);
  }
  // Sites without a neighbour on their side, and the sites of Ω.
  for (Index i = 0; i < P.size(); ++i) {
    if (nearest[i] != none) continue;
    if (P[i].w() == 0) {
      nearest[i] = nearest_to_direction(P, s, i);
    } else {
      nearest[i] = nearest_of(P, i, s.omega);
      if (nearest[i] == none) nearest[i] = nearest_of(P, i, P[i].w() > 0 ? s.back_extremes : s.front_extremes);
    }
  }
  // A site equal to another's nearest is as near: the first of them is the answer (kept).
  for (Index i = 0; i < P.size(); ++i)
    if (!equal[i]) nearest[i] = s.kept[nearest[i]];
  return nearest;
}
//< all-nearest-neighbors

}  // namespace t2
