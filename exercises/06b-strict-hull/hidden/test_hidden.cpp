// Exercise 06b, hidden tests. Oracles, independent of any hull algorithm: a brute force from the
// definition (p q is a hull edge iff every point is on its left or on the closed segment pq,
// decided with the exact t2::orient and big integers), for small front sets and for points a
// few units in the last place off a line; hulls known by construction (points of the parabola
// y = x², with points inside, on the edges and repeated) sent by integer projective maps of
// positive determinant, which keep hulls and orientation, to both sides and Ω; and sets known to
// lie in no open hemisphere.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include <t2/kernel/error.hpp>
#include <t2/kernel/orient.hpp>
#include <t2/kernel/point.hpp>

#include "cycle.hpp"
#include "hull.hpp"

namespace {

using ex06btest::compare;
using t2::Point;

using M3 = std::array<std::array<double, 3>, 3>;

// A random integer matrix with entries in [-3, 3] and a positive determinant.
M3 positive_map(std::mt19937_64& g) {
  std::uniform_int_distribution<int> d(-3, 3);
  for (;;) {
    M3 m;
    for (auto& r : m)
      for (auto& e : r) e = d(g);
    const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                       m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    if (det > 0) return m;
  }
}

std::vector<Point> image(const M3& m, const std::vector<Point>& P) {
  std::vector<Point> Q;
  for (const Point& p : P) {
    auto row = [&](int i) { return m[i][0] * p.w() + m[i][1] * p.x() + m[i][2] * p.y(); };
    Q.push_back(Point(row(0), row(1), row(2)));
  }
  return Q;
}

// αp + βq, exact for small integers.
Point mix(double al, const Point& p, double be, const Point& q) {
  return Point(al * p.w() + be * q.w(), al * p.x() + be * q.x(), al * p.y() + be * q.y());
}

// y on the closed segment pq (all three on one line, p ≠ ±q), in big integers.
bool between(const Point& p, const Point& q, const Point& y) {
  const t2::ExactPoint a = t2::to_exact(p), b = t2::to_exact(q), c = t2::to_exact(y);
  auto cross = [](const t2::ExactPoint& u, const t2::ExactPoint& v) {
    return std::array<t2::Integer, 3>{u.x() * v.y() - u.y() * v.x(), u.y() * v.w() - u.w() * v.y(),
                                      u.w() * v.x() - u.x() * v.w()};
  };
  auto dot = [](const std::array<t2::Integer, 3>& u, const std::array<t2::Integer, 3>& v) -> t2::Integer {
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  };
  const auto L = cross(a, b);
  return dot(cross(c, b), L) >= 0 && dot(cross(a, c), L) >= 0;
}

// The hull by brute force, for a set known to have one: its edges are the pairs p q of different
// points with every point left of pq or on the segment pq; they are chained into the cycle.
std::vector<long> brute_hull(const std::vector<Point>& P) {
  std::vector<long> U;  // one index per point of T²
  for (long i = 0; i < long(P.size()); ++i)
    if (ex06btest::first_of(P, i) == i) U.push_back(i);
  if (U.size() == 1) return U;
  std::vector<std::pair<long, long>> E;
  for (long i : U)
    for (long j : U) {
      if (i == j) continue;
      bool edge = true;
      for (long k : U) {
        const t2::Sign s = t2::orient(P[i], P[j], P[k]);
        if (s < 0 || (s == 0 && !between(P[i], P[j], P[k]))) {
          edge = false;
          break;
        }
      }
      if (edge) E.push_back({i, j});
    }
  if (E.size() == 2 && E[0].first == E[1].second) return {E[0].first, E[0].second};  // a segment
  std::vector<long> C = {E.at(0).first};
  for (;;) {
    const auto e = std::find_if(E.begin(), E.end(), [&](const auto& x) { return x.first == C.back(); });
    if (e->second == C[0]) return C;
    C.push_back(e->second);
  }
}

std::vector<Point> front_set(std::mt19937_64& g, int n, int range) {
  std::uniform_int_distribution<int> d(-range, range);
  std::vector<Point> P;
  for (int k = 0; k < n; ++k) P.push_back(Point::cartesian(d(g), d(g)));
  return P;
}

TEST(Hidden, FrontAgainstBruteForce) {
  std::mt19937_64 g(60);
  for (int round = 0; round < 150; ++round) {
    const std::vector<Point> P = front_set(g, 1 + round % 40, 2 + round % 5);  // small grids: collinear, repeats
    EXPECT_EQ(compare(P, ex06b::hull(P), brute_hull(P)), "") << "round " << round;
  }
}

// A hull known by construction: m points of y = x² (all strict vertices, counter-clockwise by
// increasing x), points strictly inside triangles of them, points inside the edges, repeats at
// another scale, shuffled; `want` receives the hull's indices in order.
std::vector<Point> parabola_set(std::mt19937_64& g, int m, int inside, int on_edges, std::vector<long>& want) {
  std::vector<int> xs;
  for (int x = -60; x <= 60; ++x) xs.push_back(x);
  std::shuffle(xs.begin(), xs.end(), g);
  xs.resize(m);
  std::sort(xs.begin(), xs.end());
  std::vector<Point> V;
  for (int x : xs) V.push_back(Point::cartesian(x, double(x) * x));
  std::vector<std::pair<Point, int>> S;  // a point, and its vertex number or -1
  for (int k = 0; k < m; ++k) S.push_back({V[k], k});
  std::uniform_int_distribution<int> c(1, 4), v(0, m - 1);
  for (int k = 0; k < inside; ++k) {
    const int a = v(g), b = (a + 1 + v(g) % (m - 1)) % m, d = v(g);
    if (d == a || d == b) continue;
    S.push_back({mix(1, mix(c(g), V[a], c(g), V[b]), c(g), V[d]), -1});
  }
  for (int k = 0; k < on_edges; ++k) {
    const int a = v(g);
    S.push_back({mix(c(g), V[a], c(g), V[(a + 1) % m]), -1});
  }
  for (int k = 0; k < m / 4; ++k) {
    const int a = v(g);
    S.push_back({mix(3, V[a], 0, V[a]), -1});  // V[a] again, scaled by 3
  }
  std::shuffle(S.begin(), S.end(), g);
  std::vector<Point> P;
  want.assign(m, -1);
  for (const auto& [p, k] : S) {
    if (k >= 0) want[k] = long(P.size());
    P.push_back(p);
  }
  return P;
}

TEST(Hidden, ProjectiveImages) {
  std::mt19937_64 g(606);
  int mixed = 0;
  for (int round = 0; round < 30; ++round) {
    std::vector<long> want;
    const std::vector<Point> Q = image(positive_map(g), parabola_set(g, 3 + round * 2, 3 * round, round, want));
    mixed += std::any_of(Q.begin(), Q.end(), [](const Point& q) { return q.w() < 0; }) &&
             std::any_of(Q.begin(), Q.end(), [](const Point& q) { return q.w() > 0; });
    EXPECT_EQ(compare(Q, ex06b::hull(Q), want), "") << "round " << round;
  }
  EXPECT_GT(mixed, 5);
}

TEST(Hidden, EdgePointsAreNotVertices) {
  std::mt19937_64 g(6006);
  for (int round = 0; round < 20; ++round) {
    // A triangle with many points inside its edges, sent across Ω.
    std::vector<long> want;
    const std::vector<Point> Q = image(positive_map(g), parabola_set(g, 3, 0, 30, want));
    EXPECT_EQ(compare(Q, ex06b::hull(Q), want), "") << "round " << round;
    // Points of one line, from the front through Ω to the back, within half of it: the hull is
    // the segment between the two extreme ones.
    const Point a = Point::cartesian(round, 1), b = Point(0, 1, 2);  // b: the line's point on Ω
    std::vector<Point> L = {mix(1, a, 5, b), mix(-1, a, 3, b), a, mix(1, a, 1, b), b, mix(-1, a, 9, b)};
    std::shuffle(L.begin(), L.end(), g);
    const long lo = std::find_if(L.begin(), L.end(), [&](const Point& p) { return p == a; }) - L.begin();
    const long hi = std::find_if(L.begin(), L.end(), [&](const Point& p) { return p == mix(-1, a, 3, b); }) - L.begin();
    EXPECT_EQ(compare(L, ex06b::hull(L), {lo, hi}), "") << "a line through Ω, round " << round;
  }
}

TEST(Hidden, NoHull) {
  std::mt19937_64 g(60006);
  EXPECT_THROW(ex06b::hull({Point::cartesian(1, 1), Point(0, 1, 0), Point(0, -1, 2), Point(0, -1, -2)}), t2::Undefined)
      << "three directions all round Ω";
  for (int round = 0; round < 30; ++round) {
    std::vector<long> want;
    std::vector<Point> S = parabola_set(g, 5, 10, 3, want);
    const Point& p = S[g() % S.size()];
    const Point& q = S[g() % S.size()];
    const Point& r = S[g() % S.size()];
    EXPECT_EQ(compare(S, ex06b::hull(S), want), "") << "before the antipode, round " << round;
    switch (round % 3) {
      case 0: S.push_back(mix(-2, p, 0, p)); break;                    // an antipode
      case 1: S.push_back(mix(-1, p, -2, q)); break;                   // ¬ of a point on a segment
      default: S.push_back(mix(-1, mix(1, p, 2, q), -3, r)); break;    // ¬ of a point in a triangle
    }
    std::shuffle(S.begin(), S.end(), g);
    const std::vector<Point> Q = image(positive_map(g), S);
    EXPECT_THROW(ex06b::hull(Q), t2::Undefined) << "round " << round;
  }
}

// A segment ab far from the origin (on a grid of 1/64), points at eighths of it (exact), moved
// up or down by up to two units in the last place, and a point below: which of them are strict
// vertices only exact signs tell.
TEST(Hidden, NearlyCollinear) {
  std::mt19937_64 g(600006);
  std::uniform_int_distribution<int> u(-640, 640);
  for (int round = 0; round < 30; ++round) {
    const double ax = 1000 + u(g) / 64.0, ay = 2000 + u(g) / 64.0, bx = 1100 + u(g) / 64.0, by = 2000 + u(g) / 64.0;
    std::vector<Point> P = {Point::cartesian(ax, ay), Point::cartesian(bx, by), Point::cartesian(1050, 1000)};
    for (int k = 1; k < 8; ++k) {
      const double x = ax + (bx - ax) * k / 8;
      double y = ay + (by - ay) * k / 8;
      for (int s = static_cast<int>(g() % 5) - 2; s != 0; s += s > 0 ? -1 : 1) y = std::nextafter(y, s > 0 ? 9e9 : -9e9);
      P.push_back(Point::cartesian(x, y));
    }
    std::shuffle(P.begin(), P.end(), g);
    EXPECT_EQ(compare(P, ex06b::hull(P), brute_hull(P)), "") << "round " << round;
  }
}

}  // namespace
