// Exercise 10c, hidden tests. Oracle, written from the definitions of band.hpp and none of the
// reference's steps: a hull edge is an ordered pair of sites of one side with every site of that
// side on its left or on its line and none strictly between them (O(n³), small inputs); an owner
// is found by comparing with every site of the other side (farthest to the left, ties by the
// rule); a flat face is undefined unless its third vertex is drawn at an end of its edge. The
// large input (10⁵ sites on two circles, h = n) is judged by a certificate instead: its hull
// cycles are known by construction (checked strictly convex), each face must belong to one hull
// edge, and its owner must beat its two neighbours on the other hull, which on a convex cycle
// makes it the owner. Inputs: owners with weights w != ±1 and at breaks; random sites on both
// sides; back sites near Ω (a hull: clockwise faces); tiny sets; grids (sites inside hull edges,
// parallel hull edges facing each other); antipodal pairs (flat faces that are kept); sites on
// the lines of hull edges (Undefined, next to inputs that are defined); the large input.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>

#include <t2/kernel/angle.hpp>
#include <t2/kernel/error.hpp>
#include <t2/kernel/lexicographic.hpp>
#include <t2/kernel/orient.hpp>

#include "band.hpp"
#include "certificate.hpp"

namespace {

using t2::Point;
using ex10ctest::Tri;

Point drawn(const Point& p) { return p.w() > 0 ? p : t2::antipode(p); }

std::vector<long> side(const std::vector<Point>& P, bool front) {
  std::vector<long> s;
  for (long k = 0; k < long(P.size()); ++k)
    if ((P[k].w() > 0) == front) s.push_back(k);
  return s;
}

// The hull edges of the sites s by definition (band.hpp), as drawn.
std::vector<std::pair<long, long>> hull_edges(const std::vector<Point>& D, const std::vector<long>& s) {
  std::vector<std::pair<long, long>> e;
  for (long p : s)
    for (long q : s) {
      if (p == q) continue;
      bool ok = true;
      for (long r : s) {
        const t2::Sign o = t2::orient(D[p], D[q], D[r]);
        if (o == t2::NEGATIVE || (o == t2::ZERO && r != p && r != q &&
                                  t2::detail::dot_of_differences(D[p], D[r], D[r], D[q]) == t2::POSITIVE))
          ok = false;
      }
      if (ok) e.push_back({p, q});
    }
  return e;
}

// The owner of the edge p -> q among the sites s: farthest to the left of it, ties farthest
// along it (forward for a front edge, backward for a back edge).
long owner(const std::vector<Point>& D, long p, long q, const std::vector<long>& s, bool forward) {
  long best = s[0];
  for (long x : s) {
    int c = int(t2::detail::cross_of_differences(D[p], D[q], D[best], D[x]));  // x farther left
    if (c == 0) c = int(t2::detail::dot_of_differences(D[p], D[q], D[best], D[x])) * (forward ? 1 : -1);
    if (c > 0) best = x;
  }
  return best;
}

// The band by definition; nullopt where band.hpp says Undefined.
std::optional<std::vector<long>> expected(const std::vector<Point>& P) {
  std::vector<Point> D;
  for (const Point& p : P) D.push_back(drawn(p));
  const std::vector<long> F = side(P, true), B = side(P, false);
  std::vector<long> out;
  for (auto [a1, a2] : hull_edges(D, F)) out.insert(out.end(), {a2, a1, owner(D, a1, a2, B, true)});
  for (auto [b1, b2] : hull_edges(D, B)) out.insert(out.end(), {b1, b2, owner(D, b1, b2, F, false)});
  for (std::size_t k = 0; k < out.size(); k += 3)
    if (t2::orient(D[out[k]], D[out[k + 1]], D[out[k + 2]]) == t2::ZERO && !(D[out[k + 2]] == D[out[k]]) &&
        !(D[out[k + 2]] == D[out[k + 1]]))
      return std::nullopt;
  return out;
}

// Judges band(P) against the definition. Returns whether it was defined.
bool judge(const std::vector<Point>& P, const std::string& what) {
  const auto want = expected(P);
  if (!want) {
    EXPECT_THROW(ex10c::band(P), t2::Undefined) << what;
    return false;
  }
  EXPECT_EQ(ex10ctest::check(long(P.size()), ex10c::band(P), *want), "") << what;
  return true;
}

bool on_one_line(const std::vector<Point>& P) {
  for (const Point& q : P)
    for (const Point& r : P)
      if (t2::orient(P[0], q, r) != t2::ZERO) return false;
  return true;
}

// n different sites, both sides, none on Ω; weights 1..3 of either sign; `near` back sites
// out of 4 near Ω (drawn far away in one direction: then the sites have a hull).
std::vector<Point> sites(std::mt19937_64& g, int n, int range, int near) {
  auto c = [&](int m) { return double(long(g() % (2 * m + 1)) - m); };
  std::vector<Point> P;
  while (int(P.size()) < n) {
    const bool back = P.size() == 1 || (P.size() > 1 && g() % 2);
    const double w = double(1 + g() % 3);
    if (back && int(g() % 4) < near) P.push_back(Point(-w, w * (300 + c(20)), w * c(200)));
    else P.push_back(Point(back ? -w : w, w * c(range), w * c(range)));
    if (std::count(P.begin(), P.end(), P.back()) > 1) P.pop_back();
  }
  return on_one_line(P) ? sites(g, n, range, near) : P;  // the precondition of band.hpp
}

// The owners by integer arithmetic (the sites have small integer coordinates): the value of a
// drawn position X = (x/w, y/w) in the direction v is (vx x + vy y) / w, compared across the
// positive weights; v = u in front, v = -u behind. A tie for the best value is a break.
std::optional<std::vector<long>> owners_by_integers(const std::vector<Point>& P, long ux, long uy) {
  std::vector<long> want;
  for (int s = 0; s < 2; ++s) {
    const long vx = s == 0 ? ux : -ux, vy = s == 0 ? uy : -uy;
    auto num = [&](long i) { const Point d = drawn(P[i]); return vx * long(d.x()) + vy * long(d.y()); };
    auto den = [&](long i) { return long(drawn(P[i]).w()); };
    long best = -1, ties = 0;
    for (long i = 0; i < long(P.size()); ++i) {
      if ((P[i].w() > 0) != (s == 0)) continue;
      const long c = best < 0 ? 1 : num(i) * den(best) - num(best) * den(i);
      if (c > 0) best = i, ties = 0;
      else if (c == 0) ++ties;
    }
    if (ties > 0) return std::nullopt;
    want.push_back(best);
  }
  return want;
}

TEST(Hidden, OwnersLemma1) {
  std::mt19937_64 g(101);
  int breaks = 0, defined = 0;
  for (int round = 0; round < 40; ++round) {
    const std::vector<Point> P = sites(g, 12, round % 2 ? 3 : 1000, 0);
    for (int k = 0; k < 6; ++k) {
      const long ux = long(g() % 7) - 3, uy = long(g() % 7) - 3;
      if (ux == 0 && uy == 0) continue;
      const Point z(0, double(ux), double(uy));
      const auto want = owners_by_integers(P, ux, uy);
      if (!want) {
        ++breaks;
        EXPECT_THROW(ex10c::owners(P, z), t2::Undefined) << round << " " << k;
      } else {
        ++defined;
        EXPECT_EQ(ex10c::owners(P, z), *want) << round << " " << k;
      }
    }
  }
  EXPECT_GT(breaks, 5);
  EXPECT_GT(defined, 100);
}

// The faces of the expected band that turn clockwise, and the flat ones.
std::pair<int, int> turns(const std::vector<Point>& P, const std::vector<long>& T) {
  int cw = 0, flat = 0;
  for (std::size_t k = 0; k < T.size(); k += 3) {
    const t2::Sign o = t2::orient(P[T[k]], P[T[k + 1]], P[T[k + 2]]);
    cw += o == t2::NEGATIVE, flat += o == t2::ZERO;
  }
  return {cw, flat};
}

TEST(Hidden, RandomBothSides) {
  std::mt19937_64 g(102);
  for (int round = 0; round < 6; ++round)
    EXPECT_TRUE(judge(sites(g, 20 + 8 * round, 1000, 0), "round " + std::to_string(round)));
}

// Back sites near Ω, drawn far away on one side (or, swapped, front sites beyond the back ones):
// the sites have a hull, and the band faces at the far sites turn clockwise; all are returned.
TEST(Hidden, SitesWithAHull) {
  std::mt19937_64 g(103);
  int clockwise = 0;
  for (int round = 0; round < 6; ++round) {
    std::vector<Point> P = sites(g, 16, 50, 4);
    if (round % 2)
      for (Point& p : P) p = t2::antipode(p);
    const auto want = expected(P);
    ASSERT_TRUE(want.has_value());
    EXPECT_GT(turns(P, *want).first, 0) << round;
    clockwise += turns(P, *want).first;
    judge(P, "round " + std::to_string(round));
  }
  EXPECT_GT(clockwise, 6);
}

TEST(Hidden, TinySets) {
  const std::vector<std::vector<Point>> cases = {
      {Point(1, 0, 0), Point(-1, -1, -2), Point(-1, -3, -1)},                // 1 front + 2 back
      {Point(1, 0, 0), Point(2, 2, 0), Point(-1, -1, -2)},                   // 2 + 1
      {Point(-2, 0, 0), Point(1, 5, 1), Point(3, 3, 3)},                     // 1 back + 2 front
      {Point(1, 0, 0), Point(1, 1, 0), Point(1, 2, 0), Point(-1, 0, -1)},    // 3 collinear + 1
      {Point(1, 0, 0), Point(1, 2, 0), Point(-2, 0, -2), Point(-1, -2, -1)}, // 2 + 2, parallel
      {Point(1, 0, 0), Point(-1, 0, -1), Point(-1, -1, 0), Point(-3, 3, 3)}, // 1 + 3
      {Point(1, 0, 0), Point(1, 2, 1), Point(-3, -6, -3), Point(-1, -1, 2), Point(-1, 0, 5)},  // 2 + 3 on a line, ¬1
  };
  for (std::size_t k = 0; k < cases.size(); ++k) judge(cases[k], "case " + std::to_string(k));
}

// Integer grids: sites inside hull edges (each a vertex of two hull edges) and hull edges of
// the two sides parallel, facing each other (a front and a back break at one point of Ω).
TEST(Hidden, GridsAndParallelEdges) {
  std::vector<std::vector<Point>> cases(3);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) cases[0].push_back(Point(1, i, j));  // the square [0, 3]²
  cases[1] = cases[0];
  cases[2] = cases[0];
  for (int i = 1; i < 3; ++i)
    for (int j = 5; j < 8; ++j) cases[0].push_back(Point(-2, -2.0 * i, -2.0 * j));  // drawn [1, 2] x [5, 7]
  for (int i = -2; i < 6; i += 2)
    for (int j = -2; j < 6; j += 2) cases[1].push_back(Point(-1, -i - 0.5, -j - 0.5));  // around, shifted
  for (int k = 0; k < 5; ++k) cases[2].push_back(Point(-3, -3.0 * (2 * k - 1), -3.0 * (k + 5)));  // on a slope
  for (int k = 0; k < 3; ++k) cases[2].push_back(Point(-1, -(4 + k), 3.0 - k));  // beyond a corner
  for (std::size_t k = 0; k < cases.size(); ++k) EXPECT_TRUE(judge(cases[k], "grid " + std::to_string(k)));
}

// A site and its antipode: where the antipode owns an edge at that site, the band face is
// flat, and kept (the seed's figure 5.18; chapter 09's lunes). The other back sites are drawn in
// the wedge opposite the front hull at the site a = (-30, -30): a + j (m a - S) + (a - c), S the
// sum of the m front sites and c one of them; then ¬a owns both hull edges at a (two flat
// faces). Also with the sides swapped.
TEST(Hidden, AntipodalPairs) {
  // ¬0 and two back sites drawn in the third quadrant, beyond the corner 0.
  std::vector<Point> fig = {Point(1, 0, 0),  Point(1, 4, 0),  Point(1, 0, 4),
                            Point(-1, 0, 0), Point(-1, 1, 3), Point(-2, 6, 2)};
  std::vector<std::vector<Point>> cases = {fig};
  std::mt19937_64 g(106);
  for (int round = 0; round < 4; ++round) {
    std::vector<Point> P;
    for (const Point& p : sites(g, 14, 20, 0))
      if (p.w() > 0) P.push_back(p);
    P.push_back(Point(2, -60, -60));
    double sx = 0, sy = 0;
    for (const Point& p : P) sx += p.x() / p.w(), sy += p.y() / p.w();  // small integers: exact
    const double m = double(P.size()), ax = -30, ay = -30;
    const std::size_t front = P.size();
    P.push_back(Point(-3, 90, 90));  // ¬a
    for (int j = 1; j < 4; ++j) {
      const Point& c = P[g() % front];
      const double bx = ax + j * (m * ax - sx) + (ax - c.x() / c.w());
      const double by = ay + j * (m * ay - sy) + (ay - c.y() / c.w());
      P.push_back(Point(-double(j), -j * bx, -j * by));
    }
    if (round % 2)
      for (Point& p : P) p = t2::antipode(p);
    cases.push_back(P);
  }
  int flat = 0;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const auto want = expected(cases[k]);
    ASSERT_TRUE(want.has_value()) << k;
    flat += turns(cases[k], *want).second;
    judge(cases[k], "case " + std::to_string(k));
  }
  EXPECT_GE(flat, 10);
}

// A back site drawn on the line of a front hull edge, as its owner: inside the edge, beyond it,
// and (the sides swapped) a front site on the line of a back hull edge, with weights; each next
// to the same input moved off the line (defined). Then small grids, where both happen by chance.
TEST(Hidden, SitesOnTheLineOfAHullEdge) {
  const std::vector<Point> tri = {Point(1, 0, 0), Point(1, 4, 0), Point(1, 0, 4)};
  auto with = [&](std::vector<Point> back, bool swap, double w) {
    std::vector<Point> P = tri;
    P.insert(P.end(), back.begin(), back.end());
    for (Point& p : P) p = Point(w * p.w(), w * p.x(), w * p.y());
    if (swap)
      for (Point& p : P) p = t2::antipode(p);
    return P;
  };
  int undefined = 0, defined = 0;
  for (int k = 0; k < 4; ++k) {
    const bool swap = k % 2;
    const double w = k < 2 ? 1 : 3;
    const std::vector<std::vector<Point>> off = {{Point(-1, -2, 0), Point(-1, -1, 3)},  // drawn (2, 0): inside 0 -> 1
                                                 {Point(-2, -14, 0), Point(-1, -1, 3)},  // drawn (7, 0): beyond
                                                 {Point(-1, -2, 1), Point(-1, -1, 3)},   // (2, -1): off the line
                                                 {Point(-2, -14, 1), Point(-1, -1, 3)}}; // (7, -0.5)
    for (std::size_t j = 0; j < off.size(); ++j) {
      const bool d = judge(with(off[j], swap, w), "case " + std::to_string(k) + "/" + std::to_string(j));
      EXPECT_EQ(d, j >= 2) << k << " " << j;
    }
  }
  std::mt19937_64 g(107);
  for (int round = 0; round < 30; ++round) {  // front sites on y >= 0, back ones drawn on y <= 0
    std::vector<Point> P;
    for (const Point& p : sites(g, 9, 2, 0)) P.push_back(Point(p.w(), p.x(), std::abs(p.y())));
    std::sort(P.begin(), P.end(), [](const Point& a, const Point& b) { return t2::compare_lexicographic(a, b) < 0; });
    P.erase(std::unique(P.begin(), P.end()), P.end());
    if (on_one_line(P) || P.front().w() > 0 || P.back().w() < 0) continue;
    judge(P, "grid " + std::to_string(round)) ? ++defined : ++undefined;
  }
  EXPECT_GT(undefined, 5);
  EXPECT_GT(defined, 5);
}

// Is x a better owner than y for the edge p -> q: farther to its left, or as far and farther
// along it (forward) or against it?
bool better(const std::vector<Point>& D, long p, long q, long x, long y, bool forward) {
  const t2::Sign c = t2::detail::cross_of_differences(D[p], D[q], D[y], D[x]);
  if (c != t2::ZERO) return c == t2::POSITIVE;
  return t2::detail::dot_of_differences(D[p], D[q], D[y], D[x]) == (forward ? t2::POSITIVE : t2::NEGATIVE);
}

// The certificate of the large input: cf and cb the hull cycles (known), `out` the answer.
std::string certify(const std::vector<Point>& P, const std::vector<long>& cf, const std::vector<long>& cb,
                    const std::vector<long>& out) {
  std::vector<Point> D;
  for (const Point& p : P) D.push_back(drawn(p));
  if (out.size() != 3 * (cf.size() + cb.size())) return "not one face per hull edge";
  std::vector<long> pos(P.size());
  for (std::size_t i = 0; i < cf.size(); ++i) pos[cf[i]] = long(i);
  for (std::size_t i = 0; i < cb.size(); ++i) pos[cb[i]] = long(i);
  std::vector<char> used(P.size(), 0);  // by the start of its hull edge
  for (std::size_t k = 0; k < out.size(); k += 3) {
    Tri t = {out[k], out[k + 1], out[k + 2]};
    for (long v : t)
      if (v < 0 || v >= long(P.size())) return "a site index out of range";
    const int fronts = (P[t[0]].w() > 0) + (P[t[1]].w() > 0) + (P[t[2]].w() > 0);
    if (fronts != 1 && fronts != 2) return "the face " + ex10ctest::name(t) + " is not across Ω";
    const bool front_edge = fronts == 2;
    while ((P[t[2]].w() > 0) == front_edge) std::rotate(t.begin(), t.begin() + 1, t.end());
    const long u = front_edge ? t[1] : t[0], v = front_edge ? t[0] : t[1];  // the hull edge u -> v
    const std::vector<long>& c = front_edge ? cf : cb;
    const std::vector<long>& o = front_edge ? cb : cf;
    const long n = long(c.size()), m = long(o.size());
    if (c[(pos[u] + 1) % n] != v) return "the face " + ex10ctest::name(t) + " has no hull edge";
    if (used[u]++) return "two faces at the hull edge of the face " + ex10ctest::name(t);
    const long j = pos[t[2]], prev = o[(j + m - 1) % m], next = o[(j + 1) % m];
    if (o[j] != t[2] || !better(D, u, v, t[2], prev, front_edge) || !better(D, u, v, t[2], next, front_edge))
      return "the third vertex of " + ex10ctest::name(t) + " is not the owner of its edge";
  }
  return "";
}

// 10⁵ sites: 5·10⁴ in front on a circle of radius 1000 about the origin, 5·10⁴ behind drawn on a
// circle of radius 1500 about (300, -200). Every site is a hull vertex (h = n): a search of every
// site of the other side for each hull edge, O(h n), takes far longer than the time limit.
TEST(Hidden, LargeCircles) {
  const long m = 50000;
  const double pi = std::acos(-1.0);
  std::vector<Point> P;
  std::vector<long> cf, cb;
  for (long k = 0; k < m; ++k) {
    const double a = 2 * pi * double(k) / double(m), b = a + pi / double(m);
    cf.push_back(long(P.size()));
    P.push_back(Point(1, 1000 * std::cos(a), 1000 * std::sin(a)));
    cb.push_back(long(P.size()));
    P.push_back(Point(-1, -300 - 1500 * std::cos(b), 200 - 1500 * std::sin(b)));
  }
  for (const auto* c : {&cf, &cb})
    for (long k = 0; k < m; ++k)
      ASSERT_EQ(t2::orient(drawn(P[(*c)[(k + m - 1) % m]]), drawn(P[(*c)[k]]), drawn(P[(*c)[(k + 1) % m]])),
                t2::POSITIVE) << "the test's circles are not strictly convex at " << k;
  EXPECT_EQ(certify(P, cf, cb, ex10c::band(P)), "");
}

}  // namespace
