#pragma once
// Exercise 10b: the exact certificate both test files check an answer with (part of the tests,
// not of your solution). An answer is right when its triangles are counter-clockwise, use every
// directed edge once, their boundary is one convex polygon holding every vertex, V - E + F = 1,
// every point of P is equal to exactly one vertex, and every interior edge is locally Delaunay
// under the exact t2::in_circle — which, for a triangulation of the points, makes it a Delaunay
// triangulation.
#include <cstdint>
#include <map>
#include <unordered_map>
#include <string>
#include <utility>
#include <vector>

#include <t2/kernel/incircle.hpp>
#include <t2/kernel/number.hpp>
#include <t2/kernel/orient.hpp>
#include <t2/kernel/point.hpp>

namespace ex10btest {

/// The Cartesian coordinates of a front point, exactly.
inline std::pair<t2::Rational, t2::Rational> xy(const t2::Point& p) {
  return {t2::to_rational(p.x()) / t2::to_rational(p.w()), t2::to_rational(p.y()) / t2::to_rational(p.w())};
}

struct EdgeHash {
  std::size_t operator()(const std::pair<long, long>& e) const {
    return std::size_t(((std::uint64_t(e.first) << 32) ^ std::uint64_t(e.second)) * 0x9E3779B97F4A7C15ull >> 17);
  }
};

inline std::string edge(long a, long b) { return std::to_string(a) + " -> " + std::to_string(b); }

/// "" when T is a Delaunay triangulation of P (see the file comment), else what is wrong.
inline std::string check(const std::vector<t2::Point>& P, const std::vector<long>& T) {
  if (T.empty() || T.size() % 3 != 0) return "the answer is empty or its length not a multiple of 3";
  std::unordered_map<std::pair<long, long>, long, EdgeHash> owner;  // directed edge -> its triangle
  std::vector<char> is_vertex(P.size(), 0);
  std::vector<std::pair<t2::Rational, t2::Rational>> place(P.size());  // xy(P[i]), once each
  for (std::size_t i = 0; i < P.size(); ++i) place[i] = xy(P[i]);
  for (std::size_t k = 0; k < T.size(); k += 3) {
    for (int i = 0; i < 3; ++i) {
      if (T[k + i] < 0 || T[k + i] >= long(P.size())) return "a vertex index out of range";
      is_vertex[T[k + i]] = 1;
      if (!owner.emplace(std::pair{T[k + i], T[k + (i + 1) % 3]}, long(k)).second)
        return "the directed edge " + edge(T[k + i], T[k + (i + 1) % 3]) + " is in two triangles";
    }
    if (t2::orient(P[T[k]], P[T[k + 1]], P[T[k + 2]]) != t2::POSITIVE)
      return "triangle " + std::to_string(T[k]) + " " + std::to_string(T[k + 1]) + " " + std::to_string(T[k + 2]) +
             " is not counter-clockwise";
  }
  std::vector<long> vertices;
  for (long v = 0; v < long(P.size()); ++v)
    if (is_vertex[v]) vertices.push_back(v);
  std::size_t edges = 0;
  for (const auto& [e, k] : owner) {
    const auto other = owner.find({e.second, e.first});
    if (other == owner.end()) {  // a boundary edge: every vertex on its inner side or line
      ++edges;
      for (long v : vertices)
        if (t2::orient(P[e.first], P[e.second], P[v]) == t2::NEGATIVE)
          return "point " + std::to_string(v) + " is outside the boundary edge " + edge(e.first, e.second) +
                 ": the triangles do not fill the convex hull";
      continue;
    }
    if (e.first > e.second) continue;
    ++edges;
    long c = -1, d = -1;
    for (int i = 0; i < 3; ++i) {
      if (T[k + i] != e.first && T[k + i] != e.second) c = T[k + i];
      if (T[other->second + i] != e.first && T[other->second + i] != e.second) d = T[other->second + i];
    }
    if (t2::in_circle(P[e.first], P[e.second], P[c], P[d]) == t2::POSITIVE)
      return "the edge " + edge(e.first, e.second) + " is not locally Delaunay: point " + std::to_string(d) +
             " is inside the circle of " + std::to_string(e.first) + " " + std::to_string(e.second) + " " +
             std::to_string(c);
  }
  // (No area test: with every directed edge used once, the triangles' areas always sum to the
  // area their boundary encloses, since each interior edge's two terms cancel.)
  if (long(vertices.size()) - long(edges) + long(T.size() / 3) != 1) return "V - E + F != 1: not one disc";
  std::map<std::pair<t2::Rational, t2::Rational>, int> at;  // the vertices by their exact place
  for (long v : vertices) ++at[place[v]];
  for (long p = 0; p < long(P.size()); ++p) {
    const auto it = at.find(place[p]);  // front points: equal in T² when drawn at the same place
    const int equal = it == at.end() ? 0 : it->second;
    if (equal != 1)
      return "point " + std::to_string(p) + (equal ? " is equal to two vertices" : " is not a vertex (nor equal to one)");
  }
  return "";
}

}  // namespace ex10btest
