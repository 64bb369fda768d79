#pragma once
// Exercise 12: the inputs and the oracle both test files use (part of the tests, not of your
// solution). The graph E of a set of sites is built by brute force, independently of the
// library's triangulations: a triangle of one side is Delaunay when no site of the side is
// strictly inside its circle (exact t2::in_circle), and E holds the edges of those triangles
// (O(n⁴): small sets only). A product grid {x_i} × {y_j} has its Delaunay edges known by
// construction: each cell is a rectangle, whose four corners are cocircular, so its sides and
// both diagonals hold every Delaunay edge. The oracle is brute force over all sites with the exact
// t2::compare_distance.
#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include <t2/kernel/distance.hpp>
#include <t2/kernel/error.hpp>
#include <t2/kernel/incircle.hpp>
#include <t2/kernel/orient.hpp>
#include <t2/kernel/point.hpp>

namespace ex12test {

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

/// Site i's nearest by brute force over all sites; nullopt when undefined. A site z of Ω is
/// undefined exactly when no other direction is under 90° from z and both sides hold sites.
inline std::optional<long> brute_nearest(const std::vector<Point>& P, long i) {
  bool front = false, back = false;
  long proper = -1;
  for (long j = 0; j < long(P.size()); ++j) {
    front |= P[j].w() > 0, back |= P[j].w() < 0;
    if (P[j].w() != 0) proper = j;
  }
  long best = -1;
  if (P[i].w() == 0 && front && back) {
    // Only a direction under 90° from z, nearer than every proper site by the 90° convention
    // (compare_distance against any proper site), settles it: the nearest is the best of them.
    for (long j = 0; j < long(P.size()); ++j)
      if (j != i && P[j].w() == 0 && t2::compare_distance(P[j], P[proper], P[i]) < 0 &&
          (best < 0 || t2::compare_distance(P[j], P[best], P[i]) < 0))
        best = j;
    if (best < 0) return std::nullopt;
    return best;
  }
  for (long j = 0; j < long(P.size()); ++j)  // never undefined here: one side, or i proper
    if (j != i && (best < 0 || t2::compare_distance(P[j], P[best], P[i]) < 0)) best = j;
  return best;
}

/// The whole answer by brute force; nullopt when some site's nearest is undefined.
inline std::optional<std::vector<long>> brute(const std::vector<Point>& P) {
  std::vector<long> r(P.size());
  for (long i = 0; i < long(P.size()); ++i) {
    const auto b = brute_nearest(P, i);
    if (!b) return std::nullopt;
    r[i] = *b;
  }
  return r;
}

}  // namespace ex12test
