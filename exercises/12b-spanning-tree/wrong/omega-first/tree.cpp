// Wrong on purpose: the pairs with a site of Ω go first, before the pairs of E, as if a
// direction, having no distance to a proper site, were at distance 0 from it: the tree takes
// +∞ edges where finite ones would do.
#include "tree.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <utility>

#include <t2/kernel/lexicographic.hpp>
#include <t2/kernel/orient.hpp>
#include <t2/kernel/pair_distance.hpp>

namespace ex12b {

namespace {

// The drawn position of a proper site as a front point.
t2::Point drawn(const t2::Point& p) { return p.w() < 0 ? t2::Point(-p.w(), -p.x(), -p.y()) : p; }

// The hull corners of the sites S of one side (monotone chain on the drawn positions, exact).
std::vector<long> corners(const std::vector<t2::Point>& P, std::vector<long> S) {
  if (S.size() < 3) return S;
  std::sort(S.begin(), S.end(), [&](long a, long b) { return t2::compare_xy(drawn(P[a]), drawn(P[b])) < 0; });
  std::vector<long> h(2 * S.size());
  std::size_t k = 0;
  auto turn = [&](long a, long b, long c) { return t2::orient(drawn(P[a]), drawn(P[b]), drawn(P[c])); };
  for (std::size_t i = 0; i < S.size(); ++i) {
    while (k >= 2 && turn(h[k - 2], h[k - 1], S[i]) <= 0) --k;
    h[k++] = S[i];
  }
  for (std::size_t i = S.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && turn(h[k - 2], h[k - 1], S[i]) <= 0) --k;
    h[k++] = S[i];
  }
  h.resize(k - 1);
  return h;
}

}  // namespace

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
    for (long j = n - 1; j >= 0; --j)
      if (j != omega[0]) cand.insert(cand.begin(), {omega[0], j});
  } else if (!F.empty() && !B.empty()) {
    const std::vector<long> cf = corners(P, F), cb = corners(P, B);
    std::pair<long, long> best{cf[0], cb[0]};
    for (long a : cf)
      for (long b : cb)
        if (t2::compare_pair_distance(P[a], P[b], P[best.first], P[best.second]) < 0) best = {a, b};
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
