// The 3-D hull: every algorithm against CGAL's convex_hull_3 (the oracle, tests only) on random
// cube and sphere input, against each other on degenerate input (grids, duplicates, points on
// facets and edges), exact certificates (a closed convex surface with every point inside), the
// undefined cases, and invariance under permutation.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "t2/gen/generate.hpp"
#include "t2/hull3d.hpp"
#include "cgal/cgal_oracle.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

const Hull3dAlgorithm kAll[] = {Hull3dAlgorithm::incremental, Hull3dAlgorithm::quickhull, Hull3dAlgorithm::gift_wrap};

std::vector<Point3> generated(gen::Kind k, std::size_t n, std::uint64_t seed) {
  gen::Options o;
  o.n = n;
  o.seed = seed;
  std::vector<Point3> P;
  for (const auto& [x, y, z] : gen::points3(k, o)) P.push_back({x, y, z});
  return P;
}

// CGAL's hull of distinct points as sorted triangles of indices (rotated smallest first).
std::vector<Triangle3> cgal_hull(const std::vector<Point3>& P) { return testing::cgal::hull_3(P); }

// The certificates of a hull: closed oriented surface, Euler, convex with strict vertices,
// every input point inside or on it.
void certify(const std::vector<Point3>& P, const Facets& facets) {
  const Polyhedron H = polyhedron_of(P, facets);
  EXPECT_EQ(validate_surface(H), "");
  EXPECT_EQ(euler_characteristic(H), 2);
  EXPECT_EQ(validate_convex(H), "");
  EXPECT_TRUE(contains_all(H, P));
}

TEST(Hull3d, EqualsCgalOnRandomInput) {
  for (gen::Kind k : {gen::Kind::cube, gen::Kind::sphere})
    for (std::uint64_t seed = 1; seed <= 3u * static_cast<unsigned>(testing::scale()); ++seed) {
      const auto P = generated(k, k == gen::Kind::sphere ? 600 : 3000, seed);
      const auto ref = cgal_hull(P);
      for (Hull3dAlgorithm a : kAll) {
        SCOPED_TRACE(std::string(name(a)) + " " + std::string(gen::name(k)) + " seed " + std::to_string(seed));
        const Facets f = hull_facets_3d(P, a);
        EXPECT_EQ(fan_triangles(f), ref);
        certify(P, f);
      }
    }
}

TEST(Hull3d, LargeInputAgreesWithCgal) {
  const auto P = generated(gen::Kind::cube, 100000, 7);
  EXPECT_EQ(convex_hull_3d(P, Hull3dAlgorithm::quickhull), cgal_hull(P));
  EXPECT_EQ(convex_hull_3d(P, Hull3dAlgorithm::incremental), cgal_hull(P));
}

// The m×m×m integer grid, shuffled: the hull is the cube of its 8 corners, 6 square facets.
TEST(Hull3d, GridIsACube) {
  std::vector<Point3> P;
  const int m = 5;
  for (int x = 0; x < m; ++x)
    for (int y = 0; y < m; ++y)
      for (int z = 0; z < m; ++z) P.push_back({double(x), double(y), double(z)});
  std::mt19937 rng(3);
  std::shuffle(P.begin(), P.end(), rng);
  for (Hull3dAlgorithm a : kAll) {
    SCOPED_TRACE(name(a));
    const Facets f = hull_facets_3d(P, a);
    ASSERT_EQ(f.size(), 6u);
    for (const auto& g : f) {
      EXPECT_EQ(g.size(), 4u);
      for (std::uint32_t v : g)
        for (double c : {P[v].x, P[v].y, P[v].z}) EXPECT_TRUE(c == 0 || c == m - 1);
    }
    certify(P, f);
    EXPECT_EQ(convex_hull_3d(P, a).size(), 12u);
  }
}

// Coplanar-heavy input: points on the faces and edges of a box and inside, with duplicates.
std::vector<Point3> degenerate_box(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> d(0, 4);
  std::vector<Point3> P;
  for (int i = 0; i < 400; ++i) {
    double c[3] = {double(d(rng)), double(d(rng)), double(d(rng)) / 2};
    const int pin = d(rng) % 3;  // push one coordinate to a face of [0, 4]²×[0, 2]
    if (d(rng) < 2) c[pin] = pin == 2 ? 2.0 * (d(rng) % 2) : 4.0 * (d(rng) % 2);
    P.push_back({c[0], c[1], c[2]});
  }
  for (int i = 0; i < 50; ++i) P.push_back(P[static_cast<std::size_t>(d(rng)) * 7]);  // duplicates
  return P;
}

TEST(Hull3d, AlgorithmsAgreeOnDegenerateInput) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const auto P = degenerate_box(seed);
    const Facets ref = hull_facets_3d(P, Hull3dAlgorithm::gift_wrap);
    certify(P, ref);
    for (Hull3dAlgorithm a : kAll) EXPECT_EQ(hull_facets_3d(P, a), ref) << name(a) << " seed " << seed;
    // CGAL's vertices are the strict extreme points too (its triangulation of a facet may differ)
    std::vector<std::uint32_t> ours, theirs;
    for (const auto& g : ref) ours.insert(ours.end(), g.begin(), g.end());
    for (const auto& t : cgal_hull(P)) theirs.insert(theirs.end(), t.begin(), t.end());
    for (auto* v : {&ours, &theirs}) {
      std::sort(v->begin(), v->end());
      v->erase(std::unique(v->begin(), v->end()), v->end());
    }
    // CGAL keeps some equal point: compare coordinates
    auto coords = [&](const std::vector<std::uint32_t>& v) {
      std::vector<std::array<double, 3>> c;
      for (auto i : v) c.push_back({P[i].x, P[i].y, P[i].z});
      std::sort(c.begin(), c.end());
      return c;
    };
    EXPECT_EQ(coords(ours), coords(theirs));
  }
}

TEST(Hull3d, DuplicatesKeepTheSmallestIndex) {
  std::vector<Point3> P = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int i = 0; i < 4; ++i) P.push_back(P[static_cast<std::size_t>(i)]);  // 4..7 equal 0..3
  P.push_back({0.25, 0.25, 0.25});                                           // inside
  P.push_back({0.5, 0.5, 0});                                                // on an edge
  for (Hull3dAlgorithm a : kAll) {
    const auto T = convex_hull_3d(P, a);
    const std::vector<Triangle3> want = {{0, 1, 3}, {0, 2, 1}, {0, 3, 2}, {1, 2, 3}};
    EXPECT_EQ(T, want) << name(a);
  }
}

TEST(Hull3d, PermutationInvariant) {
  const auto P = degenerate_box(9);
  std::vector<std::uint32_t> perm(P.size());
  std::iota(perm.begin(), perm.end(), 0u);
  std::mt19937 rng(5);
  std::shuffle(perm.begin(), perm.end(), rng);
  std::vector<Point3> Q(P.size());
  for (std::size_t i = 0; i < P.size(); ++i) Q[perm[i]] = P[i];  // point i of P is point perm[i] of Q
  for (Hull3dAlgorithm a : kAll) {
    // the same polyhedron: compare facets as coordinate cycles
    auto shape = [](const std::vector<Point3>& X, Facets F) {
      std::vector<std::vector<std::array<double, 3>>> s;
      for (auto& f : F) {
        std::vector<std::array<double, 3>> c;
        for (auto v : f) c.push_back({X[v].x, X[v].y, X[v].z});
        std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
        s.push_back(c);
      }
      std::sort(s.begin(), s.end());
      return s;
    };
    EXPECT_EQ(shape(P, hull_facets_3d(P, a)), shape(Q, hull_facets_3d(Q, a))) << name(a);
  }
}

TEST(Hull3d, UndefinedWhenThePointsDoNotSpanSpace) {
  const std::vector<std::vector<Point3>> cases = {
      {},
      {{1, 2, 3}},
      {{1, 2, 3}, {1, 2, 3}, {1, 2, 3}, {1, 2, 3}},
      {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {-3, -3, -3}, {0.5, 0.5, 0.5}},
      {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.1, 0.7, 0}},
      {{0, 0, 1}, {1, 0, 2}, {0, 1, 3}, {1, 1, 4}},  // on the plane z = 1 + x + 2y
  };
  const char* why[] = {"no point", "1 points are equal", "are equal", "collinear", "coplanar", "coplanar"};
  for (std::size_t i = 0; i < cases.size(); ++i)
    for (Hull3dAlgorithm a : kAll) {
      try {
        hull_facets_3d(cases[i], a);
        ADD_FAILURE() << "case " << i << " " << name(a) << " has a hull";
      } catch (const Undefined& e) {
        EXPECT_NE(std::string(e.what()).find(why[i]), std::string::npos) << e.what();
      }
    }
  const std::vector<Point3> bad = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, std::nan("")}};
  for (Hull3dAlgorithm a : kAll) EXPECT_THROW(hull_facets_3d(bad, a), BadInput);
}

// Points nearly coplanar with a facet (one unit in the last place off it): only exact
// predicates tell which side; the certificates are exact.
TEST(Hull3d, NearlyCoplanarPoints) {
  std::vector<Point3> P = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  for (int i = 0; i < 200; ++i) {  // on or a hair off the plane x + y + z = 1... and z = 0
    const double x = u(rng), y = u(rng) * (1 - x);
    const double z = 1 - x - y;
    P.push_back({x, y, (i % 3 == 0) ? std::nextafter(z, 2.0) : z});
    P.push_back({x, y, (i % 2) ? std::nextafter(0.0, 1.0) : -0.0});
  }
  const Facets ref = hull_facets_3d(P, Hull3dAlgorithm::gift_wrap);
  certify(P, ref);
  for (Hull3dAlgorithm a : kAll) EXPECT_EQ(hull_facets_3d(P, a), ref) << name(a);
}

}  // namespace
}  // namespace t2
