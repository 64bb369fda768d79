// Exercise 08, hidden tests. Oracle: certificate.hpp (the exact certificate of a closed convex
// surface containing the old vertices and the new point) and the unique answer of the rule.
// Hulls by brute force (a triple is a face when every other point is strictly inside its plane:
// random points have no four coplanar) or written out (the cube); inputs:
// random points in and around a ball, a cube's coplanar triangles with points on its face
// planes, edges, corners and inside, and points rounded onto the plane of a face.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

#include "certificate.hpp"
#include "horizon.hpp"

namespace {

using t2::Point3;

double unit(std::mt19937_64& g) { return double(g() >> 11) * 0x1p-53; }

// The hull of P[0..n) by brute force, for points with no four coplanar: its outward triangles.
std::vector<long> brute_hull(const std::vector<Point3>& P, std::size_t n) {
  std::vector<long> H;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = j + 1; k < n; ++k) {
        int pos = 0, neg = 0;
        for (std::size_t q = 0; q < n; ++q) {
          const t2::Sign s = t2::orient3d(P[i], P[j], P[k], P[q]);
          pos += s == t2::POSITIVE;
          neg += s == t2::NEGATIVE;
        }
        if (pos == 0) H.insert(H.end(), {long(i), long(j), long(k)});
        if (neg == 0) H.insert(H.end(), {long(i), long(k), long(j)});
      }
  return H;
}

// The answer by the rule of horizon.hpp: what p does not see strictly stays, and each horizon
// edge a -> b gets (a, b, p).
std::vector<long> rule(const std::vector<Point3>& P, const std::vector<long>& H, long p) {
  std::vector<long> want;
  std::map<std::pair<long, long>, bool> seen_edge;
  std::vector<bool> seen;
  for (std::size_t k = 0; k < H.size(); k += 3) {
    seen.push_back(t2::orient3d(P[H[k]], P[H[k + 1]], P[H[k + 2]], P[p]) == t2::POSITIVE);
    for (int i = 0; i < 3; ++i) seen_edge[{H[k + i], H[k + (i + 1) % 3]}] = seen.back();
  }
  for (std::size_t k = 0; k < H.size(); k += 3) {
    if (!seen[k / 3]) want.insert(want.end(), {H[k], H[k + 1], H[k + 2]});
    else
      for (int i = 0; i < 3; ++i)
        if (!seen_edge.at({H[k + (i + 1) % 3], H[k + i]})) want.insert(want.end(), {H[k + i], H[k + (i + 1) % 3], p});
  }
  return want;
}

// Inserts each of the points P[first..] into the hull of P[0..first) and checks the answer.
void insert_each(const std::vector<Point3>& P, const std::vector<long>& H, std::size_t first) {
  for (std::size_t p = first; p < P.size(); ++p)
    EXPECT_EQ(ex08test::check(P, H, long(p), ex08::insert_point(P, H, long(p)), rule(P, H, long(p))), "") << "point " << p;
}

TEST(Hidden, RandomHulls) {
  std::mt19937_64 g(8);
  for (int round = 0; round < 3; ++round) {
    std::vector<Point3> P;
    for (int k = 0; k < 40; ++k) P.push_back({2 * unit(g) - 1, 2 * unit(g) - 1, 2 * unit(g) - 1});
    for (int k = 0; k < 40; ++k) P.push_back({3 * unit(g) - 1.5, 3 * unit(g) - 1.5, 3 * unit(g) - 1.5});
    insert_each(P, brute_hull(P, 40), 40);
  }
}

// The cube [0, 2]³: its six squares cut into twelve triangles, coplanar in pairs.
TEST(Hidden, CoplanarAndOnTheSurface) {
  std::vector<Point3> P;
  for (int k = 0; k < 8; ++k) P.push_back({double(2 * (k & 1)), double(k & 2), double((k & 4) / 2)});
  const std::vector<Point3> queries = {
      {1, 1, 2},  // the centre of the top square: on two triangles' plane, sees nothing
      {2, 1, 1},  // the centre of a side
      {2, 2, 1},  // inside a vertical edge
      {2, 0, 2},  // a corner again (a duplicate point)
      {1, 1, 1},  // inside
      {1, 1, 3},  // above the top: sees its two triangles
      {3, 1, 2},  // in the top's plane, beyond the side x = 2: sees that side only
      {3, 3, 2},  // in the top's plane, beyond the vertical edge x = y = 2
      {3, 3, 3},  // beyond the corner (2, 2, 2): sees three squares
      {1, -1, 2}, // in the top's plane beyond y = 0
      {4, 1, 1},  // straight out of the side x = 2, seeing the two triangles of it
      {3, 1, 0},  // in the bottom's plane beyond x = 2
  };
  P.insert(P.end(), queries.begin(), queries.end());
  // Corner k = (2 bit0, bit1, bit2 of k, times 2); each square as two triangles, outward.
  const std::vector<long> H = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                               2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
  insert_each(P, H, 8);
}

// Points rounded onto the plane of a face (a + s(b − a) + t(c − a) in doubles, then a few units
// in the last place up or down): orient3d is decided by the rounding, beyond a 3×3 determinant
// evaluated in doubles.
TEST(Hidden, NearlyCoplanar) {
  std::mt19937_64 g(88);
  std::vector<Point3> P;
  for (int k = 0; k < 12; ++k) P.push_back({unit(g), 2 * unit(g), 3 * unit(g)});
  const std::vector<long> H = brute_hull(P, P.size());
  std::vector<Point3> Q = P;
  for (std::size_t f = 0; f + 2 < H.size(); f += 3)
    for (int k = 0; k < 25; ++k) {
      const Point3 &a = P[H[f]], &b = P[H[f + 1]], &c = P[H[f + 2]];
      const double s = unit(g) / 2, t = unit(g) / 2;
      Point3 q = {a.x + s * (b.x - a.x) + t * (c.x - a.x), a.y + s * (b.y - a.y) + t * (c.y - a.y),
                  a.z + s * (b.z - a.z) + t * (c.z - a.z)};
      for (int u = int(g() % 3); u > 0; --u) q.z = std::nextafter(q.z, g() % 2 ? 1e9 : -1e9);
      Q.push_back(q);
    }
  for (std::size_t p = P.size(); p < Q.size(); ++p)
    EXPECT_EQ(ex08test::check(Q, H, long(p), ex08::insert_point(Q, H, long(p)), rule(Q, H, long(p))), "") << "point " << p;
}

}  // namespace
