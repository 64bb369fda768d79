#pragma once
// Exercise 08: how both test files judge an answer (part of the tests, not of your solution).
// First the certificate of a convex surface, decided exactly: every directed edge of a triangle
// once and its reverse once (a closed oriented surface), no triangle with collinear corners,
// every vertex of H and the new point on the inner side of every triangle or on its plane.
// Then the answer the rule of horizon.hpp makes unique, which the test knows, compared as a set
// of triangles.
#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <t2/hull3d/degenerate.hpp>
#include <t2/kernel/orient3d.hpp>

namespace ex08test {

using Tri = std::array<long, 3>;

/// The triangles of a flat list, each rotated to start at its smallest index, sorted.
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
  return "(" + std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) + ")";
}

/// "" when `out` is the surface after inserting P[p] into H — the triangles `want`, which the
/// test knows — and a convex surface, else what is wrong.
inline std::string check(const std::vector<t2::Point3>& P, const std::vector<long>& H, long p,
                         const std::vector<long>& out, const std::vector<long>& want) {
  if (out.size() % 3 != 0) return "the answer's length is not a multiple of 3";
  const long n = long(P.size());
  for (long v : out)
    if (v < 0 || v >= n) return "a vertex index out of range: " + std::to_string(v);
  const std::vector<Tri> got = canonical(out);
  std::map<std::pair<long, long>, int> directed;
  for (const Tri& t : got) {
    if (t2::collinear(P[t[0]], P[t[1]], P[t[2]])) return "the triangle " + name(t) + " has collinear corners";
    for (int i = 0; i < 3; ++i) ++directed[{t[i], t[(i + 1) % 3]}];
  }
  for (const auto& [e, k] : directed) {
    const std::string s = std::to_string(e.first) + " -> " + std::to_string(e.second);
    if (k > 1) return "the directed edge " + s + " is in two triangles";
    if (!directed.count({e.second, e.first})) return "the edge " + s + " has a triangle on one side only: a hole";
  }
  std::vector<long> q(H.begin(), H.end());
  q.push_back(p);
  for (const Tri& t : got)
    for (long v : q)
      if (t2::orient3d(P[t[0]], P[t[1]], P[t[2]], P[v]) == t2::POSITIVE)
        return "point " + std::to_string(v) + " is outside the triangle " + name(t) + ": not convex";
  const std::vector<Tri> w = canonical(want);
  for (const Tri& t : w)
    if (!std::binary_search(got.begin(), got.end(), t)) return "the triangle " + name(t) + " is missing";
  for (const Tri& t : got)
    if (!std::binary_search(w.begin(), w.end(), t))
      return "the triangle " + name(t) + " should not be there (which triangles does p see, strictly?)";
  return "";
}

}  // namespace ex08test
