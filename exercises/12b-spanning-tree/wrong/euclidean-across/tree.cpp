// Wrong on purpose: Euclidean across the sides. With no site on Ω the two sides are joined by
// the pair nearest as drawn (brute force over all front-back pairs), as in the plane; in T² a
// front and a back site are beyond infinity, and the farther apart they are drawn the nearer.
#include "tree.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <utility>

#include <t2/kernel/pair_distance.hpp>

namespace ex12b {

std::vector<long> spanning_tree(const std::vector<t2::Point>& P, const std::vector<long>& E) {
  const long n = long(P.size());
  std::vector<std::pair<long, long>> cand;
  for (std::size_t k = 0; k + 1 < E.size(); k += 2) cand.push_back({E[k], E[k + 1]});
  std::sort(cand.begin(), cand.end(), [&](const auto& a, const auto& b) {
    return t2::compare_pair_distance(P[a.first], P[a.second], P[b.first], P[b.second]) < 0;
  });
  std::vector<long> F, B, omega;
  for (long i = 0; i < n; ++i) (P[i].w() > 0 ? F : P[i].w() < 0 ? B : omega).push_back(i);
  if (!omega.empty()) {
    for (long j = 0; j < n; ++j)
      if (j != omega[0]) cand.push_back({omega[0], j});
  } else if (!F.empty() && !B.empty()) {
    auto d2 = [&](long a, long b) {
      const double dx = P[a].x() / P[a].w() - P[b].x() / P[b].w(), dy = P[a].y() / P[a].w() - P[b].y() / P[b].w();
      return dx * dx + dy * dy;
    };
    std::pair<long, long> best{F[0], B[0]};
    for (long a : F)
      for (long b : B)
        if (d2(a, b) < d2(best.first, best.second)) best = {a, b};
    cand.push_back(best);
  }
  std::vector<long> parent(n), size(n, 1), T;
  std::iota(parent.begin(), parent.end(), 0L);
  auto find = [&](long x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto& [i, j] : cand) {
    long a = find(i), b = find(j);
    if (a == b) continue;
    if (size[a] < size[b]) std::swap(a, b);
    parent[b] = a;
    size[a] += size[b];
    T.insert(T.end(), {i, j});
  }
  return T;
}

}  // namespace ex12b
