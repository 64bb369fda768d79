// Wrong on purpose: a right tree by brute force — Prim's algorithm over all n(n − 1)/2 pairs
// with the exact t2::compare_pair_distance, ignoring E — so Θ(n²): too slow for the large
// hidden input.
#include "tree.hpp"

#include <t2/kernel/pair_distance.hpp>

namespace ex12b {

std::vector<long> spanning_tree(const std::vector<t2::Point>& P, const std::vector<long>& E) {
  (void)E;
  const long n = long(P.size());
  std::vector<long> T, link(n, 0);  // link[v]: the tree site nearest to v
  std::vector<bool> in(n, false);
  if (n < 2) return T;
  in[0] = true;
  for (long step = 1; step < n; ++step) {
    long next = -1;
    for (long v = 0; v < n; ++v)
      if (!in[v] && (next < 0 || t2::compare_pair_distance(P[v], P[link[v]], P[next], P[link[next]]) < 0)) next = v;
    in[next] = true;
    T.insert(T.end(), {link[next], next});
    for (long v = 0; v < n; ++v)
      if (!in[v] && t2::compare_pair_distance(P[v], P[next], P[v], P[link[v]]) < 0) link[v] = next;
  }
  return T;
}

}  // namespace ex12b
