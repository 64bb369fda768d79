// Exercise 09c, hidden tests. Oracle: certificate.hpp (an exact certificate of a triangulated
// sphere) and the answer of insert.hpp's rules, written here again from the geometry (¬q in the
// closed hull H iff orient(a, b, ¬q) >= 0 for every hull edge a -> b); the kinds from the signs of
// orient and w. Each test builds triangulations with the rules, then asks insert (and kinds, on
// the answer): the antipodes of the hull vertices (two lunes), back points that destroy a front
// hull or leave it (band faces), a set on both sides in the hemisphere x > 0, sites on Ω (points
// and antipodes on Ω), and antipodes inside hull edges, also where the hull is straight
// (Undefined, next to insertions that are defined).
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <random>

#include <t2/kernel/error.hpp>

#include "certificate.hpp"
#include "insert.hpp"

namespace {

using t2::Point;
using ex09c::Kind;
using ex09ctest::Tri;
constexpr long I = ex09c::kInfinite;

std::vector<Tri> faces(const std::vector<long>& T) {
  std::vector<Tri> r;
  for (std::size_t k = 0; k + 2 < T.size(); k += 3) r.push_back({T[k], T[k + 1], T[k + 2]});
  return r;
}

std::vector<long> flat(const std::vector<Tri>& F) {
  std::vector<long> r;
  for (const Tri& t : F) r.insert(r.end(), t.begin(), t.end());
  return r;
}

// The hull edges a -> b of T, read off its infinite triangles (b, a, v∞).
std::vector<std::pair<long, long>> hull_edges(const std::vector<long>& T) {
  std::vector<std::pair<long, long>> r;
  for (Tri t : faces(T))
    if (std::find(t.begin(), t.end(), I) != t.end()) {
      std::rotate(t.begin(), std::find(t.begin(), t.end(), I), t.end());  // (v∞, b, a)
      r.push_back({t[2], t[1]});
    }
  return r;
}

// The rules of insert.hpp; nullopt where they say Undefined.
std::optional<std::vector<long>> rule(const std::vector<Point>& P, const std::vector<long>& T, long q) {
  const Point p = P[q], np = t2::antipode(p);
  auto is_vertex = [&](const Point& x) { return std::any_of(T.begin(), T.end(), [&](long v) { return v != I && P[v] == x; }); };
  if (is_vertex(p)) return T;
  const auto H = hull_edges(T);
  auto signs = [&](const Point& x, int want) {
    return long(std::count_if(H.begin(), H.end(), [&](const auto& e) { return int(t2::orient(P[e.first], P[e.second], x)) == want; }));
  };
  std::vector<Tri> F = faces(T);
  if (signs(p, -1) == 0) {  // p in H: the finite face or edge that holds it
    for (std::size_t f = 0; f < F.size(); ++f) {
      const Tri t = F[f];
      if (t[0] == I || t[1] == I || t[2] == I) continue;
      int s[3];
      for (int i = 0; i < 3; ++i) s[i] = int(t2::orient(P[t[i]], P[t[(i + 1) % 3]], p));
      if (std::min({s[0], s[1], s[2]}) < 0) continue;
      F.erase(F.begin() + long(f));
      if (s[0] && s[1] && s[2]) {
        F.insert(F.end(), {{t[0], t[1], q}, {t[1], t[2], q}, {t[2], t[0], q}});
        return flat(F);
      }
      const int i = !s[0] ? 0 : !s[1] ? 1 : 2;
      const long a = t[i], b = t[(i + 1) % 3], c = t[(i + 2) % 3];
      for (std::size_t g = 0; g < F.size(); ++g) {
        Tri u = F[g];
        const auto at = std::find(u.begin(), u.end(), b);
        if (at == u.end()) continue;
        std::rotate(u.begin(), at, u.end());  // (b, ?, ?)
        if (u[1] != a) continue;
        F.erase(F.begin() + long(g));
        F.insert(F.end(), {{a, q, c}, {q, b, c}, {b, q, u[2]}, {q, a, u[2]}});
        return flat(F);
      }
    }
    ADD_FAILURE() << "test bug: a point of the hull in no face";
    return T;
  }
  if (signs(np, -1) > 0) {  // ¬p outside H: the hull survives
    std::vector<std::pair<long, long>> seen;
    for (auto& t : F) {
      if (std::find(t.begin(), t.end(), I) == t.end()) continue;
      std::rotate(t.begin(), std::find(t.begin(), t.end(), I), t.end());  // (v∞, b, a): hull edge a -> b
      if (t2::orient(P[t[2]], P[t[1]], p) < 0) {  // p strictly right of a -> b: (b, a, q)
        seen.push_back({t[2], t[1]});
        t = {t[1], t[2], q};
      }
    }
    long first = I, last = I;  // the chain of seen edges runs first -> ... -> last
    for (const auto& [a, b] : seen) {
      if (std::none_of(seen.begin(), seen.end(), [&](const auto& e) { return e.second == a; })) first = a;
      if (std::none_of(seen.begin(), seen.end(), [&](const auto& e) { return e.first == b; })) last = b;
    }
    F.insert(F.end(), {{q, first, I}, {last, q, I}});
    return flat(F);
  }
  if (signs(np, 0) == 0 || is_vertex(np)) {  // ¬p strictly inside H, or a vertex: H is destroyed
    for (auto& t : F)
      for (long& v : t) v = v == I ? q : v;
    return flat(F);
  }
  return std::nullopt;  // ¬p inside a hull edge
}

std::vector<Kind> kinds(const std::vector<Point>& P, const std::vector<long>& T) {
  std::vector<Kind> r;
  for (const Tri& t : faces(T)) {
    if (std::find(t.begin(), t.end(), I) != t.end()) {
      r.push_back(Kind::infinite);
      continue;
    }
    const Point &a = P[t[0]], &b = P[t[1]], &c = P[t[2]];
    if (t2::orient(a, b, c) == t2::ZERO) {
      const bool pair = t2::antipode(a) == b || t2::antipode(b) == c || t2::antipode(c) == a;
      r.push_back(pair ? Kind::lune : Kind::flat);
    } else if (a.w() > 0 && b.w() > 0 && c.w() > 0) {
      r.push_back(Kind::front);
    } else if (a.w() < 0 && b.w() < 0 && c.w() < 0) {
      r.push_back(Kind::back);
    } else {
      r.push_back(a.w() == 0 || b.w() == 0 || c.w() == 0 ? Kind::omega : Kind::band);
    }
  }
  return r;
}

// Asks insert(P, T, q) and the kinds of its answer; returns the kinds the rules give.
std::vector<Kind> ask(const std::vector<Point>& P, const std::vector<long>& T, long q, const std::string& what) {
  const auto want = rule(P, T, q);
  if (!want) {
    EXPECT_THROW(ex09c::insert(P, T, q), t2::Undefined) << what << ": ¬q inside a hull edge";
    return {};
  }
  EXPECT_EQ(ex09ctest::check(P, T, q, ex09c::insert(P, T, q), *want), "") << what;
  const auto k = kinds(P, *want);
  EXPECT_TRUE(ex09c::kinds(P, *want) == k) << what << ": the kinds of the faces";
  return k;
}

// The triangulation of P (an open hemisphere) by the rules, in the order given.
std::vector<long> grow(const std::vector<Point>& P) {
  std::size_t k = 2;
  while (t2::orient(P[0], P[1], P[k]) == t2::ZERO) ++k;
  std::vector<long> T = t2::orient(P[0], P[1], P[k]) > 0
                            ? std::vector<long>{0, 1, long(k), 1, 0, I, long(k), 1, I, 0, long(k), I}
                            : std::vector<long>{0, long(k), 1, long(k), 0, I, 1, long(k), I, 0, 1, I};
  for (long q = 2; q < long(P.size()); ++q)
    if (q != long(k)) T = *rule(P, T, q);
  return T;
}

long count(const std::vector<Kind>& k, Kind x) { return long(std::count(k.begin(), k.end(), x)); }

double unit(std::mt19937_64& g) { return double(g() >> 11) * 0x1p-53; }

std::vector<long> hull_vertices(const std::vector<long>& T) {
  std::vector<long> r;
  for (const auto& e : hull_edges(T)) r.push_back(e.first);
  return r;
}

TEST(Hidden, AntipodeOfAHullVertex) {
  std::mt19937_64 g(2028);
  for (int round = 0; round < 3; ++round) {
    std::vector<Point> P;
    for (int k = 0; k < 30; ++k) P.push_back(Point(1 + round, (1 + round) * std::floor(64 * unit(g)), (1 + round) * std::floor(64 * unit(g))));
    const std::vector<long> T = grow(P);
    for (long z : hull_vertices(T)) {
      std::vector<Point> Q = P;
      const Point& p = P[z];
      Q.push_back(Point(-3 * p.w(), -3 * p.x(), -3 * p.y()));  // ¬z, with another weight
      const auto k = ask(Q, T, long(P.size()), "¬ of the hull vertex " + std::to_string(z));
      EXPECT_EQ(count(k, Kind::lune), 2) << "test bug: two lunes at a hull vertex";
    }
  }
}

// A front hull; back points: the antipodes of points strictly inside it (the hull is destroyed,
// every new face a band face) and random back points (the hull often survives).
TEST(Hidden, HullDestroyed) {
  std::mt19937_64 g(28);
  std::vector<Point> P;
  for (int k = 0; k < 25; ++k) P.push_back(Point::cartesian(unit(g), unit(g)));
  const std::vector<long> T = grow(P);
  long band = 0;
  for (int k = 0; k < 60; ++k) {
    std::vector<Point> Q = P;
    const double x = 0.25 + unit(g) / 2, y = 0.25 + unit(g) / 2, w = k % 2 ? -1 : -0.5;
    Q.push_back(k % 3 ? Point(w, w * x, w * y) : Point(w, w * (3 * unit(g) - 1), w * (3 * unit(g) - 1)));
    band += count(ask(Q, T, 25, "back point " + std::to_string(k)), Kind::band);
  }
  EXPECT_GT(band, 100) << "test bug: few band faces";
}

// Points of T² in the open hemisphere x > 0, front and back; every kind of new point.
TEST(Hidden, BothSidesSet) {
  std::mt19937_64 g(2029);
  std::vector<Point> P;
  for (int k = 0; k < 30; ++k) {
    const double w = double(long(g() % 13) - 6), x = double(1 + g() % 16), y = double(long(g() % 33) - 16);
    P.push_back(Point(w == 0 ? 1 : w, x, y));
  }
  const std::vector<long> T = grow(P);
  long band = 0, back = 0;
  for (const auto& k : kinds(P, T)) band += k == Kind::band, back += k == Kind::back;
  ASSERT_GT(band, 3);
  ASSERT_GT(back, 3);
  EXPECT_TRUE(ex09c::kinds(P, T) == kinds(P, T)) << "the kinds of a triangulation on both sides";
  for (long z = 0; z < 30; ++z) {
    std::vector<Point> Q = P;
    Q.push_back(t2::antipode(P[z]));
    ask(Q, T, 30, "¬ of point " + std::to_string(z));
  }
  for (int k = 0; k < 30; ++k) {
    std::vector<Point> Q = P;
    const double w = double(long(g() % 13) - 6), x = double(long(g() % 33) - 16), y = double(long(g() % 33) - 16);
    if (w == 0 && x == 0 && y == 0) continue;
    Q.push_back(Point(w, x, y));
    ask(Q, T, 30, "point " + std::to_string(k));
  }
}

// Sites on Ω: points of Ω in the hull (some of them hull vertices), new points on Ω, and the
// antipodes of the Ω hull vertices (two lunes with their vertices on Ω).
TEST(Hidden, SitesOnOmega) {
  std::mt19937_64 g(2030);
  std::vector<Point> P;
  for (int k = 0; k < 30; ++k) {
    const double w = k % 4 == 0 ? 0.0 : double(long(g() % 13) - 6), x = double(1 + g() % 16), y = double(long(g() % 33) - 16);
    P.push_back(Point(w, x, y));
  }
  const std::vector<long> T = grow(P);
  long omega = 0;
  for (const auto& k : kinds(P, T)) omega += k == Kind::omega;
  ASSERT_GT(omega, 3);
  EXPECT_TRUE(ex09c::kinds(P, T) == kinds(P, T)) << "the kinds of a triangulation with sites on Ω";
  long omega_lunes = 0;
  for (long z : hull_vertices(T)) {
    std::vector<Point> Q = P;
    Q.push_back(t2::antipode(P[z]));
    const auto k = ask(Q, T, 30, "¬ of the hull vertex " + std::to_string(z));
    omega_lunes += P[z].w() == 0 && count(k, Kind::lune) == 2;
  }
  EXPECT_GT(omega_lunes, 0) << "test bug: no hull vertex on Ω";
  for (int k = 0; k < 30; ++k) {
    std::vector<Point> Q = P;
    const double x = double(long(g() % 33) - 16), y = double(long(g() % 33) - 16);
    if (x == 0 && y == 0) continue;
    Q.push_back(Point(0, x, y));
    ask(Q, T, 30, "point of Ω " + std::to_string(k));
  }
}

// ¬q inside a hull edge: Undefined. A grid, whose hull is straight along each side (hull
// vertices in the middle of sides): the antipodes of those vertices are defined (two lunes and
// flat faces along the side), the antipodes of points between them are not.
TEST(Hidden, AntipodeInsideAHullEdge) {
  std::vector<Point> P;
  for (int k = 0; k < 16; ++k) P.push_back(Point::cartesian(k % 4, k / 4));
  std::shuffle(P.begin() + 3, P.end(), std::mt19937_64(31));
  const std::vector<long> T = grow(P);
  long undefined = 0, flats = 0;
  for (int k = 0; k < 7; ++k)
    for (int m = 0; m < 7; ++m) {
      std::vector<Point> Q = P;
      Q.push_back(Point(-2, -double(k), -double(m)));  // ¬ of (k/2, m/2)
      const auto want = rule(Q, T, 16);
      undefined += !want;
      const auto kind = ask(Q, T, 16, "¬(" + std::to_string(k) + "/2, " + std::to_string(m) + "/2)");
      flats += count(kind, Kind::flat);
    }
  EXPECT_EQ(undefined, 12) << "test bug: the half-integer points inside the grid's hull edges";
  EXPECT_GT(flats, 0) << "test bug: no flat face";
}

}  // namespace
