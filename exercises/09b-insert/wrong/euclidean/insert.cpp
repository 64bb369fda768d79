// Wrong on purpose: the Euclidean habit of a point as the place where it is drawn. Every point
// is first brought to the front (a back point [w, x, y] replaced by [-w, -x, -y], which is drawn
// at the same place (x/w, y/w)), then oriented exactly. Right on front points with any weights;
// on a hemisphere that holds back points, a triangle with an odd number of them turns over.
#include "insert.hpp"

#include <array>
#include <map>
#include <utility>

#include <t2/kernel/orient.hpp>

namespace ex09b {

namespace {

// The point where p is drawn, as a front point (points of Omega are left as they are).
t2::Point drawn(const t2::Point& p) { return p.w() < 0 ? t2::antipode(p) : p; }
// The orientation of the drawn P[a], P[b], P[c], exact.
t2::Sign side(const std::vector<t2::Point>& P, long a, long b, long c) {
  return t2::orient(drawn(P[a]), drawn(P[b]), drawn(P[c]));
}

}  // namespace

std::vector<long> insert(const std::vector<t2::Point>& P, const std::vector<long>& T, long q) {
  std::vector<std::array<long, 3>> tri;
  std::map<std::pair<long, long>, std::size_t> owner;  // directed edge -> its triangle
  for (std::size_t k = 0; k + 2 < T.size(); k += 3) {
    tri.push_back({T[k], T[k + 1], T[k + 2]});
    for (int i = 0; i < 3; ++i) owner[{T[k + i], T[k + (i + 1) % 3]}] = tri.size() - 1;
  }
  for (long v : T)
    if (v != kInfinite && drawn(P[v]) == drawn(P[q])) return T;  // already a vertex
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
  // Outside the hull: the infinite triangles (a, b, v∞) with q strictly left of a -> b.
  for (auto& t : tri) {
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

}  // namespace ex09b
