// Exercise 10c, reference solution: the two hulls of the drawn positions (Andrew's monotone
// chain, keeping the sites on the boundary) and one merge of their edges by the exact angle of
// the breaks on Ω (chapter 10, section 8, Theorem 2 (b)): O(n log n) for the sort, O(h) for the
// merge. The owners of one point of Ω: one scan each side (Lemma 1).
#include "band.hpp"

#include <algorithm>
#include <array>
#include <string>

#include <t2/kernel/angle.hpp>
#include <t2/kernel/error.hpp>
#include <t2/kernel/lexicographic.hpp>
#include <t2/kernel/orient.hpp>

namespace ex10c {

namespace {

using t2::Point;

// The drawn position of a site, as a front point (the antipode of a back site).
Point drawn(const Point& p) { return p.w() > 0 ? p : t2::antipode(p); }

// The hull cycle of the sites s at their drawn positions D, counter-clockwise, through every
// site on the boundary: the lower chain, then the upper one, each popping only at a strict right
// turn. Collinear sites give s0 … sk … s1, the segment both ways; one site gives itself.
std::vector<long> hull_cycle(const std::vector<Point>& D, std::vector<long> s) {
  std::sort(s.begin(), s.end(), [&](long a, long b) { return t2::compare_xy(D[a], D[b]) == t2::NEGATIVE; });
  if (s.size() < 2) return s;
  std::vector<long> h;
  for (int chain = 0; chain < 2; ++chain) {
    const std::size_t base = h.size();
    for (long p : s) {
      while (h.size() >= base + 2 && t2::orient(D[h[h.size() - 2]], D[h.back()], D[p]) == t2::NEGATIVE) h.pop_back();
      h.push_back(p);
    }
    h.pop_back();  // the last site of a chain starts the next one
    std::reverse(s.begin(), s.end());
  }
  return h;
}

// A break on Ω: the hull edge u → v (indices into P) and the drawn vector `from` → `to` whose
// angle orders the breaks: the edge itself in front, the edge reversed behind (a back edge's
// break is at −n, a front edge's at n: rotating both by 90° compares a1 → a2 with b̄2 → b̄1).
struct Break {
  long u, v;
  const Point *from, *to;
};

// 0 for a direction in [0, π), 1 for [π, 2π), measured from the x axis.
int half(const Break& e) {
  const t2::Sign y = t2::compare_y(*e.to, *e.from);
  return y == t2::POSITIVE || (y == t2::ZERO && t2::compare_x(*e.to, *e.from) == t2::POSITIVE) ? 0 : 1;
}

// Is the angle of a strictly below that of b, in [0, 2π)?
bool before(const Break& a, const Break& b) {
  const int ha = half(a), hb = half(b);
  if (ha != hb) return ha < hb;
  return t2::detail::cross_of_differences(*a.from, *a.to, *b.from, *b.to) == t2::POSITIVE;
}

// The breaks of one side's hull cycle, in angle order from the x axis: the cycle's edges turn
// counter-clockwise once around, so they are sorted once started after their strict descent.
std::vector<Break> breaks(const std::vector<Point>& D, const std::vector<long>& c, bool front) {
  std::vector<Break> e;
  const std::size_t m = c.size();
  if (m < 2) return e;
  for (std::size_t i = 0; i < m; ++i) {
    const long u = c[i], v = c[(i + 1) % m];
    e.push_back(front ? Break{u, v, &D[u], &D[v]} : Break{u, v, &D[v], &D[u]});
  }
  std::size_t s = 0;
  for (std::size_t i = 0; i < m; ++i)
    if (before(e[i], e[(i + m - 1) % m])) s = i;
  std::rotate(e.begin(), e.begin() + static_cast<std::ptrdiff_t>(s), e.end());
  return e;
}

}  // namespace

std::vector<long> owners(const std::vector<Point>& P, const Point& z) {
  // For front points p, q and r = [0, -uy, ux]: orient(p, q, r) = sign(u · (Q - P)).
  const Point ahead(0, -z.y(), z.x()), behind(0, z.y(), -z.x());
  long best[2] = {-1, -1};
  bool tie[2] = {false, false};
  for (long k = 0; k < long(P.size()); ++k) {
    const int side = P[k].w() > 0 ? 0 : 1;
    const Point& r = side == 0 ? ahead : behind;
    if (best[side] < 0) {
      best[side] = k;
      continue;
    }
    const t2::Sign s = t2::orient(drawn(P[best[side]]), drawn(P[k]), r);
    if (s == t2::POSITIVE) best[side] = k, tie[side] = false;
    else if (s == t2::ZERO) tie[side] = true;
  }
  if (tie[0] || tie[1])
    throw t2::Undefined("owners: two " + std::string(tie[0] ? "front" : "back") +
                        " sites are extreme: the point is a break on Omega");
  return {best[0], best[1]};
}

std::vector<long> band(const std::vector<Point>& P) {
  std::vector<Point> D;
  std::vector<long> front, back;
  for (long k = 0; k < long(P.size()); ++k) {
    D.push_back(drawn(P[k]));
    (P[k].w() > 0 ? front : back).push_back(k);
  }
  const std::vector<long> cf = hull_cycle(D, front), cb = hull_cycle(D, back);
  const std::vector<Break> fe = breaks(D, cf, true), be = breaks(D, cb, false);
  long a = fe.empty() ? cf[0] : fe[0].u, b = be.empty() ? cb[0] : be[0].u;  // owners before the first break
  std::vector<long> out;
  std::size_t i = 0, j = 0;
  while (i < fe.size() || j < be.size()) {
    if (j == be.size() || (i < fe.size() && !before(be[j], fe[i]))) {  // a front break first at a tie
      out.insert(out.end(), {fe[i].v, fe[i].u, b});
      a = fe[i++].v;
    } else {
      out.insert(out.end(), {be[j].u, be[j].v, a});
      b = be[j++].v;
    }
  }
  for (std::size_t k = 0; k < out.size(); k += 3) {
    const Point &x = P[out[k]], &y = P[out[k + 1]], &o = P[out[k + 2]];
    if (t2::orient(x, y, o) == t2::ZERO && !(o == t2::antipode(x) || o == t2::antipode(y)))
      throw t2::Undefined("band: the site " + std::to_string(out[k + 2]) + " is drawn on the line of the hull edge " +
                          std::to_string(out[k]) + ", " + std::to_string(out[k + 1]) + ": a flat face");
  }
  return out;
}

}  // namespace ex10c
