// Exercise 07c, hidden tests. Oracle: the strict hull by its defining property (below), O(n³),
// on every small input; on the large one a certificate of the hull known by construction.
// Inputs: random simple polygons (random points untangled by 2-opt moves: deep pockets that
// the chain leaves and re-enters) on the front, on the back (w < 0) and across Ω (in the open
// hemisphere x > 0 or x < 0, some vertices on Ω), each point at a positive scale 1, 2, 3 or
// 1/2, in both orientations and from any start; degenerate ones (combs whose teeth end on a hull
// edge, edges cut by collinear vertices, a collinear first run, repeated vertices at another
// scale, also across the end, polygons on one line); and LargePolygon: 10⁵ vertices alternating
// on two circles (h = 5·10⁴), across Ω and on the back, where an O(n h) method runs out of time.
#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include <t2/kernel/number.hpp>
#include <t2/kernel/orient.hpp>
#include <t2/kernel/point.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "hull.hpp"

namespace {

using t2::Integer;
using t2::Point;
using V = std::array<Integer, 3>;

inline V exact(const Point& p) {
  const t2::ExactPoint e = t2::to_exact(p);
  return {e.w(), e.x(), e.y()};
}
inline V cross(const V& p, const V& q) {
  return {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
}
inline int sign_dot(const V& p, const V& q) { return sgn(p[0] * q[0] + p[1] * q[1] + p[2] * q[2]); }

// For collinear p ≠ ±q and r: r = αp + βq; the signs of α and β.
inline std::array<int, 2> coefficients(const Point& p, const Point& q, const Point& r) {
  const V P = exact(p), Q = exact(q), R = exact(r), pq = cross(P, Q);
  return {sign_dot(cross(R, Q), pq), sign_dot(cross(P, R), pq)};
}

inline std::vector<long> expected_hull(const std::vector<Point>& P) {
  std::vector<long> S;  // the distinct points, by their smallest index
  for (std::size_t i = 0; i < P.size(); ++i)
    if (std::none_of(S.begin(), S.end(), [&](long j) { return P[j] == P[i]; })) S.push_back(long(i));
  if (S.size() <= 1) return S;
  bool line = true;
  for (long r : S) line = line && t2::orient(P[S[0]], P[S[1]], P[r]) == t2::ZERO;
  // p → q is an edge: every other point strictly left of it or strictly inside p q.
  const auto edge = [&](long p, long q) {
    for (long r : S) {
      if (r == p || r == q) continue;
      const t2::Sign o = t2::orient(P[p], P[q], P[r]);
      if (o < 0) return false;
      if (o == t2::ZERO) {
        const auto c = coefficients(P[p], P[q], P[r]);
        if (c[0] <= 0 || c[1] <= 0) return false;
      }
    }
    return true;
  };
  std::vector<long> C;
  for (long p : S)
    for (long q : S)
      if (C.empty() && p != q && edge(p, q)) C = {p, q};
  if (line || C.empty()) return C;
  while (C.size() <= S.size()) {
    long next = -1;
    for (long q : S)
      if (q != C.back() && edge(C.back(), q)) next = q;
    if (next == C[0] || next < 0) return C;
    C.push_back(next);
  }
  return C;
}

// "" when `got` is `want` up to a rotation (any start), else what differs.
inline std::string judge(const std::vector<long>& want, const std::vector<long>& got) {
  const auto show = [](const std::vector<long>& v) {
    std::string s;
    for (std::size_t k = 0; k < v.size() && k < 12; ++k) s += " " + std::to_string(v[k]);
    return s + (v.size() > 12 ? " ..." : "");
  };
  std::string bad = "expected" + show(want) + " (" + std::to_string(want.size()) + " vertices), got" + show(got) +
                    " (" + std::to_string(got.size()) + ")";
  if (want.size() != got.size()) return bad;
  if (want.empty()) return "";
  if (want.size() == 2 && got[0] == want[1] && got[1] == want[0]) return "";
  const auto at = std::find(got.begin(), got.end(), want[0]);
  if (at == got.end()) return bad;
  const std::size_t s = std::size_t(at - got.begin());
  for (std::size_t k = 0; k < want.size(); ++k)
    if (got[(s + k) % got.size()] != want[k]) return bad;
  return "";
}

// ---- inputs ----

using Planar = std::vector<std::array<double, 2>>;

bool crosses(const Planar& v, std::size_t i, std::size_t j, bool& degenerate) {
  const auto p = [&](std::size_t k) { return Point(1, v[k % v.size()][0], v[k % v.size()][1]); };
  const t2::Sign o1 = t2::orient(p(i), p(i + 1), p(j)), o2 = t2::orient(p(i), p(i + 1), p(j + 1));
  const t2::Sign o3 = t2::orient(p(j), p(j + 1), p(i)), o4 = t2::orient(p(j), p(j + 1), p(i + 1));
  if (o1 == 0 || o2 == 0 || o3 == 0 || o4 == 0) degenerate = true;
  return o1 * o2 < 0 && o3 * o4 < 0;
}

// A simple polygon of n random points of a 2²⁰ grid: 2-opt moves (reverse the path between
// two crossing edges: the length drops) until no two edges cross. Deep pockets, often nested.
Planar simple_polygon(std::mt19937_64& g, int n) {
  for (;;) {
    Planar v;
    for (int k = 0; k < n; ++k) v.push_back({double(g() % (1 << 20)), double(g() % (1 << 20))});
    bool degenerate = false, again = true;
    for (int pass = 0; again && !degenerate && pass < 100000; ++pass) {
      again = false;
      for (std::size_t i = 0; i < v.size() && !again; ++i)
        for (std::size_t j = i + 2; j < v.size() && !again; ++j) {
          if (i == 0 && j + 1 == v.size()) continue;  // adjacent across the end
          if (crosses(v, i, j, degenerate)) std::reverse(v.begin() + long(i) + 1, v.begin() + long(j) + 1), again = true;
        }
    }
    if (!again && !degenerate) return v;
  }
}

double scale(std::mt19937_64& g) {
  const double s[] = {1, 2, 3, 0.5};
  return s[g() % 4];
}

enum class Side { front, back, across };

// The planar polygon as points of T²: front [1, a, b]; back [-1, -a, -b] (drawn at the same
// place, every turn reversed); across Ω [a - c, ±D, b], in the open hemisphere ±x > 0, where a
// vertex with a = c lies on Ω. Each point at a positive scale; reversed, rotated.
std::vector<Point> lift(std::mt19937_64& g, Planar v, Side side) {
  if (g() % 2) std::reverse(v.begin(), v.end());
  std::rotate(v.begin(), v.begin() + long(g() % v.size()), v.end());
  const double c = v[g() % v.size()][0], D = double(g() % 2 ? 1 : -1) * (1 << 19);
  std::vector<Point> P;
  for (const auto& [a, b] : v) {
    const double s = scale(g);
    if (side == Side::front) P.push_back(Point(s, s * a, s * b));
    else if (side == Side::back) P.push_back(Point(-s, -s * a, -s * b));
    else P.push_back(Point(s * (a - c), s * D, s * b));
  }
  return P;
}

void expect_hull(const std::vector<Point>& P, const std::string& what) {
  const std::vector<long> want = expected_hull(P);
  EXPECT_EQ(judge(want, ex07c::hull(P)), "") << what;
}

void random_polygons(std::uint64_t seed, Side side, int rounds) {
  std::mt19937_64 g(seed);
  for (int round = 0; round < rounds; ++round)
    expect_hull(lift(g, simple_polygon(g, 6 + round % 22), side), "round " + std::to_string(round));
}

TEST(Hidden, Pockets) { random_polygons(7301, Side::front, 120); }

TEST(Hidden, BackSide) { random_polygons(7302, Side::back, 80); }

TEST(Hidden, AcrossOmega) { random_polygons(7303, Side::across, 80); }

// Combs: a bar with teeth that all end on the line y = H (the tips of the inner teeth lie inside
// the hull edge between the outer ones), with every edge cut by collinear vertices at random,
// some vertices repeated (at another scale), the first run collinear; and polygons on one line.
TEST(Hidden, Degenerate) {
  std::mt19937_64 g(7304);
  for (int round = 0; round < 60; ++round) {
    const int teeth = 2 + round % 5, H = 6;
    Planar v = {{0, 0}, {double(4 * teeth - 2), 0}};
    for (int t = teeth - 1; t >= 0; --t) {
      const double x = 4 * t;
      v.push_back({x + 2, H});
      v.push_back({x, H});
      if (t > 0) v.push_back({x, 2}), v.push_back({x - 2, 2});
    }
    Planar cut;  // vertices inside edges (every coordinate even, so the midpoint is exact)
    for (std::size_t k = 0; k < v.size(); ++k) {
      cut.push_back(v[k]);
      if (g() % 2) cut.push_back({(v[k][0] + v[(k + 1) % v.size()][0]) / 2, (v[k][1] + v[(k + 1) % v.size()][1]) / 2});
    }
    std::vector<Point> P = lift(g, cut, Side(round % 3));
    for (int k = 0; k < 3; ++k) {  // repeats, at another scale, next to the original
      const std::size_t i = g() % P.size();
      P.insert(P.begin() + long(i) + 1, Point(2 * P[i].w(), 2 * P[i].x(), 2 * P[i].y()));
    }
    if (round % 4 == 0) P.push_back(Point(3 * P[0].w(), 3 * P[0].x(), 3 * P[0].y()));  // the last repeats the first
    expect_hull(P, "round " + std::to_string(round));
  }
  for (int round = 0; round < 12; ++round) {  // on one line: a point and back, or a segment
    Planar v = {{2, 1}, {6, 3}, {10, 5}};
    if (round % 2) v.push_back({8, 4});
    if (round % 3 == 0) v = {{4, 2}, {4, 2}};
    expect_hull(lift(g, v, Side(round % 3)), "one line, round " + std::to_string(round));
  }
}

// 10⁵ vertices alternating between a circle of radius R = 2⁴⁰ (the hull, 5·10⁴ vertices) and the
// circle of radius R/2 (each in the pocket between its two neighbours), lifted across Ω (first
// round) and to the back (second). Certificate, exact: the outer vertices turn strictly the
// same way at each vertex and round the centre c; each inner one lies strictly inside the
// triangle c, o_k, o_{k+1}. So the hull is the outer cycle, in the order its turns give.
TEST(Hidden, LargePolygon) {
  const int h = 50000;
  const double R = std::ldexp(1.0, 40), pi = std::acos(-1.0);
  for (int round = 0; round < 2; ++round) {
    std::mt19937_64 g(7305 + round);
    std::vector<Point> P, O;
    const auto at = [&](double r, double t) {
      const double a = std::round(r * std::cos(t)), b = std::round(r * std::sin(t)), s = scale(g);
      return round == 0 ? Point(s * a, s * R, s * b) : Point(-s * R, -s * a, -s * b);
    };
    const Point c = round == 0 ? Point(0, 1, 0) : Point(-1, 0, 0);
    for (int k = 0; k < h; ++k) {
      P.push_back(at(R, 2 * pi * k / h));
      P.push_back(at(R / 2, 2 * pi * (k + 0.5) / h));
    }
    const t2::Sign turn = t2::orient(P[0], P[2], P[4]);
    std::vector<long> want;
    for (int k = 0; k < h; ++k) {
      const Point &o0 = P[2 * k], &o1 = P[(2 * k + 2) % (2 * h)], &o2 = P[(2 * k + 4) % (2 * h)], &in = P[2 * k + 1];
      ASSERT_TRUE(t2::orient(o0, o1, o2) == turn && t2::orient(c, o0, o1) == turn) << "the test's construction";
      ASSERT_TRUE(t2::orient(o0, o1, in) == turn && t2::orient(c, o0, in) == turn && t2::orient(c, in, o1) == turn)
          << "the test's construction";
      want.push_back(2 * k);
    }
    if (turn < 0) std::reverse(want.begin(), want.end());
    EXPECT_EQ(judge(want, ex07c::hull(P)), "") << "round " << round;
  }
}

}  // namespace
