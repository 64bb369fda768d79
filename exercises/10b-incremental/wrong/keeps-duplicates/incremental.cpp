// Wrong on purpose: a point equal to a vertex is not recognized. It is inserted "on an edge"
// of a triangle at that vertex, which makes flat triangles and a vertex twice.
#include "incremental.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <deque>
#include <numeric>
#include <random>
#include <unordered_map>
#include <utility>

#include <t2/kernel/error.hpp>
#include <t2/kernel/incircle.hpp>
#include <t2/kernel/orient.hpp>

namespace ex10b {

namespace {

constexpr long kInf = -1;  // the infinite vertex

t2::Sign side(const t2::Point& a, const t2::Point& b, const t2::Point& c) { return t2::orient(a, b, c); }

// > 0: flip the edge a b of (a, b, c) whose other triangle is (b, a, d).
bool illegal(const t2::Point& a, const t2::Point& b, const t2::Point& c, const t2::Point& d) {
  return t2::in_circle(a, b, c, d) > 0;
}

std::uint64_t key(long a, long b) { return (std::uint64_t(a + 1) << 32) | std::uint64_t(b + 1); }
struct Mix {  // spreads the keys over the buckets
  std::size_t operator()(std::uint64_t k) const { return std::size_t((k * 0x9E3779B97F4A7C15ull) >> 17); }
};

struct Mesh {
  const std::vector<t2::Point>& P;
  std::vector<std::array<long, 3>> tri;
  std::unordered_map<std::uint64_t, std::size_t, Mix> owner;  // directed edge -> its triangle
  std::size_t hint = 0;                                 // a finite triangle, near the last point

  void set(std::size_t t, const std::array<long, 3>& v) {
    if (t == tri.size()) tri.push_back(v);
    else
      for (int i = 0; i < 3; ++i) {  // unlink the old edges that still name t
        const auto e = owner.find(key(tri[t][i], tri[t][(i + 1) % 3]));
        if (e != owner.end() && e->second == t) owner.erase(e);
      }
    tri[t] = v;
    for (int i = 0; i < 3; ++i) owner[key(v[i], v[(i + 1) % 3])] = t;
  }
  void add(const std::array<long, 3>& v) { set(tri.size(), v); }
  std::size_t across(long a, long b) const { return owner.at(key(b, a)); }  // the triangle beyond a -> b
  long third(std::size_t t, long a, long b) const {
    for (long x : tri[t])
      if (x != a && x != b) return x;
    return kInf;
  }
  static bool infinite(const std::array<long, 3>& v) { return v[0] == kInf || v[1] == kInf || v[2] == kInf; }
  // (a, b) of the infinite triangle (a, b, inf): its hull edge a -> b, the finite side on its right.
  std::pair<long, long> hull_edge(std::size_t t) const {
    std::array<long, 3> v = tri[t];
    std::rotate(v.begin(), std::find(v.begin(), v.end(), kInf), v.end());  // (inf, a, b)
    return {v[1], v[2]};
  }

  // A finite triangle holding q (closed), or an infinite one whose hull edge has q strictly
  // outside: the walk from the hint, or (past the step bound) every triangle in turn.
  std::size_t locate(long q) const {
    std::size_t t = hint;
    for (std::size_t steps = 0; steps <= tri.size(); ++steps) {
      if (infinite(tri[t])) return t;
      const auto [a, b, c] = tri[t];
      if (side(P[a], P[b], P[q]) < 0) t = across(a, b);
      else if (side(P[b], P[c], P[q]) < 0) t = across(b, c);
      else if (side(P[c], P[a], P[q]) < 0) t = across(c, a);
      else return t;
    }
    for (std::size_t s = 0; s < tri.size(); ++s) {
      const auto [a, b, c] = tri[s];
      if (infinite(tri[s])) {
        if (const auto [x, y] = hull_edge(s); side(P[x], P[y], P[q]) > 0) return s;
      } else if (side(P[a], P[b], P[q]) >= 0 && side(P[b], P[c], P[q]) >= 0 && side(P[c], P[a], P[q]) >= 0) {
        return s;
      }
    }
    return hint;  // not reached: q is in a triangle or outside some hull edge
  }

  // Flips the edges opposite q while they are illegal.
  void legalize(long q, std::vector<std::pair<long, long>> stack) {
    while (!stack.empty()) {
      const auto [x, y] = stack.back();
      stack.pop_back();
      if (x == kInf || y == kInf) continue;
      const auto it = owner.find(key(x, y));
      if (it == owner.end() || third(it->second, x, y) != q) continue;  // flipped away
      const std::size_t t = it->second, u = across(x, y);
      const long d = third(u, y, x);
      if (d == kInf || !illegal(P[x], P[y], P[q], P[d])) continue;
      set(t, {x, d, q});  // the quadrilateral x, d, y, q, cut by q d
      set(u, {d, y, q});
      stack.push_back({x, d});
      stack.push_back({d, y});
    }
  }

  void insert(long q) {
    const std::size_t t = locate(q);
    if (infinite(tri[t])) return outside(q, t);
    const auto [a, b, c] = tri[t];
    const t2::Sign o[3] = {side(P[a], P[b], P[q]), side(P[b], P[c], P[q]), side(P[c], P[a], P[q])};
    const int zeros = (o[0] == 0) + (o[1] == 0) + (o[2] == 0);
    hint = t;
    if (zeros == 0) {
      set(t, {a, b, q});
      add({b, c, q});
      add({c, a, q});
      legalize(q, {{a, b}, {b, c}, {c, a}});
      return;
    }
    const int i = o[0] == 0 ? 0 : o[1] == 0 ? 1 : 2;  // inside the edge u -> v
    const long u = tri[t][i], v = tri[t][(i + 1) % 3], w = tri[t][(i + 2) % 3];
    const std::size_t s = across(u, v);
    const long d = third(s, v, u);
    set(t, {u, q, w});
    add({q, v, w});
    set(s, {v, q, d});
    add({q, u, d});
    legalize(q, {{w, u}, {v, w}, {d, v}, {u, d}});
  }

  // Outside the hull, beyond the hull edge of the infinite triangle t: the infinite triangles
  // that see q strictly (a contiguous run around the hull) become finite.
  void outside(long q, std::size_t t) {
    const auto sees = [&](std::size_t s) {
      const auto [a, b] = hull_edge(s);
      return side(P[a], P[b], P[q]) > 0;
    };
    std::deque<std::size_t> run = {t};
    for (std::size_t s = across(hull_edge(t).second, kInf); s != t && sees(s); s = across(hull_edge(s).second, kInf))
      run.push_back(s);  // forward: the triangle beyond the edge b -> inf
    for (std::size_t s = across(kInf, hull_edge(t).first); s != run.back() && sees(s); s = across(kInf, hull_edge(s).first))
      run.push_front(s);  // backward: beyond inf -> a
    std::vector<std::pair<long, long>> seen;
    for (std::size_t s : run) seen.push_back(hull_edge(s));
    for (std::size_t k = 0; k < run.size(); ++k) set(run[k], {seen[k].first, seen[k].second, q});
    add({seen.front().first, q, kInf});
    add({q, seen.back().second, kInf});
    hint = run.front();
    legalize(q, seen);
  }
};

// The index of (x, y) ∈ [0, 2¹⁶)² along the Hilbert curve of order 16.
std::uint64_t hilbert(std::uint32_t x, std::uint32_t y) {
  std::uint64_t d = 0;
  for (std::uint32_t s = 1u << 15; s > 0; s >>= 1) {
    const std::uint32_t rx = (x & s) ? 1 : 0, ry = (y & s) ? 1 : 0;
    d += std::uint64_t(s) * s * ((3 * rx) ^ ry);
    if (ry == 0) {  // rotate the quadrant
      if (rx == 1) x = s - 1 - (x & (s - 1)) + (x & ~(s - 1)), y = s - 1 - (y & (s - 1)) + (y & ~(s - 1));
      std::swap(x, y);
    }
  }
  return d;
}

// The points in a biased randomized insertion order (BRIO, chapter 10): a random order cut into
// rounds of doubling size (the last round is the second half), each round sorted along a Hilbert
// curve of the drawn positions (doubles: the order only guides the walk, it decides nothing).
std::vector<long> brio(const std::vector<t2::Point>& P) {
  std::vector<long> order(P.size());
  std::iota(order.begin(), order.end(), 0L);
  std::shuffle(order.begin(), order.end(), std::mt19937_64(10));
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  std::vector<std::array<double, 2>> at(P.size());
  for (std::size_t i = 0; i < P.size(); ++i) {
    at[i] = {P[i].x() / P[i].w(), P[i].y() / P[i].w()};
    for (int c = 0; c < 2; ++c) lo[c] = std::min(lo[c], at[i][c]), hi[c] = std::max(hi[c], at[i][c]);
  }
  std::vector<std::uint64_t> h(P.size());
  for (std::size_t i = 0; i < P.size(); ++i) {
    std::uint32_t c[2];
    for (int k = 0; k < 2; ++k) {
      const double span = hi[k] > lo[k] ? hi[k] - lo[k] : 1;
      c[k] = std::uint32_t(std::min(65535.0, std::max(0.0, (at[i][k] - lo[k]) / span * 65535.0)));
    }
    h[i] = hilbert(c[0], c[1]);
  }
  for (std::size_t end = order.size(); end > 0; end /= 2) {
    const std::size_t begin = end / 2 < 64 ? 0 : end / 2;
    std::sort(order.begin() + long(begin), order.begin() + long(end), [&](long a, long b) { return h[a] < h[b]; });
    if (begin == 0) break;
  }
  return order;
}

}  // namespace

std::vector<long> delaunay(const std::vector<t2::Point>& P) {
  const std::vector<long> order = brio(P);
  // The first triangle: the first point, the first one off it, the first one off their line.
  std::size_t j = 1, k = 0;
  while (j < order.size() && P[order[j]] == P[order[0]]) ++j;
  for (std::size_t i = j + 1; i < order.size() && k == 0; ++i)
    if (side(P[order[0]], P[order[j]], P[order[i]]) != t2::ZERO) k = i;
  if (k == 0) throw t2::Undefined("no three points of P are off one line: there is no triangle");
  long a = order[0], b = order[j], c = order[k];
  if (side(P[a], P[b], P[c]) < 0) std::swap(b, c);
  Mesh m{P, {}, {}};
  m.owner.reserve(6 * P.size() + 12);
  m.add({a, b, c});
  m.add({b, a, kInf});
  m.add({c, b, kInf});
  m.add({a, c, kInf});
  for (std::size_t i = 1; i < order.size(); ++i)
    if (i != j && i != k) m.insert(order[i]);
  std::vector<long> out;
  for (const auto& t : m.tri)
    if (!Mesh::infinite(t)) out.insert(out.end(), t.begin(), t.end());
  return out;
}

}  // namespace ex10b
