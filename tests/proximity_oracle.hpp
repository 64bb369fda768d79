#pragma once
// The oracles of the proximity tests (test_proximity*.cpp): random sites of T² with many ties
// and equal sites, and the T² distance of a pair as exact rationals, written from the
// definition of pair_distance.hpp without the kernel.
#include <gmpxx.h>

#include <algorithm>
#include <random>
#include <tuple>
#include <utility>
#include <vector>

#include "t2/kernel/point.hpp"

namespace t2::testing {

/// Which parts of T² the sites come from.
enum class Parts { front, back, mixed, front_omega, mixed_omega, omega };

/// n sites with small integer coordinates (ties, collinear and cocircular sites), some of them
/// repeated, some repeated with another positive scale (equal in T², different coordinates).
inline std::vector<Point> proximity_sites_random(std::mt19937& rng, Parts parts, int n, int range) {
  std::uniform_int_distribution<int> c(-range, range), coin(0, 9), wpick(0, 2);
  std::vector<Point> P;
  while (static_cast<int>(P.size()) < n) {
    if (!P.empty() && coin(rng) == 0) {  // a repeat, possibly scaled by 2
      const Point& q = P[std::uniform_int_distribution<std::size_t>(0, P.size() - 1)(rng)];
      const double s = coin(rng) < 5 ? 1 : 2;
      P.emplace_back(q.w() * s, q.x() * s, q.y() * s);
      continue;
    }
    int side = 1;  // +1 front, −1 back, 0 Ω
    const int r = coin(rng);
    switch (parts) {
      case Parts::front: side = 1; break;
      case Parts::back: side = -1; break;
      case Parts::mixed: side = r < 5 ? 1 : -1; break;
      case Parts::front_omega: side = r < 8 ? 1 : 0; break;
      case Parts::mixed_omega: side = r < 4 ? 1 : r < 8 ? -1 : 0; break;
      case Parts::omega: side = 0; break;
    }
    const int x = c(rng), y = c(rng);
    if (side == 0 && x == 0 && y == 0) continue;
    const int w = side * (wpick(rng) == 0 ? 2 : 1);
    P.emplace_back(w, x, y);
  }
  return P;
}

/// The weight of the pair {a, b} (pair_distance.hpp), from the definition: (class, value) with
/// class 0 equal or same side (value |A − B|²), 1 a site on Ω (value 0), 2 opposite sides
/// (value −|A − B|², the larger the nearer). Compared lexicographically.
inline std::pair<int, mpq_class> pair_weight(const Point& a, const Point& b) {
  const auto q = [](double v) { return mpq_class(v); };
  if (a.w() == 0 || b.w() == 0) {
    if (a.w() == 0 && b.w() == 0) {
      const mpq_class cross = q(a.x()) * q(b.y()) - q(a.y()) * q(b.x()), dot = q(a.x()) * q(b.x()) + q(a.y()) * q(b.y());
      if (cross == 0 && dot > 0) return {0, 0};
    }
    return {1, 0};
  }
  const mpq_class dx = q(a.x()) / q(a.w()) - q(b.x()) / q(b.w()), dy = q(a.y()) / q(a.w()) - q(b.y()) / q(b.w());
  const mpq_class d2 = dx * dx + dy * dy;
  if ((a.w() > 0) == (b.w() > 0)) return {0, d2};
  return {2, -d2};
}

using Edge = std::pair<std::uint32_t, std::uint32_t>;

/// Kruskal on all pairs in the order (weight, i, j): the tree spanning_tree.hpp promises.
inline std::vector<Edge> kruskal_all_pairs(const std::vector<Point>& P) {
  std::vector<std::tuple<int, mpq_class, std::uint32_t, std::uint32_t>> e;
  for (std::uint32_t i = 0; i < P.size(); ++i)
    for (std::uint32_t j = i + 1; j < P.size(); ++j) {
      auto [k, v] = pair_weight(P[i], P[j]);
      e.emplace_back(k, v, i, j);
    }
  std::sort(e.begin(), e.end());
  std::vector<std::uint32_t> comp(P.size());
  for (std::uint32_t i = 0; i < P.size(); ++i) comp[i] = i;
  std::vector<Edge> tree;
  for (auto& [k, v, i, j] : e) {
    const std::uint32_t ci = comp[i], cj = comp[j];
    if (ci == cj) continue;
    for (auto& c : comp)
      if (c == cj) c = ci;
    tree.emplace_back(i, j);
  }
  return tree;
}

/// Prim on all pairs: the sorted weights of a minimum tree (every minimum tree has them).
inline std::vector<std::pair<int, mpq_class>> prim_weights(const std::vector<Point>& P) {
  std::vector<std::pair<int, mpq_class>> out;
  if (P.size() < 2) return out;
  std::vector<char> in(P.size(), 0);
  std::vector<std::pair<int, mpq_class>> best(P.size());
  std::vector<char> has(P.size(), 0);
  std::uint32_t u = 0;
  in[0] = 1;
  for (std::size_t step = 1; step < P.size(); ++step) {
    for (std::uint32_t v = 0; v < P.size(); ++v)
      if (!in[v]) {
        const auto w = pair_weight(P[u], P[v]);
        if (!has[v] || w < best[v]) best[v] = w, has[v] = 1;
      }
    std::uint32_t next = 0;
    bool found = false;
    for (std::uint32_t v = 0; v < P.size(); ++v)
      if (!in[v] && (!found || best[v] < best[next])) next = v, found = true;
    in[next] = 1;
    out.push_back(best[next]);
    u = next;
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// The sorted weights of the edges `tree`.
inline std::vector<std::pair<int, mpq_class>> tree_weights(const std::vector<Point>& P, const std::vector<Edge>& tree) {
  std::vector<std::pair<int, mpq_class>> out;
  for (auto [i, j] : tree) out.push_back(pair_weight(P[i], P[j]));
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace t2::testing
