// Wrong on purpose: right for the proper sites, but a site of Ω scans all other sites with
// t2::compare_distance. The scan compares a front and a back site, which throws t2::Undefined
// even when a direction under 90° is the nearest of all.
#include "nearest.hpp"

#include <t2/kernel/distance.hpp>
#include <t2/kernel/error.hpp>

namespace ex12 {

std::vector<long> nearest_neighbours(const std::vector<t2::Point>& P, const std::vector<long>& E) {
  const long n = long(P.size());
  std::vector<std::vector<long>> adj(n);
  for (std::size_t k = 0; k + 1 < E.size(); k += 2) {
    adj[E[k]].push_back(E[k + 1]);
    adj[E[k + 1]].push_back(E[k]);
  }
  std::vector<long> omega, proper;
  for (long i = 0; i < n; ++i) {
    (P[i].w() == 0 ? omega : proper).push_back(i);
  }
  // The nearest to i among `cands` (none equal to i), ties to the smallest index.
  auto best_of = [&](long i, const std::vector<long>& cands) {
    long best = -1;
    for (long j : cands) {
      if (j == i) continue;
      const t2::Sign s = best < 0 ? t2::NEGATIVE : t2::compare_distance(P[j], P[best], P[i]);
      if (s < 0 || (s == 0 && j < best)) best = j;
    }
    return best;
  };
  std::vector<long> nearest(n);
  for (long i = 0; i < n; ++i) {
    if (P[i].w() != 0) {
      // Lemma 3: a site of the same side, if any, is a neighbour in E; then Ω (at +∞); then the
      // other side (beyond infinity).
      nearest[i] = !adj[i].empty() ? best_of(i, adj[i]) : !omega.empty() ? best_of(i, omega) : best_of(i, proper);
      continue;
    }
    std::vector<long> all;
    for (long j = 0; j < n; ++j) all.push_back(j);
    nearest[i] = best_of(i, all);
  }
  return nearest;
}

}  // namespace ex12
