#pragma once
/// @file ear_clipping.hpp
/// @brief Triangulating a simple polygon by cutting off ears (Meisters' two-ears theorem).

#include <array>
#include <cstddef>
#include <vector>

#include "t2/kernel/error.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/polygon.hpp"

namespace t2 {

/// A triangle of a triangulation: three indices into the polygon's vertex list.
using IndexTriangle = std::array<std::size_t, 3>;

/// Triangulates the simple polygon P (vertices all on the front side or all on the back
/// side of T²) by ear clipping: repeatedly cut off a vertex v whose neighbours u, w see each
/// other inside P — Δ(u, v, w) has the orientation of P and no other remaining vertex lies in
/// the closed triangle uvw. Returns n − 2 triangles (indices into P), each ordered like P, whose
/// areas add up to the area of P. When collinear vertices leave no strict ear, a straight
/// vertex (on the segment between its neighbours) is cut off as a zero-area triangle.
///
/// Exact (only Δ signs). O(n³) in the worst case, O(n²) typically: a teaching version.
/// Throws `Undefined` when the vertices are not all proper on one side, when P has zero area,
/// or when no ear can be found (P is not simple).
template <class T>
std::vector<IndexTriangle> ear_clipping(const BasicPolygon<T>& P) {
  const std::size_t n = P.size();
  if (n < 3) throw Undefined("ear_clipping(P) needs a polygon of at least 3 vertices");
  const Sign o = orientation(P);  // checks the side too
  if (o == ZERO) throw Undefined("ear_clipping(P) needs a simple polygon (this one has zero area)");
  std::vector<std::size_t> prev(n), next(n);
  for (std::size_t i = 0; i < n; ++i) {
    prev[i] = (i + n - 1) % n;
    next[i] = (i + 1) % n;
  }
  //> ear-test
  // v is an ear when it turns like P and no other remaining vertex is in the closed
  // triangle.
  auto is_ear = [&](std::size_t v) {
    const std::size_t u = prev[v], w = next[v];
    if (orient(P[u], P[v], P[w]) != o) return false;
    for (std::size_t j = next[w]; j != u; j = next[j])
      if (orient(P[u], P[v], P[j]) != -o && orient(P[v], P[w], P[j]) != -o &&
          orient(P[w], P[u], P[j]) != -o)
        return false;  // P[j] inside or on the triangle uvw
    return true;
  };
  //< ear-test
  auto is_straight = [&](std::size_t v) {
    return orient(P[prev[v]], P[v], P[next[v]]) == ZERO && on_segment(P[prev[v]], P[next[v]], P[v]);
  };
  std::vector<IndexTriangle> out;
  out.reserve(n - 2);
  std::size_t m = n, v = 0;
  auto cut = [&](std::size_t x) {
    out.push_back({prev[x], x, next[x]});
    next[prev[x]] = next[x];
    prev[next[x]] = prev[x];
    --m;
    return next[x];
  };
  while (m > 3) {
    std::size_t tries = 0;
    while (tries < m && !is_ear(v)) {
      v = next[v];
      ++tries;
    }
    if (tries < m) {
      v = cut(v);
      continue;
    }
    tries = 0;
    while (tries < m && !is_straight(v)) {
      v = next[v];
      ++tries;
    }
    if (tries == m) throw Undefined("ear_clipping(P) found no ear: P is not a simple polygon");
    v = cut(v);
  }
  out.push_back({prev[v], v, next[v]});
  return out;
}

}  // namespace t2
