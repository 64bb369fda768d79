#pragma once
// Shared helpers of the hull tests: the algorithms to run, cyclic comparison of answers, and
// the exact brute force of hull existence and hull vertices (Carathéodory: a point lies in the
// cone of a set iff it lies in the cone of at most three of its points).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "t2/gen/generate.hpp"
#include "t2/hull.hpp"

namespace t2::testing {

inline const std::vector<HullAlgorithm>& all_algorithms() {
  static const std::vector<HullAlgorithm> a{HullAlgorithm::automatic, HullAlgorithm::merge, HullAlgorithm::jarvis,
                                            HullAlgorithm::graham,    HullAlgorithm::quickhull, HullAlgorithm::monotone,
                                            HullAlgorithm::chan};
  return a;
}

/// Hull traits that count their orientation tests (the algorithms are templates on them).
struct CountingTraits {
  static inline long calls = 0;  ///< the tests so far
  static Sign orient(const Point& p, const Point& q, const Point& r) {
    ++calls;
    return t2::orient(p, q, r);
  }
  static bool equal(const Point& p, const Point& q) { return p == q; }
};

/// True when a and b are the same cyclic sequence of points of T² (equality in T²).
template <class P>
bool same_cycle(const std::vector<P>& a, const std::vector<P>& b) {
  if (a.size() != b.size()) return false;
  if (a.empty()) return true;
  for (std::size_t r = 0; r < b.size(); ++r) {
    if (!(a[0] == b[r])) continue;
    bool all = true;
    for (std::size_t i = 0; i < a.size() && all; ++i) all = a[i] == b[(r + i) % b.size()];
    if (all) return true;
  }
  return false;
}

/// The polygon of a generator kind (simple-, star-, convex-, monotone-polygon).
inline Polygon polygon_of(gen::Kind k, std::size_t n, std::uint64_t seed) {
  gen::Options o;
  o.n = n;
  o.seed = seed;
  return gen::polygon(k, o);
}

inline std::vector<Point> at(const std::vector<Point>& P, const std::vector<std::size_t>& idx) {
  std::vector<Point> out;
  for (std::size_t i : idx) out.push_back(P[i]);
  return out;
}

inline std::string text(const std::vector<Point>& v) {
  std::string s;
  for (const auto& p : v) s += to_string(p) + " ";
  return s;
}

// A coordinate axis point off the plane of the vectors u, v (u, v independent).
inline Point off_plane(const Point& u, const Point& v) {
  for (const Point& e : {Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)})
    if (orient(u, v, e) != ZERO) return e;
  ADD_FAILURE() << "dependent vectors";
  return Point(1, 0, 0);
}

/// v lies in the cone of a (v = a as points of T²).
inline bool in_cone1(const Point& v, const Point& a) { return v == a; }

/// v = αa + βb with α, β ≥ 0 (not both 0), for a, b not equal or antipodal.
inline bool in_cone2(const Point& v, const Point& a, const Point& b) {
  if (a == b || a == antipode(b)) return in_cone1(v, a) || in_cone1(v, b);
  if (orient(v, a, b) != ZERO) return false;
  const Point e = off_plane(a, b);
  const int s = orient(a, b, e);
  return orient(v, b, e) * s >= 0 && orient(a, v, e) * s >= 0;
}

/// v = αa + βb + γc with α, β, γ ≥ 0, for a, b, c independent (Cramer's signs).
inline bool in_cone3(const Point& v, const Point& a, const Point& b, const Point& c) {
  const int s = orient(a, b, c);
  if (s == 0) return false;
  return orient(v, b, c) * s >= 0 && orient(a, v, c) * s >= 0 && orient(a, b, v) * s >= 0;
}

/// v lies in the cone of the points B (as vectors): brute force over 1, 2, 3 of them.
inline bool in_cone(const Point& v, const std::vector<Point>& B) {
  const std::size_t n = B.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (in_cone1(v, B[i])) return true;
    for (std::size_t j = i + 1; j < n; ++j) {
      if (in_cone2(v, B[i], B[j])) return true;
      for (std::size_t k = j + 1; k < n; ++k)
        if (in_cone3(v, B[i], B[j], B[k])) return true;
    }
  }
  return false;
}

/// The points lie in no open hemisphere: some ¬p lies in the cone of the others (brute force).
inline bool brute_no_hull(const std::vector<Point>& P) {
  for (std::size_t i = 0; i < P.size(); ++i) {
    std::vector<Point> rest;
    for (std::size_t j = 0; j < P.size(); ++j)
      if (j != i) rest.push_back(P[j]);
    if (in_cone(antipode(P[i]), rest)) return true;
  }
  return false;
}

/// The strict hull vertices by their definition, counter-clockwise (the points must have a hull):
/// v is a vertex when it is not in the cone of the points other than v; u → v is an edge when
/// every other vertex lies strictly left of it.
inline std::vector<Point> brute_hull(const std::vector<Point>& P) {
  std::vector<Point> V;
  for (const auto& v : P) {
    std::vector<Point> others;
    for (const auto& p : P)
      if (!(p == v)) others.push_back(p);
    if (!in_cone(v, others) && std::none_of(V.begin(), V.end(), [&](const Point& u) { return u == v; })) V.push_back(v);
  }
  if (V.size() < 3) return V;
  std::vector<Point> cycle{V[0]};
  while (cycle.size() < V.size()) {
    bool found = false;
    for (const auto& w : V) {
      if (w == cycle.back()) continue;
      if (std::all_of(V.begin(), V.end(), [&](const Point& x) {
            return x == cycle.back() || x == w || orient(cycle.back(), w, x) > 0;
          })) {
        if (w == cycle[0]) break;
        cycle.push_back(w);
        found = true;
        break;
      }
    }
    if (!found) break;
  }
  return cycle;
}

}  // namespace t2::testing
