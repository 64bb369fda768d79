// t2::delaunay on T² input (points on both sides, antipodal pairs, all on Ω) against a brute-force
// O(n⁴) construction with the same exact predicate (in_face_disk), and exact certificates:
// structure and Euler (validate), every face's disk empty, every point a vertex or a duplicate,
// the hull edges (when a hull exists) a convex hull, and the triangles tiling the sphere or the
// hull — the number of faces containing random points, counted with exact orientations, is 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <random>
#include <set>
#include <vector>

#include "delaunay_inputs.hpp"
#include "delaunay_t2_testing.hpp"
#include "testing.hpp"
#include "t2/triangulation/delaunay.hpp"

namespace t2 {
namespace {

using testing::brute_force;
using testing::expect_brute_force;
using testing::expect_t2_delaunay;
using testing::flat;
using testing::proper_faces;
using testing::random_sides;
using testing::Tri;
using testing::triangle_set;
using Index = Triangulation::Index;

// Random points on both sides: with and without a hull (both must occur), with flat faces
// when the input happens to hold none of them.
TEST(DelaunayT2, BothSidesSmallAgainstBruteForce) {
  int with_hull = 0, sphere = 0;
  for (std::uint64_t seed = 1; seed <= 150; ++seed) {
    const auto pts = random_sides(4 + seed % 11, 0.1 + 0.8 * double(seed % 7) / 6, seed);
    SCOPED_TRACE(seed);
    expect_brute_force(pts);
    (delaunay(pts).hull_edges().empty() ? sphere : with_hull)++;
  }
  EXPECT_GT(with_hull, 10);
  EXPECT_GT(sphere, 50);
}

// gen's both-sides: all points in an open hemisphere across Ω, so the hull exists and v∞ stays.
TEST(DelaunayT2, HullAcrossOmegaAgainstBruteForce) {
  int mixed = 0;
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    gen::Options o;
    o.n = 4 + seed % 12;
    o.seed = seed;
    o.back = 0.2 + 0.1 * double(seed % 5);
    const auto pts = gen::points(gen::Kind::both_sides, o);
    SCOPED_TRACE(seed);
    expect_brute_force(pts);
    if (std::any_of(pts.begin(), pts.end(), [](const Point& p) { return p.w() > 0; }) &&
        std::any_of(pts.begin(), pts.end(), [](const Point& p) { return p.w() < 0; })) {
      EXPECT_FALSE(delaunay(pts).hull_edges().empty());
      ++mixed;
    }
  }
  EXPECT_GT(mixed, 50);
}

// The certificates cost O(n²) exact tests: 500 points here, 2000 under the `long` label.
TEST(DelaunayT2, LargeBothSides) {
  const std::size_t n = 500 * static_cast<std::size_t>(testing::scale());
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    expect_t2_delaunay(delaunay(random_sides(n, 0.3 * double(seed), seed)), 100);
    gen::Options o;
    o.n = n;
    o.seed = seed;
    expect_t2_delaunay(delaunay(gen::points(gen::Kind::both_sides, o)), 100);
  }
}

// No hull: the triangles cover the whole sphere, v∞ is gone, Euler with n vertices: 2n − 4.
TEST(DelaunayT2, SphereWithoutHull) {
  const std::vector<Point> pts = {Point::cartesian(0, 0), Point::cartesian(1, 0), Point::cartesian(0, 1),
                                  Point(-1, 0.2, 0.3), Point(-1, -0.9, 0.1), Point(-1, 0.3, -0.8)};
  const Triangulation tr = delaunay(pts);
  expect_t2_delaunay(tr);
  EXPECT_TRUE(tr.hull_edges().empty());
  EXPECT_EQ(tr.size(), 2 * pts.size() - 4);
  EXPECT_EQ(proper_faces(tr), brute_force(pts));
}

// The seed's figure 5.18: the antipode of a hull vertex v. The two faces beside the segment
// v ¬v are flat (orient 0), and that segment crosses Ω in v's normal cone.
TEST(DelaunayT2, AntipodeOfHullVertex) {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    auto pts = testing::gen_points(gen::Kind::uniform, 5 + seed % 15, seed);
    const Triangulation front = delaunay(pts);
    const Index v = front.hull_edges()[seed % front.hull_edges().size()].first;
    pts.push_back(antipode(pts[v]));
    const Triangulation tr = delaunay(pts);
    SCOPED_TRACE(seed);
    expect_t2_delaunay(tr);
    EXPECT_TRUE(tr.hull_edges().empty());
    int flats = 0;
    for (const Tri& t : tr.finite_triangles())
      if (flat(pts[t[0]], pts[t[1]], pts[t[2]])) {
        ++flats;
        EXPECT_TRUE(std::count(t.begin(), t.end(), v) == 1 && std::count(t.begin(), t.end(), Index(pts.size() - 1)) == 1);
      }
    EXPECT_EQ(flats, 2);
    EXPECT_EQ(proper_faces(tr), brute_force(pts));
    // A later point behind, near the antipode: still a valid triangulation (figures 5.19-5.20).
    pts.push_back(Point(-1, -pts[v].x() / pts[v].w() * 1.5, -pts[v].y() / pts[v].w() * 1.5 - 0.25));
    expect_t2_delaunay(delaunay(pts));
  }
}

TEST(DelaunayT2, GenAntipodal) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    gen::Options o;
    o.n = seed == 1 ? 12 : 1000;
    o.seed = seed;
    const auto pts = gen::points(gen::Kind::antipodal, o);
    expect_t2_delaunay(delaunay(pts), 100);
    if (pts.size() <= 20) {
      EXPECT_EQ(proper_faces(delaunay(pts)), brute_force(pts));
    }
  }
}

// Behind only: the mirror of the front triangulation (each triangle reversed), with v∞.
TEST(DelaunayT2, BackOnlyIsTheMirror) {
  const auto front = testing::gen_points(gen::Kind::uniform, 500, 3);
  std::vector<Point> back;
  for (const Point& p : front) back.push_back(antipode(p));
  const Triangulation tr = delaunay(back);
  expect_t2_delaunay(tr);
  std::vector<Tri> mirrored;
  for (const Tri& t : delaunay(front).finite_triangles()) mirrored.push_back({t[0], t[2], t[1]});
  std::sort(mirrored.begin(), mirrored.end());
  EXPECT_EQ(triangle_set(tr), mirrored);
}

TEST(DelaunayT2, IndependentOfOrderAndDuplicatesMerged) {
  auto pts = random_sides(300, 0.4, 5);
  for (std::size_t k = 0; k < 40; ++k) pts.push_back(Point(2 * pts[k].w(), 2 * pts[k].x(), 2 * pts[k].y()));
  std::vector<Index> perm(pts.size());
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), std::mt19937_64(6));
  std::vector<Point> shuffled;
  for (Index k : perm) shuffled.push_back(pts[k]);
  const Triangulation a = delaunay(pts), b = delaunay(shuffled);
  expect_t2_delaunay(a, 50);
  expect_t2_delaunay(b, 50);
  EXPECT_EQ(a.duplicates().size(), 40u);
  std::vector<Tri> renamed;
  for (const Tri& t : b.finite_triangles()) renamed.push_back(testing::renamed(t, perm));
  std::sort(renamed.begin(), renamed.end());
  // The kept point of an equal pair may differ with the order: compare up to duplicates.
  std::vector<Index> canon(pts.size());
  std::iota(canon.begin(), canon.end(), 0);
  for (auto [d, k] : a.duplicates()) canon[d] = k;
  for (Tri& t : renamed) t = testing::renamed(t, canon);
  std::sort(renamed.begin(), renamed.end());
  EXPECT_EQ(triangle_set(a), renamed);
}

// All points on Ω lie on one line of T²: no triangle (dimension 1), duplicates merged.
TEST(DelaunayT2, AllOnOmegaIsCollinear) {
  std::vector<Point> pts;
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 50; ++k) pts.push_back(Point::at_infinity(u(rng), u(rng)));
  pts.push_back(Point(0, 4 * pts[4].x(), 4 * pts[4].y()));  // exact: a power of two
  pts.push_back(antipode(pts[7]));  // a different point
  const Triangulation tr = delaunay(pts);
  EXPECT_EQ(tr.dimension(), 1);
  EXPECT_TRUE(tr.finite_triangles().empty());
  ASSERT_EQ(tr.duplicates().size(), 1u);
  EXPECT_EQ(tr.duplicates()[0], (std::pair<Index, Index>(50, 4)));
  const Triangulation one = delaunay(std::vector<Point>{Point::at_infinity(1, 2), Point::at_infinity(2, 4)});
  EXPECT_EQ(one.dimension(), 0);
  // A front point, its antipode and a point between on their line: collinear too.
  const std::vector<Point> line = {Point::cartesian(1, 1), Point(-1, -1, -1), Point::at_infinity(1, 1),
                                   Point::cartesian(2, 2)};
  EXPECT_EQ(delaunay(line).dimension(), 1);
}

}  // namespace
}  // namespace t2
