// Wrong on purpose: Euclidean only. Every site is its drawn point (x/w, y/w) and the nearest is
// the one at the smallest Euclidean distance: right among the neighbours of one side, wrong for a
// site alone on its side (the other side is beyond infinity: the farthest drawn is the nearest),
// and the sites of Ω, which have no drawn point, are skipped as candidates and given the
// nearest proper site by the sweep of the plane towards them, never undefined.
#include "nearest.hpp"

#include <cmath>

namespace ex12 {

std::vector<long> nearest_neighbours(const std::vector<t2::Point>& P, const std::vector<long>& E) {
  const long n = long(P.size());
  std::vector<std::vector<long>> adj(n);
  for (std::size_t k = 0; k + 1 < E.size(); k += 2) {
    adj[E[k]].push_back(E[k + 1]);
    adj[E[k + 1]].push_back(E[k]);
  }
  auto dist = [&](long i, long j) {
    return std::hypot(P[i].x() / P[i].w() - P[j].x() / P[j].w(), P[i].y() / P[i].w() - P[j].y() / P[j].w());
  };
  std::vector<long> nearest(n, -1);
  for (long i = 0; i < n; ++i) {
    double d = INFINITY;
    if (P[i].w() == 0) {  // the proper site furthest towards the direction (x, y)
      for (long j = 0; j < n; ++j) {
        if (P[j].w() == 0) continue;
        const double s = -(P[i].x() * P[j].x() + P[i].y() * P[j].y()) / P[j].w();
        if (s < d) d = s, nearest[i] = j;
      }
      if (nearest[i] < 0) nearest[i] = i == 0 ? 1 : 0;
      continue;
    }
    std::vector<long> cands = adj[i];
    if (cands.empty())
      for (long j = 0; j < n; ++j)
        if (j != i && P[j].w() != 0) cands.push_back(j);
    for (long j : cands)
      if (dist(i, j) < d || (dist(i, j) == d && j < nearest[i])) d = dist(i, j), nearest[i] = j;
    if (nearest[i] < 0) nearest[i] = i == 0 ? 1 : 0;
  }
  return nearest;
}

}  // namespace ex12
