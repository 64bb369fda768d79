#pragma once
// Exercise 09: the exact certificate both test files check an answer with (part of the tests,
// not of your solution): every triangle counter-clockwise (exact), every directed edge used
// once, every point a vertex, every boundary edge with all points on its left or on it, and the
// triangles' exact rational areas summing to the area of the convex hull (computed here by the
// monotone chain with the exact t2::orient).
#include <algorithm>
#include <map>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include <t2/kernel/lexicographic.hpp>
#include <t2/kernel/number.hpp>
#include <t2/kernel/orient.hpp>
#include <t2/kernel/point.hpp>

namespace ex09test {

/// Twice the area of a b c, exactly (front points).
inline t2::Rational area2(const t2::Point& a, const t2::Point& b, const t2::Point& c) {
  auto q = [](double v) { return t2::to_rational(v); };
  const t2::Rational ax = q(a.x()) / q(a.w()), ay = q(a.y()) / q(a.w()), bx = q(b.x()) / q(b.w()),
                     by = q(b.y()) / q(b.w()), cx = q(c.x()) / q(c.w()), cy = q(c.y()) / q(c.w());
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

/// Twice the area of the convex hull of P (monotone chain, exact).
inline t2::Rational hull_area2(const std::vector<t2::Point>& P) {
  std::vector<long> idx(P.size()), h;
  std::iota(idx.begin(), idx.end(), 0L);
  std::sort(idx.begin(), idx.end(), [&](long a, long b) { return t2::compare_xy(P[a], P[b]) < 0; });
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t base = h.size();
    for (long p : idx) {
      while (h.size() >= base + 2 && t2::orient(P[h[h.size() - 2]], P[h.back()], P[p]) <= 0) h.pop_back();
      h.push_back(p);
    }
    h.pop_back();
    std::reverse(idx.begin(), idx.end());
  }
  t2::Rational a = 0;
  for (std::size_t k = 1; k + 1 < h.size(); ++k) a += area2(P[h[0]], P[h[k]], P[h[k + 1]]);
  return a;
}

/// "" when T is a triangulation of P (see the file comment), else what is wrong.
inline std::string check(const std::vector<t2::Point>& P, const std::vector<long>& T) {
  if (T.size() % 3 != 0) return "the list's length is not a multiple of 3";
  std::map<std::pair<long, long>, long> edges;
  std::vector<char> vertex(P.size(), 0);
  t2::Rational area = 0;
  for (std::size_t k = 0; k < T.size(); k += 3) {
    for (int i = 0; i < 3; ++i) {
      if (T[k + i] < 0 || T[k + i] >= long(P.size())) return "a vertex index out of range";
      vertex[T[k + i]] = 1;
      if (!edges.emplace(std::pair{T[k + i], T[k + (i + 1) % 3]}, long(k / 3)).second)
        return "the directed edge " + std::to_string(T[k + i]) + " -> " + std::to_string(T[k + (i + 1) % 3]) +
               " is in two triangles: triangles overlap";
    }
    if (t2::orient(P[T[k]], P[T[k + 1]], P[T[k + 2]]) != t2::POSITIVE)
      return "triangle " + std::to_string(T[k]) + " " + std::to_string(T[k + 1]) + " " + std::to_string(T[k + 2]) +
             " is not counter-clockwise (or is flat)";
    area += area2(P[T[k]], P[T[k + 1]], P[T[k + 2]]);
  }
  for (std::size_t v = 0; v < P.size(); ++v)
    if (!vertex[v]) return "point " + std::to_string(v) + " is not a vertex";
  for (const auto& [e, t] : edges)
    if (!edges.count({e.second, e.first}))
      for (std::size_t v = 0; v < P.size(); ++v)
        if (t2::orient(P[e.first], P[e.second], P[v]) < 0)
          return "the boundary edge " + std::to_string(e.first) + " -> " + std::to_string(e.second) +
                 " is not a hull edge: point " + std::to_string(v) + " is outside it";
  if (area != hull_area2(P)) return "the triangles do not cover the convex hull exactly once";
  return "";
}

}  // namespace ex09test
