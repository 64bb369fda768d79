// Exercise 08b, hidden tests. Oracle: every facet of the hull by brute force — a triple of
// distinct points spans a facet plane when no point is strictly beyond it (exact orient3d); the
// facet is the strict hull of the points of that plane, found edge by edge (u -> v is an edge
// when every point of the plane is strictly to its left or on the closed segment u v). Each
// facet and each of its edges is then asked for. Inputs: random points, the 3×3×3 grid with
// copies (points inside edges and facets, duplicates), prisms with polygon facets, and points
// rounded near a plane.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>

#include <t2/kernel/orient.hpp>
#include <t2/kernel/point.hpp>

#include "facet.hpp"

namespace {

using t2::Point3;

bool same(const Point3& p, const Point3& q) { return p.x == q.x && p.y == q.y && p.z == q.z; }

t2::Point flat(const Point3& p, int drop) {
  return drop == 0 ? t2::Point::cartesian(p.x, p.y) : drop == 1 ? t2::Point::cartesian(p.y, p.z)
                                                                 : t2::Point::cartesian(p.z, p.x);
}

// The facet in the plane of (i, j, k), which has no point beyond it: strict vertices,
// counter-clockwise seen from outside, rotated to its smallest index.
std::vector<long> facet_of(const std::vector<Point3>& P, const std::vector<long>& ids, long i, long j, long k) {
  std::vector<long> S;
  for (long q : ids)
    if (t2::orient3d(P[i], P[j], P[k], P[q]) == t2::ZERO) S.push_back(q);
  int drop = 0;
  t2::Sign s = t2::ZERO;
  while ((s = t2::orient(flat(P[i], drop), flat(P[j], drop), flat(P[k], drop))) == t2::ZERO) ++drop;
  auto between = [&](long u, long v, long w) {
    const t2::Point U = flat(P[u], drop), V = flat(P[v], drop), W = flat(P[w], drop);
    return std::min(U.x(), V.x()) <= W.x() && W.x() <= std::max(U.x(), V.x()) && std::min(U.y(), V.y()) <= W.y() &&
           W.y() <= std::max(U.y(), V.y());
  };
  std::map<long, long> next;
  for (long u : S)
    for (long v : S) {
      if (u == v) continue;
      bool edge = true;
      for (long w : S) {
        const int o = s * t2::orient(flat(P[u], drop), flat(P[v], drop), flat(P[w], drop));
        if (o < 0 || (o == 0 && !between(u, v, w))) edge = false;
      }
      if (edge) next[u] = v;
    }
  std::vector<long> F = {next.begin()->first};
  while (next.at(F.back()) != F.front()) F.push_back(next.at(F.back()));
  std::rotate(F.begin(), std::min_element(F.begin(), F.end()), F.end());
  return F;
}

// Every facet of the hull of P, by brute force.
std::set<std::vector<long>> all_facets(const std::vector<Point3>& P) {
  std::vector<long> ids;  // of equal points the smallest index
  for (long q = 0; q < long(P.size()); ++q)
    if (std::none_of(ids.begin(), ids.end(), [&](long r) { return same(P[r], P[q]); })) ids.push_back(q);
  std::set<std::vector<long>> F;
  for (long i : ids)
    for (long j : ids)
      for (long k : ids) {
        if (!(i < j && i < k && j != k)) continue;
        bool support = false;
        for (long q : ids) {
          const t2::Sign o = t2::orient3d(P[i], P[j], P[k], P[q]);
          if (o == t2::POSITIVE) goto next_triple;
          support |= o == t2::NEGATIVE;
        }
        if (support) F.insert(facet_of(P, ids, i, j, k));
      next_triple:;
      }
  return F;
}

// Asks for the facet across every edge of every facet; returns the number of answers checked.
int check_all(const std::vector<Point3>& P) {
  const std::set<std::vector<long>> F = all_facets(P);
  std::map<std::pair<long, long>, const std::vector<long>*> owner;
  for (const auto& f : F)
    for (std::size_t i = 0; i < f.size(); ++i) owner[{f[i], f[(i + 1) % f.size()]}] = &f;
  int n = 0;
  for (const auto& f : F)
    for (std::size_t k = 0; k < f.size(); ++k) {
      const long a = f[k], b = f[(k + 1) % f.size()];
      std::vector<long> want = *owner.at({b, a});
      std::rotate(want.begin(), std::find(want.begin(), want.end(), b), want.end());
      EXPECT_EQ(ex08b::next_facet(P, f, long(k)), want) << "facet of " << f.size() << " vertices, edge " << k;
      ++n;
    }
  return n;
}

double unit(std::mt19937_64& g) { return double(g() >> 11) * 0x1p-53; }

TEST(Hidden, RandomPoints) {
  std::mt19937_64 g(808);
  for (int round = 0; round < 2; ++round) {
    std::vector<Point3> P;
    for (int k = 0; k < 30; ++k) P.push_back({unit(g), unit(g), unit(g)});
    EXPECT_GT(check_all(P), 30);
  }
}

// The grid {0, 1, 2}³ in a shuffled order, and copies of some of its points.
TEST(Hidden, GridCube) {
  std::vector<Point3> P;
  for (int k = 0; k < 27; ++k) P.push_back({double(k % 3), double(k / 3 % 3), double(k / 9)});
  std::shuffle(P.begin(), P.end(), std::mt19937_64(27));
  for (int k = 0; k < 27; k += 4) P.push_back(P[k]);
  EXPECT_EQ(check_all(P), 24);  // six squares of four strict corners each
}

// Prisms and pyramids over regular-ish polygons with integer corners: facets with many vertices,
// some points inside their edges.
TEST(Hidden, PolygonFacets) {
  const std::vector<std::pair<double, double>> oct = {{3, 0}, {2, 2}, {0, 3}, {-2, 2}, {-3, 0}, {-2, -2}, {0, -3}, {2, -2},
                                                      {1, 1}, {0, 0}, {2.5, 1}, {1, 2.5}};
  std::vector<Point3> P;
  for (const auto& [x, y] : oct) P.push_back({x, y, 0});
  for (const auto& [x, y] : oct) P.push_back({x, y, 5});
  P.push_back({0, 0, 9});
  EXPECT_GT(check_all(P), 40);
  P.pop_back();
  for (const auto& [x, y] : oct) P.push_back({x, y, 2.5});
  EXPECT_GT(check_all(P), 40);
}

// Points of a tilted plane rounded to doubles (so a few units in the last place off it), under a
// cap point: the hull's facets near the plane are nearly coplanar, and a determinant evaluated
// in doubles misjudges which points lie beyond or on a plane.
TEST(Hidden, NearlyCoplanar) {
  std::mt19937_64 g(8088);
  std::vector<Point3> P;
  for (int k = 0; k < 22; ++k) {
    const double x = unit(g), y = unit(g);
    P.push_back({x, y, 0.1 * x + 0.3 * y + 0.7});
  }
  P.push_back({0.5, 0.5, -3});
  EXPECT_GT(check_all(P), 20);
}

}  // namespace
