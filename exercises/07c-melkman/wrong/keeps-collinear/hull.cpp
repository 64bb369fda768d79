// Wrong on purpose: Melkman's deque that pops only on a strict right turn (Δ < 0), so a vertex
// inside a hull edge stays (the tips of a comb's inner teeth, a vertex cutting an edge): the
// answer is not the strict hull.
#include "hull.hpp"

#include <cstddef>

#include <t2/kernel/orient.hpp>

namespace ex07c {

namespace {

using t2::Point;

// For collinear u, w, p (u ≠ ±w): p on the closed segment u w of T². With c strictly left of
// u → w, p = αu + βw has sign α = Δ(p, w, c) and sign β = Δ(u, p, c).
bool on_segment(const Point& u, const Point& w, const Point& p) {
  for (const Point& e : {Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)}) {
    const t2::Sign s = t2::orient(u, w, e);
    if (s == t2::ZERO) continue;
    const Point c = s > 0 ? e : t2::antipode(e);
    return t2::orient(p, w, c) >= 0 && t2::orient(u, p, c) >= 0;
  }
  return false;  // u = ±w: not called so
}

// The ends of points on one line (v: indices of P, repeated neighbours dropped).
std::vector<long> segment(const std::vector<t2::Point>& P, const std::vector<long>& v) {
  std::vector<long> H;
  for (long q : v) {
    if (H.empty()) H.push_back(q);
    else if (H.size() == 1) {
      if (!(P[H[0]] == P[q])) H.push_back(q);
    } else if (!on_segment(P[H[0]], P[H[1]], P[q])) {
      // q lies beyond one end: the one on its side goes.
      H[on_segment(P[q], P[H[1]], P[H[0]]) ? 0 : 1] = q;
    }
  }
  return H;
}

}  // namespace

std::vector<long> hull(const std::vector<t2::Point>& P) {
  std::vector<long> v;  // the vertices, each run of one point named by its first index
  for (std::size_t i = 0; i < P.size(); ++i)
    if (v.empty() || !(P[v.back()] == P[i])) v.push_back(long(i));
  while (v.size() > 1 && P[v.back()] == P[v.front()]) v.pop_back();
  std::size_t k = 2;  // the first vertex off the line v0 v1
  while (k < v.size() && t2::orient(P[v[0]], P[v[1]], P[v[k]]) == t2::ZERO) ++k;
  if (k >= v.size()) return segment(P, v);
  // A simple chain along a line is monotone: v0 and v[k-1] end the first run.
  const long a = v[0], b = v[k - 1], c = v[k];
  std::vector<long> D(2 * v.size() + 1);
  std::size_t bot = v.size(), top = bot + 3;  // D[bot..top], D[bot] = D[top] = the last vertex
  const bool ccw = t2::orient(P[a], P[b], P[c]) > 0;
  D[bot] = c, D[bot + 1] = ccw ? a : b, D[bot + 2] = ccw ? b : a, D[top] = c;
  const auto inside = [&](long u, long w, long p) {  // left of u → w, or on the segment
    const t2::Sign s = t2::orient(P[u], P[w], P[p]);
    return s > 0 || (s == 0 && on_segment(P[u], P[w], P[p]));
  };
  for (std::size_t i = k + 1; i < v.size(); ++i) {
    const long p = v[i];
    if (inside(D[top - 1], D[top], p) && inside(D[bot], D[bot + 1], p)) continue;  // in a pocket
    while (t2::orient(P[D[top - 1]], P[D[top]], P[p]) < 0) --top;
    D[++top] = p;
    while (t2::orient(P[p], P[D[bot]], P[D[bot + 1]]) < 0) ++bot;
    D[--bot] = p;
  }
  return {D.begin() + std::ptrdiff_t(bot), D.begin() + std::ptrdiff_t(top)};
}

}  // namespace ex07c
