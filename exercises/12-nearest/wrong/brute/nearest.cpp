// Wrong on purpose: right answers by brute force — every proper site compares all n − 1 others
// instead of its neighbours in E — so O(n²): too slow for the large hidden input.
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
  bool front = false, back = false;
  for (long i = 0; i < n; ++i) {
    (P[i].w() == 0 ? omega : proper).push_back(i);
    front |= P[i].w() > 0;
    back |= P[i].w() < 0;
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
      std::vector<long> all;
      for (long j = 0; j < n; ++j) all.push_back(j);
      nearest[i] = best_of(i, all);
      continue;
    }
    std::vector<long> close;  // the directions under 90° from z: nearer than any proper site
    for (long j : omega)
      if (j != i && (proper.empty() || t2::compare_distance(P[j], P[proper[0]], P[i]) < 0)) close.push_back(j);
    if (!close.empty()) {
      nearest[i] = best_of(i, close);
    } else if (front && back) {
      throw t2::Undefined("site " + std::to_string(i) + " on Ω: its nearest is a front or a back site, which no "
                          "distance of T² orders seen from it");
    } else {
      std::vector<long> all;  // one side: the sweep rule, then the directions beyond 90°
      for (long j = 0; j < n; ++j) all.push_back(j);
      nearest[i] = best_of(i, all);
    }
  }
  return nearest;
}

}  // namespace ex12
