#pragma once
// Exercise 12b: the inputs and the check both test files use (part of the tests, not of your
// solution). The graph E of a set of sites is built by brute force, independently of the
// library's triangulations: a triangle of one side is Delaunay when no site of the side is
// strictly inside its circle (exact t2::in_circle), and E holds the edges of those triangles
// (O(n⁴): small sets only). A product grid {x_i} × {y_j} has its Delaunay edges known by
// construction: each cell is a rectangle, whose four corners are cocircular, so its sides and
// both diagonals hold every Delaunay edge. An answer is right when it is a spanning tree whose
// sorted weights equal those of a minimum tree term by term (every minimum tree has the same sorted weights:
// chapter 12, Theorem 1).
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <t2/kernel/distance.hpp>
#include <t2/kernel/error.hpp>
#include <t2/kernel/incircle.hpp>
#include <t2/kernel/orient.hpp>
#include <t2/kernel/point.hpp>
#include <t2/kernel/pair_distance.hpp>

namespace ex12btest {

using t2::Point;

/// The drawn position of a proper site as a front point.
inline Point front(const Point& p) { return p.w() < 0 ? Point(-p.w(), -p.x(), -p.y()) : p; }

/// Appends to E the Delaunay edges of the sites `S` of one side (brute force, see above).
inline void side_edges(const std::vector<Point>& P, const std::vector<long>& S, std::vector<long>& E) {
  if (S.size() == 2) E.insert(E.end(), {S[0], S[1]});
  for (std::size_t a = 0; a < S.size(); ++a)
    for (std::size_t b = a + 1; b < S.size(); ++b)
      for (std::size_t c = b + 1; c < S.size(); ++c) {
        Point A = front(P[S[a]]), B = front(P[S[b]]), C = front(P[S[c]]);
        const t2::Sign o = t2::orient(A, B, C);
        if (o == t2::ZERO) continue;
        if (o < 0) std::swap(B, C);
        bool empty = true;
        for (std::size_t d = 0; d < S.size() && empty; ++d) empty = t2::in_circle(A, B, C, front(P[S[d]])) <= 0;
        if (empty) E.insert(E.end(), {S[a], S[b], S[b], S[c], S[c], S[a]});
      }
}

/// The graph of the statement for small P: Delaunay edges of the front and of the back sites.
inline std::vector<long> brute_graph(const std::vector<Point>& P) {
  std::vector<long> F, B, E;
  for (long i = 0; i < long(P.size()); ++i) {
    if (P[i].w() > 0) F.push_back(i);
    if (P[i].w() < 0) B.push_back(i);
  }
  side_edges(P, F, E);
  side_edges(P, B, E);
  return E;
}

/// Appends the product grid {x_0 < … < x_{m−1}} × {y_0 < … < y_{m−1}} (random gaps in [1, 2)),
/// with weight w (its sign is the side), and its cells' sides and diagonals to E.
inline void product_grid(std::mt19937_64& g, int m, double w, std::vector<Point>& P, std::vector<long>& E) {
  std::uniform_real_distribution<double> gap(1, 2);
  std::vector<double> x(m), y(m);
  for (int k = 1; k < m; ++k) x[k] = x[k - 1] + gap(g), y[k] = y[k - 1] + gap(g);
  const long base = long(P.size());
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) P.push_back(Point(w, x[i] * w, y[j] * w));
  auto at = [&](int i, int j) { return base + long(i) * m + j; };
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      if (i + 1 < m) E.insert(E.end(), {at(i, j), at(i + 1, j)});
      if (j + 1 < m) E.insert(E.end(), {at(i, j), at(i, j + 1)});
      if (i + 1 < m && j + 1 < m) E.insert(E.end(), {at(i, j), at(i + 1, j + 1), at(i + 1, j), at(i, j + 1)});
    }
}

/// "" when T is a spanning tree of P whose sorted weights equal those of `want`, else what is wrong.
inline std::string check(const std::vector<Point>& P, const std::vector<long>& T, const std::vector<long>& want) {
  const long n = long(P.size());
  if (long(T.size()) != 2 * std::max(n - 1, 0L))
    return "the answer has " + std::to_string(T.size()) + " indices, a tree of " + std::to_string(n) + " sites " +
           std::to_string(2 * std::max(n - 1, 0L));
  std::vector<long> parent(P.size());
  std::iota(parent.begin(), parent.end(), 0L);
  auto find = [&](long x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (std::size_t k = 0; k < T.size(); k += 2) {
    if (T[k] < 0 || T[k] >= n || T[k + 1] < 0 || T[k + 1] >= n) return "a site index out of range";
    if (find(T[k]) == find(T[k + 1]))
      return "the pair " + std::to_string(T[k]) + " " + std::to_string(T[k + 1]) + " closes a cycle";
    parent[find(T[k])] = find(T[k + 1]);
  }
  auto sorted = [&](const std::vector<long>& U) {
    std::vector<std::pair<long, long>> w;
    for (std::size_t k = 0; k + 1 < U.size(); k += 2) w.push_back({U[k], U[k + 1]});
    std::sort(w.begin(), w.end(), [&](const auto& a, const auto& b) {
      return t2::compare_pair_distance(P[a.first], P[a.second], P[b.first], P[b.second]) < 0;
    });
    return w;
  };
  const auto got = sorted(T), best = sorted(want);
  for (std::size_t k = 0; k < got.size(); ++k)
    if (t2::compare_pair_distance(P[got[k].first], P[got[k].second], P[best[k].first], P[best[k].second]) != 0)
      return "the " + std::to_string(k + 1) + "-th lightest edge " + std::to_string(got[k].first) + " " +
             std::to_string(got[k].second) + " does not weigh the same as the " + std::to_string(k + 1) +
             "-th of a minimum tree (" + std::to_string(best[k].first) + " " + std::to_string(best[k].second) + ")";
  return "";
}

}  // namespace ex12btest
