// Wrong on purpose: "the polygon gives the order, so Graham's scan needs no sort": one stack, the
// vertices in the polygon's order, pop while the turn is not strictly left, push; then the same
// closing pops round the start. The orientation is found by trying both directions and keeping
// the longer answer. Right on convex and on star-shaped polygons; but a vertex popped while the
// chain runs into a pocket never comes back, and a pocket vertex that turns left stays.
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

std::vector<long> scan(const std::vector<t2::Point>& P, const std::vector<long>& v) {
  std::vector<long> s;
  for (long p : v) {
    while (s.size() >= 2 && t2::orient(P[s[s.size() - 2]], P[s.back()], P[p]) <= 0) s.pop_back();
    s.push_back(p);
  }
  std::size_t b = 0;  // the closing pops, at both ends of the stack
  for (bool again = true; again;) {
    again = false;
    while (s.size() - b >= 3 && t2::orient(P[s[s.size() - 2]], P[s.back()], P[s[b]]) <= 0) s.pop_back(), again = true;
    while (s.size() - b >= 3 && t2::orient(P[s.back()], P[s[b]], P[s[b + 1]]) <= 0) ++b, again = true;
  }
  return {s.begin() + std::ptrdiff_t(b), s.end()};
}

}  // namespace

std::vector<long> hull(const std::vector<t2::Point>& P) {
  std::vector<long> v;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (v.empty() || !(P[v.back()] == P[i])) v.push_back(long(i));
  while (v.size() > 1 && P[v.back()] == P[v.front()]) v.pop_back();
  std::size_t k = 2;
  while (k < v.size() && t2::orient(P[v[0]], P[v[1]], P[v[k]]) == t2::ZERO) ++k;
  if (k >= v.size()) return segment(P, v);
  const std::vector<long> f = scan(P, v), b = scan(P, std::vector<long>(v.rbegin(), v.rend()));
  return f.size() >= b.size() ? f : b;
}

}  // namespace ex07c
