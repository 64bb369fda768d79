// Exercise 09c, reference solution. kinds: the signs of orient and of the weights. insert:
// locate P[q] by testing every finite triangle (exact orientations), and split a face or an edge
// as in 09b; outside the hull, count the hull edges that have q strictly to their left: if one
// does, ¬q is outside the hull, which survives (09b's rule); if none does, ¬q is in the closed
// hull: q replaces v∞ when ¬q is strictly inside or is a vertex, else ¬q is inside a hull edge
// and no triangulation exists.
#include "insert.hpp"

#include <array>
#include <map>
#include <utility>

#include <t2/kernel/error.hpp>
#include <t2/kernel/orient.hpp>

namespace ex09c {

namespace {

// The orientation of P[a], P[b], P[c], exact on homogeneous points.
t2::Sign side(const std::vector<t2::Point>& P, long a, long b, long c) { return t2::orient(P[a], P[b], P[c]); }

}  // namespace

std::vector<Kind> kinds(const std::vector<t2::Point>& P, const std::vector<long>& T) {
  std::vector<Kind> r;
  for (std::size_t k = 0; k + 2 < T.size(); k += 3) {
    const long a = T[k], b = T[k + 1], c = T[k + 2];
    if (a == kInfinite || b == kInfinite || c == kInfinite) {
      r.push_back(Kind::infinite);
      continue;
    }
    if (side(P, a, b, c) == t2::ZERO) {
      const bool lune = P[a] == t2::antipode(P[b]) || P[b] == t2::antipode(P[c]) || P[c] == t2::antipode(P[a]);
      r.push_back(lune ? Kind::lune : Kind::flat);
      continue;
    }
    int front = 0, back = 0;
    for (long v : {a, b, c}) front += P[v].w() > 0, back += P[v].w() < 0;
    r.push_back(front == 3 ? Kind::front : back == 3 ? Kind::back : front + back == 3 ? Kind::band : Kind::omega);
  }
  return r;
}

std::vector<long> insert(const std::vector<t2::Point>& P, const std::vector<long>& T, long q) {
  std::vector<std::array<long, 3>> tri;
  std::map<std::pair<long, long>, std::size_t> owner;  // directed edge -> its triangle
  for (std::size_t k = 0; k + 2 < T.size(); k += 3) {
    tri.push_back({T[k], T[k + 1], T[k + 2]});
    for (int i = 0; i < 3; ++i) owner[{T[k + i], T[k + (i + 1) % 3]}] = tri.size() - 1;
  }
  const t2::Point nq = t2::antipode(P[q]);
  bool antipode_is_vertex = false;
  for (long v : T) {
    if (v != kInfinite && P[v] == P[q]) return T;  // already a vertex
    if (v != kInfinite && P[v] == nq) antipode_is_vertex = true;
  }
  std::vector<long> out;
  auto emit = [&](std::array<long, 3> t) { out.insert(out.end(), t.begin(), t.end()); };
  auto keep_all_but = [&](std::size_t x, std::size_t y) {
    for (std::size_t t = 0; t < tri.size(); ++t)
      if (t != x && t != y) emit(tri[t]);
  };
  for (std::size_t t = 0; t < tri.size(); ++t) {
    const auto [a, b, c] = tri[t];
    if (a == kInfinite || b == kInfinite || c == kInfinite) continue;
    const t2::Sign o[3] = {side(P, a, b, q), side(P, b, c, q), side(P, c, a, q)};
    if (o[0] < 0 || o[1] < 0 || o[2] < 0) continue;
    if (o[0] > 0 && o[1] > 0 && o[2] > 0) {  // inside the face
      keep_all_but(t, t);
      emit({a, b, q});
      emit({b, c, q});
      emit({c, a, q});
      return out;
    }
    const int i = o[0] == 0 ? 0 : o[1] == 0 ? 1 : 2;  // on the edge u -> v (not at a vertex)
    const long u = tri[t][i], v = tri[t][(i + 1) % 3], w = tri[t][(i + 2) % 3];
    const std::size_t s = owner.at({v, u});
    long d = kInfinite;
    for (long x : tri[s])
      if (x != u && x != v) d = x;
    keep_all_but(t, s);
    emit({u, q, w});
    emit({q, v, w});
    emit({v, q, d});
    emit({q, u, d});
    return out;
  }
  // Outside the hull. The infinite triangle (a, b, v∞) holds the hull edge b -> a: q strictly
  // left of a -> b is q beyond that edge, strictly right of it is ¬q beyond it.
  int left_of_hull_edge = 0, on_line = 0;
  for (auto& t : tri) {
    int k = 0;
    while (k < 3 && t[k] != kInfinite) ++k;
    if (k == 3) continue;
    const t2::Sign s = side(P, t[(k + 1) % 3], t[(k + 2) % 3], q);
    left_of_hull_edge += s < 0;
    on_line += s == 0;
  }
  if (left_of_hull_edge == 0) {  // ¬q in the closed hull: the hull is destroyed, or no triangulation
    if (on_line > 0 && !antipode_is_vertex)
      throw t2::Undefined("insert(): the antipode of the point lies inside a hull edge");
    for (long v : T) out.push_back(v == kInfinite ? q : v);
    return out;
  }
  for (auto& t : tri) {  // the hull survives: 09b's rule
    int k = 0;
    while (k < 3 && t[k] != kInfinite) ++k;
    if (k == 3) continue;
    const long a = t[(k + 1) % 3], b = t[(k + 2) % 3];
    if (side(P, a, b, q) > 0) t = {a, b, q};
  }
  std::map<std::pair<long, long>, int> edges;
  for (const auto& t : tri) {
    emit(t);
    for (int i = 0; i < 3; ++i) ++edges[{t[i], t[(i + 1) % 3]}];
  }
  for (const auto& [e, n] : edges)  // the new hull edges: finite edges without their reverse
    if (e.first != kInfinite && e.second != kInfinite && !edges.count({e.second, e.first}))
      emit({e.second, e.first, kInfinite});
  return out;
}

}  // namespace ex09c
