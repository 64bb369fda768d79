#pragma once
// Exercise 09b: how both test files judge an answer (part of the tests, not of your solution).
// First an exact certificate that the answer is a triangulation with the infinite vertex of the
// vertices of T and q: every directed edge once and its reverse once, Euler's formula, every
// finite triangle counter-clockwise, every vertex on the inner side of every hull edge, and the
// finite triangles' areas summing exactly (rationals, in the chart of a pole of the points'
// hemisphere) to the area the hull edges enclose. Then the
// answer the rules of insert.hpp make unique, which the test knows, as a set of triangles.
#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <t2/kernel/number.hpp>
#include <t2/kernel/orient.hpp>
#include <t2/kernel/point.hpp>

#include "insert.hpp"

namespace ex09btest {

using Tri = std::array<long, 3>;

/// The triangles of a flat list, each rotated to start at its smallest index (v∞ = -1 first), sorted.
inline std::vector<Tri> canonical(const std::vector<long>& T) {
  std::vector<Tri> r;
  for (std::size_t k = 0; k + 2 < T.size(); k += 3) {
    Tri t = {T[k], T[k + 1], T[k + 2]};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    r.push_back(t);
  }
  std::sort(r.begin(), r.end());
  return r;
}

inline std::string name(const Tri& t) {
  auto v = [](long i) { return i == ex09b::kInfinite ? std::string("inf") : std::to_string(i); };
  return "(" + v(t[0]) + ", " + v(t[1]) + ", " + v(t[2]) + ")";
}

using Vec = std::array<t2::Rational, 3>;

inline t2::Rational dot(const t2::Point& z, const t2::Point& p) {
  return t2::to_rational(z.w()) * t2::to_rational(p.w()) + t2::to_rational(z.x()) * t2::to_rational(p.x()) +
         t2::to_rational(z.y()) * t2::to_rational(p.y());
}

/// p in the chart of the pole z: p / (z·p), on the plane z·v = 1, exactly. For z = [1, 0, 0] it
/// is (1, X, Y), the Cartesian position; in general the central projection that keeps orient.
inline Vec chart(const t2::Point& z, const t2::Point& p) {
  const t2::Rational s = dot(z, p);
  return {t2::to_rational(p.w()) / s, t2::to_rational(p.x()) / s, t2::to_rational(p.y()) / s};
}

inline t2::Rational det(const Vec& a, const Vec& b, const Vec& c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

/// "" when `out` is the triangulation `want` and passes the certificate, else what is wrong.
/// `pole`: a point z with z·p > 0 for every point p of P (the centre of an open hemisphere that
/// holds P); areas are compared in its chart, where det(a, b, c) is twice the area times a constant
/// and det(o, a, b), o = z/(z·z) on the chart's plane, is the hull edge's share.
inline std::string check(const std::vector<t2::Point>& P, const std::vector<long>& T, long q,
                         const std::vector<long>& out, const std::vector<long>& want,
                         const t2::Point& pole = t2::Point(1, 0, 0)) {
  for (const t2::Point& p : P)
    if (dot(pole, p) <= 0) return "the test's pole does not hold the point " + t2::to_string(p);  // a test bug
  const t2::Rational zz = dot(pole, pole);
  const Vec o = {t2::to_rational(pole.w()) / zz, t2::to_rational(pole.x()) / zz, t2::to_rational(pole.y()) / zz};
  if (out.size() % 3 != 0) return "the answer's length is not a multiple of 3";
  const long n = long(P.size()), inf = ex09b::kInfinite;
  const std::vector<Tri> got = canonical(out);
  std::map<std::pair<long, long>, int> directed;
  std::set<long> V;
  t2::Rational area = 0, hull = 0;
  std::vector<std::pair<long, long>> hull_edges;
  for (const Tri& t : got) {
    for (long v : t)
      if (v < inf || v >= n) return "a vertex index out of range: " + std::to_string(v);
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) return "the triangle " + name(t) + " repeats a vertex";
    for (int i = 0; i < 3; ++i) {
      ++directed[{t[i], t[(i + 1) % 3]}];
      V.insert(t[i]);
    }
    if (t[0] != inf) {
      if (t2::orient(P[t[0]], P[t[1]], P[t[2]]) != t2::POSITIVE)
        return "the finite triangle " + name(t) + " is not counter-clockwise";
      area += det(chart(pole, P[t[0]]), chart(pole, P[t[1]]), chart(pole, P[t[2]]));
      continue;
    }
    const long a = t[2], b = t[1];  // (inf, b, a): the hull edge a -> b
    hull_edges.push_back({a, b});
    hull += det(o, chart(pole, P[a]), chart(pole, P[b]));
  }
  for (const auto& [a, b] : hull_edges)
    for (long v : V)
      if (v != inf && t2::orient(P[a], P[b], P[v]) == t2::NEGATIVE)
        return "point " + std::to_string(v) + " is outside the hull edge " + std::to_string(a) + " -> " + std::to_string(b);
  for (const auto& [e, k] : directed) {
    const std::string s = name({e.first, e.second, e.second});
    if (k > 1) return "the directed edge " + s.substr(0, s.rfind(',')) + ") is in two triangles";
    if (!directed.count({e.second, e.first})) return "the edge " + s.substr(0, s.rfind(',')) + ") has one triangle";
  }
  if (long(V.size()) - long(directed.size() / 2) + long(got.size()) != 2) return "Euler's formula fails: not a sphere";
  if (area != hull) return "the finite triangles do not cover the hull exactly once";
  std::set<long> W(T.begin(), T.end());
  if (std::none_of(W.begin(), W.end(), [&](long v) { return v != inf && P[v] == P[q]; })) W.insert(q);
  if (V != W) return "the vertices are not those of T and q (a point equal to a vertex is not inserted again)";
  const std::vector<Tri> w = canonical(want);
  for (const Tri& t : w)
    if (!std::binary_search(got.begin(), got.end(), t)) return "the triangle " + name(t) + " is missing";
  for (const Tri& t : got)
    if (!std::binary_search(w.begin(), w.end(), t)) return "the triangle " + name(t) + " should not be there";
  return "";
}

}  // namespace ex09btest
