#pragma once
// Exercise 09c: how both test files judge an answer of insert (part of the tests, not of your
// solution). First an exact certificate that the answer is a triangulated sphere on the vertices
// of T and q: every directed edge once and its reverse once, Euler's formula, no face turning
// clockwise (t2::orient < 0). While v∞ is a vertex every finite face is proper (orient > 0), no
// two vertices are antipodes and every vertex lies on the inner side of every hull edge; once q
// has replaced v∞, faces with orient = 0 (lunes and flat faces) may occur. Then the answer the
// rules of insert.hpp make unique, which the test knows, as a set of triangles.
#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <t2/kernel/orient.hpp>
#include <t2/kernel/point.hpp>

#include "insert.hpp"

namespace ex09ctest {

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
  auto v = [](long i) { return i == ex09c::kInfinite ? std::string("inf") : std::to_string(i); };
  return "(" + v(t[0]) + ", " + v(t[1]) + ", " + v(t[2]) + ")";
}

/// "" when `out` is the triangulation `want` and passes the certificate, else what is wrong.
inline std::string check(const std::vector<t2::Point>& P, const std::vector<long>& T, long q,
                         const std::vector<long>& out, const std::vector<long>& want) {
  if (out.size() % 3 != 0) return "the answer's length is not a multiple of 3";
  const long n = long(P.size()), inf = ex09c::kInfinite;
  const std::vector<Tri> got = canonical(out);
  std::map<std::pair<long, long>, int> directed;
  std::set<long> V;
  std::vector<std::pair<long, long>> hull_edges;
  for (const Tri& t : got) {
    for (long v : t)
      if (v < inf || v >= n) return "a vertex index out of range: " + std::to_string(v);
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) return "the triangle " + name(t) + " repeats a vertex";
    for (int i = 0; i < 3; ++i) {
      ++directed[{t[i], t[(i + 1) % 3]}];
      V.insert(t[i]);
    }
    if (t[0] == inf) {
      hull_edges.push_back({t[2], t[1]});  // (inf, b, a): the hull edge a -> b
      continue;
    }
    const t2::Sign o = t2::orient(P[t[0]], P[t[1]], P[t[2]]);
    if (o == t2::NEGATIVE) return "the face " + name(t) + " turns clockwise";
  }
  const bool hull = V.count(inf) > 0;
  if (hull)
    for (const Tri& t : got)
      if (t[0] != inf && t2::orient(P[t[0]], P[t[1]], P[t[2]]) == t2::ZERO)
        return "the face " + name(t) + " has orient 0, but v∞ is still a vertex (a hull has no such face)";
  if (hull)
    for (long a : V)
      for (long b : V)
        if (a != inf && b != inf && P[a] == t2::antipode(P[b]))
          return "v∞ is still a vertex, but " + std::to_string(a) + " and " + std::to_string(b) + " are antipodes: no hull holds both";
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
  std::set<long> W(T.begin(), T.end());
  const bool known = std::any_of(W.begin(), W.end(), [&](long v) { return v != inf && P[v] == P[q]; });
  if (!known) W.insert(q);
  if (!known && !hull) W.erase(inf);
  if (V != W) return "the vertices are not those of T and q (v∞ stays while the hull does; a point equal to a vertex is not inserted again)";
  const std::vector<Tri> w = canonical(want);
  for (const Tri& t : w)
    if (!std::binary_search(got.begin(), got.end(), t)) return "the triangle " + name(t) + " is missing";
  for (const Tri& t : got)
    if (!std::binary_search(w.begin(), w.end(), t)) return "the triangle " + name(t) + " should not be there";
  return "";
}

}  // namespace ex09ctest
