#pragma once
// Exercise 12: the inputs both test files use (part of the tests, not of your solution). The graph E of a set of sites is built by brute force, independently of the
// library's triangulations: a triangle of one side is Delaunay when no site of the side is
// strictly inside its circle (exact t2::in_circle), and E holds the edges of those triangles
// (O(n⁴): small sets only). A product grid {x_i} × {y_j} has its Delaunay edges known by
// construction: each cell is a rectangle, whose four corners are cocircular, so its sides and
// both diagonals hold every Delaunay edge.
#include <cstdint>
#include <random>
#include <vector>

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

}  // namespace ex12test
