// Exercise 10, reference solution: Lawson's algorithm on a map from directed edges to triangles.
#include "lawson.hpp"

#include <array>
#include <map>
#include <utility>

#include <t2/kernel/incircle.hpp>

namespace ex10 {

std::vector<long> delaunay_flips(const std::vector<t2::Point>& P, const std::vector<long>& T) {
  std::vector<std::array<long, 3>> tri;
  for (std::size_t k = 0; k + 2 < T.size(); k += 3) tri.push_back({T[k], T[k + 1], T[k + 2]});
  std::map<std::pair<long, long>, long> owner;  // directed edge a -> b: the triangle holding it
  auto link = [&](long t, bool on) {
    for (int i = 0; i < 3; ++i) {
      const std::pair<long, long> e{tri[t][i], tri[t][(i + 1) % 3]};
      if (on) owner[e] = t; else owner.erase(e);
    }
  };
  for (long t = 0; t < long(tri.size()); ++t) link(t, true);
  std::vector<std::pair<long, long>> stack;
  for (const auto& [e, t] : owner)
    if (e.first < e.second) stack.push_back(e);
  auto third = [&](long t, long a, long b) {
    for (long v : tri[t])
      if (v != a && v != b) return v;
    return -1L;
  };
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    const auto ab = owner.find({a, b}), ba = owner.find({b, a});
    if (ab == owner.end() || ba == owner.end()) continue;  // a hull edge, or flipped away
    const long t = ab->second, u = ba->second, c = third(t, a, b), d = third(u, b, a);
    // t = (a, b, c) and u = (b, a, d), counter-clockwise: illegal when d is inside the circle.
    if (t2::in_circle(P[a], P[b], P[c], P[d]) <= 0) continue;
    link(t, false);
    link(u, false);
    tri[t] = {a, d, c};  // the quadrilateral a, d, b, c, cut by c d
    tri[u] = {d, b, c};
    link(t, true);
    link(u, true);
    for (auto [x, y] : {std::pair{a, d}, {d, b}, {b, c}, {c, a}}) stack.push_back({std::min(x, y), std::max(x, y)});
  }
  std::vector<long> out;
  for (const auto& t : tri) out.insert(out.end(), t.begin(), t.end());
  return out;
}

}  // namespace ex10
