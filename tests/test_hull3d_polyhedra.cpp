// Polyhedra: the Platonic solids (counts, Euler, exact convexity, regular combinatorics), the
// polar dual, the winged-edge structure against the seed's cube table, and the lifting map
// against t2::delaunay.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>

#include "delaunay_certificates.hpp"
#include "t2/hull3d.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

struct Expected {
  Platonic s;
  std::size_t V, E, F, p, r;  // p vertices per face, r faces per vertex
};

TEST(Platonic, CountsEulerAndConvexity) {
  const Expected all[] = {{Platonic::tetrahedron, 4, 6, 4, 3, 3}, {Platonic::cube, 8, 12, 6, 4, 3},
                          {Platonic::octahedron, 6, 12, 8, 3, 4}, {Platonic::dodecahedron, 20, 30, 12, 5, 3},
                          {Platonic::icosahedron, 12, 30, 20, 3, 5}};
  for (const Expected& x : all) {
    SCOPED_TRACE(name(x.s));
    const Polyhedron P = platonic(x.s);
    EXPECT_EQ(P.vertices.size(), x.V);
    EXPECT_EQ(edges(P).size(), x.E);
    EXPECT_EQ(P.faces.size(), x.F);
    EXPECT_EQ(euler_characteristic(P), 2);
    EXPECT_EQ(validate_surface(P), "");
    EXPECT_EQ(validate_convex(P), "");
    for (const auto& f : P.faces) EXPECT_EQ(f.size(), x.p);
    const WingedEdge W = WingedEdge::from(P);
    EXPECT_EQ(W.validate(), "");
    for (std::uint32_t v = 0; v < P.vertices.size(); ++v) EXPECT_EQ(W.vertex_faces(v).size(), x.r);
    for (const Point3& q : P.vertices)  // integer coordinates: exact doubles
      for (double c : {q.x, q.y, q.z}) EXPECT_EQ(c, std::trunc(c));
  }
  EXPECT_EQ(all_platonic().size(), 5u);
}

// The polar dual's faces (built from the faces around each vertex) are the hull's facets of
// its vertices: the pentagons are exactly planar and in counter-clockwise order.
TEST(Platonic, PolarDualFacesAreTheHullFacets) {
  for (Platonic s : {Platonic::cube, Platonic::octahedron, Platonic::icosahedron}) {
    const Polyhedron D = polar_dual(platonic(s));
    EXPECT_EQ(validate_surface(D), "") << name(s);
    EXPECT_EQ(validate_convex(D), "") << name(s);
    Facets mine = D.faces;
    canonicalize(mine);
    EXPECT_EQ(mine, hull_facets_3d(D.vertices)) << name(s);
  }
  EXPECT_THROW(polar_dual(Polyhedron{{{1, 1, 1}, {2, 1, 1}, {1, 2, 1}, {1, 1, 2}}, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}}),
               Undefined);  // the origin is outside
}

// Seed 004's cube (figure 9) and its winged-edge table, 0-based: p1..p8 -> 0..7, e1..e12 ->
// 0..11, f1..f6 -> 0..5. Columns: v1 v2 fccw fcw pccw nccw pcw ncw.
const std::uint32_t kSeedEdges[12][8] = {
    {0, 1, 0, 4, 3, 1, 5, 4},  {1, 2, 0, 1, 0, 2, 6, 5},  {2, 3, 0, 5, 1, 3, 7, 6},   {3, 0, 0, 3, 2, 0, 4, 7},
    {0, 4, 4, 3, 0, 8, 11, 3}, {1, 5, 1, 4, 1, 9, 8, 0},  {2, 6, 5, 1, 2, 10, 9, 1},  {3, 7, 3, 5, 3, 11, 10, 2},
    {4, 5, 4, 2, 4, 5, 9, 11}, {5, 6, 1, 2, 5, 6, 10, 8}, {6, 7, 5, 2, 6, 7, 11, 9}, {7, 4, 3, 2, 7, 4, 8, 10}};

WingedEdge seed_cube() {
  WingedEdge W;
  const Point3 p[8] = {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}, {0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}};
  const std::uint32_t av[8] = {0, 1, 2, 3, 8, 9, 10, 11}, af[6] = {0, 1, 9, 11, 0, 7};
  for (int v = 0; v < 8; ++v) W.vertices.push_back({p[v], av[v]});
  for (std::uint32_t a : af) W.faces.push_back({a});
  for (const auto& e : kSeedEdges) W.edges.push_back({e[0], e[1], e[2], e[3], e[4], e[5], e[6], e[7]});
  return W;
}

TEST(WingedEdge, TheSeedCubeTable) {
  const WingedEdge W = seed_cube();
  EXPECT_EQ(W.validate(), "");
  const Polyhedron P = W.to_polyhedron();
  EXPECT_EQ(validate_surface(P), "");
  EXPECT_EQ(validate_convex(P), "");  // exact: every face outward
  EXPECT_EQ(euler_characteristic(P), 2);
  // the faces around p1 are f1, f5, f4 in some rotation
  auto around = W.vertex_faces(0);
  std::sort(around.begin(), around.end());
  EXPECT_EQ(around, (std::vector<std::uint32_t>{0, 3, 4}));
  // from the face list, the same table again (up to the numbering of the edges)
  const WingedEdge R = WingedEdge::from(P);
  EXPECT_EQ(R.validate(), "");
  for (std::uint32_t f = 0; f < 6; ++f) {
    auto a = W.face_vertices(f), b = R.face_vertices(f);
    std::rotate(a.begin(), std::min_element(a.begin(), a.end()), a.end());
    std::rotate(b.begin(), std::min_element(b.begin(), b.end()), b.end());
    EXPECT_EQ(a, b);
  }
}

TEST(WingedEdge, BrokenTablesAreCaught) {
  WingedEdge W = seed_cube();
  std::swap(W.edges[0].pcw, W.edges[0].ncw);  // the wings of e1 crossed
  EXPECT_NE(W.validate(), "");
  W = seed_cube();
  W.vertices[4].av = 0;  // av(p5) = e1, which does not touch p5
  EXPECT_NE(W.validate(), "");
  Polyhedron open = platonic(Platonic::cube);
  open.faces.pop_back();
  EXPECT_NE(validate_surface(open), "");
  EXPECT_THROW(WingedEdge::from(open), BadInput);
}

TEST(Polyhedron, CertificatesCatchWrongFaces) {
  Polyhedron P = platonic(Platonic::cube);
  std::reverse(P.faces[0].begin(), P.faces[0].end());  // inward
  EXPECT_NE(validate_convex(P), "");
  P = platonic(Platonic::cube);
  P.vertices[0].x += 0.5;  // a corner pulled out: its faces are no longer planar
  EXPECT_NE(validate_convex(P), "");
  EXPECT_FALSE(contains_all(platonic(Platonic::octahedron), std::vector<Point3>{{0.5, 0.5, 0.01}}));
  EXPECT_TRUE(contains_all(platonic(Platonic::octahedron), std::vector<Point3>{{0.5, 0.5, 0}}));
}

// Random integer points: x² + y² is exact, so the lower hull of the lifts is the Delaunay
// triangulation, which t2::delaunay computes by flips (an independent algorithm).
TEST(Lifting, LowerHullIsDelaunay) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<int> d(-100000, 100000);
    std::vector<Point> P;
    for (int i = 0; i < 2000; ++i) P.push_back(Point::cartesian(d(rng), d(rng)));
    const auto ours = delaunay_by_lifting(P);
    const auto theirs = testing::triangle_set(delaunay(P));
    EXPECT_EQ(ours.size(), theirs.size());
    EXPECT_TRUE(std::equal(ours.begin(), ours.end(), theirs.begin(), theirs.end(),
                           [](const Triangle3& a, const auto& b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }))
        << "seed " << seed;
  }
}

TEST(Lifting, InexactOrUndefinedLifts) {
  EXPECT_THROW(lift(Point::cartesian(0.1, 0)), Undefined);  // 0.1² is no double
  EXPECT_THROW(lift(Point(2, 1, 1)), Undefined);            // not [1, x, y]
  const Point3 q = lift(Point::cartesian(3, -4));
  EXPECT_EQ(q.z, 25);
  const std::vector<Point> circle = {Point::cartesian(5, 0), Point::cartesian(0, 5), Point::cartesian(-5, 0),
                                     Point::cartesian(3, 4), Point::cartesian(-4, -3)};
  EXPECT_THROW(delaunay_by_lifting(circle), Undefined);  // lifts coplanar
}

}  // namespace
}  // namespace t2
