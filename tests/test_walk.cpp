// The walk of Algorithm 15 (location/walk.hpp) against the brute-force oracle (every face tested
// with point_in_polygon.hpp's locate): Delaunay maps of front points, random maps of the whole
// sphere whose faces cross Ω and are not convex, maps with holes in the complement, and queries
// exactly on vertices and edges, on Ω and on the back. The map checks (subdivision.hpp) too.
#include <gtest/gtest.h>

#include <array>
#include <optional>
#include <random>
#include <set>
#include <vector>

#include "t2/kernel/orient.hpp"
#include "t2/location/walk.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "t2/triangulation/triangulate.hpp"

namespace {

using t2::Location;
using t2::Point;
using t2::Subdivision;
using Index = Subdivision::Index;
using Faces = std::vector<std::vector<Index>>;

// The octahedron ±u, ±v, ±t of three independent integer vectors: eight triangles covering T²,
// four of them crossing Ω; each turned counter-clockwise (orient > 0: the small triangle).
void octahedron(std::vector<Point>& P, Faces& F) {
  const std::array<std::array<double, 3>, 3> b{{{3, 1, -1}, {1, -2, 2}, {-1, 2, 3}}};
  for (const auto& v : b) {
    P.emplace_back(v[0], v[1], v[2]);
    P.emplace_back(-v[0], -v[1], -v[2]);
  }
  for (Index s = 0; s < 8; ++s) {
    std::vector<Index> f{(s & 1), Index(2 + ((s >> 1) & 1)), Index(4 + ((s >> 2) & 1))};
    if (t2::orient(P[f[0]], P[f[1]], P[f[2]]) < 0) std::swap(f[1], f[2]);
    F.push_back(f);
  }
}

// Splits random triangles at a point αa + βb + γc (small positive integers: exact, strictly
// inside), then merges random pairs of neighbouring triangles into quadrilaterals, convex or
// not, as long as the result is simple, and finally drops `holes` faces (the complement).
Subdivision random_map(std::mt19937_64& rng, int splits, int merges, int holes) {
  std::vector<Point> P;
  Faces F;
  octahedron(P, F);
  std::uniform_int_distribution<int> wt(1, 3);
  for (int s = 0; s < splits; ++s) {
    const std::size_t t = rng() % F.size();
    const auto f = F[t];
    const Point &a = P[f[0]], &b = P[f[1]], &c = P[f[2]];
    const double x = wt(rng), y = wt(rng), z = wt(rng);
    P.emplace_back(x * a.w() + y * b.w() + z * c.w(), x * a.x() + y * b.x() + z * c.x(),
                   x * a.y() + y * b.y() + z * c.y());
    const Index n = Index(P.size() - 1);
    F[t] = {f[0], f[1], n};
    F.push_back({f[1], f[2], n});
    F.push_back({f[2], f[0], n});
  }
  for (int m = 0; m < merges && F.size() > 2; ++m) {
    const std::size_t t = rng() % F.size();
    if (F[t].size() != 3) continue;
    for (std::size_t u = 0; u < F.size(); ++u) {
      if (u == t || F[u].size() != 3) continue;
      // a shared edge a -> b in t is b -> a in u
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          if (F[t][i] == F[u][(j + 1) % 3] && F[t][(i + 1) % 3] == F[u][j]) {
            const std::vector<Index> q{F[t][(i + 1) % 3], F[t][(i + 2) % 3], F[t][i], F[u][(j + 2) % 3]};
            t2::Polygon poly;
            for (Index v : q) poly.push_back(P[v]);
            if (!t2::is_simple(poly)) continue;
            F[t] = q;
            F.erase(F.begin() + long(u));
            goto merged;
          }
    }
  merged:;
  }
  for (int h = 0; h < holes && F.size() > 1; ++h) F.erase(F.begin() + long(rng() % F.size()));
  return Subdivision(P, F);
}

// Queries: every vertex, a point inside every edge (a + b, exact for these small integers),
// random points of the front, the back and Ω.
std::vector<Point> queries(const Subdivision& S, std::mt19937_64& rng, int random) {
  std::vector<Point> Q = S.points();
  for (Index h = 0; h < S.half_edges(); ++h) {
    const Point &a = S.points()[S.org(h)], &b = S.points()[S.dest(h)];
    Q.emplace_back(a.w() + b.w(), a.x() + b.x(), a.y() + b.y());
  }
  std::uniform_int_distribution<int> c(-9, 9);
  for (int k = 0; k < random; ++k) {
    const int w = c(rng) / 3, x = c(rng), y = c(rng);  // w in −3..3: a seventh on Ω
    if (w != 0 || x != 0 || y != 0) Q.emplace_back(w, x, y);
  }
  return Q;
}

// Each query walked from a random vertex, and from the last query found strictly inside a face
// (the second overload of walk, as a run of queries uses it).
void expect_walk_matches_brute(const Subdivision& S, const std::vector<Point>& Q, std::mt19937_64& rng,
                               std::set<Location::Kind>* seen = nullptr) {
  std::optional<std::pair<Point, Index>> inside;
  for (const Point& p : Q) {
    const Location want = t2::locate_brute(S, p);
    const Index q = Index(rng() % S.points().size());
    const Location got = t2::walk(S, p, q);
    ASSERT_EQ(to_string(got), to_string(want)) << "p = " << p.w() << " " << p.x() << " " << p.y() << " from " << q;
    if (inside) {
      const auto& [from, face] = *inside;
      ASSERT_EQ(to_string(t2::walk(S, p, from, face)), to_string(want))
          << "p = " << p.w() << " " << p.x() << " " << p.y() << " from " << from.w() << " " << from.x() << " " << from.y();
    }
    if (want.kind == Location::Kind::face) inside = {p, want.face};
    if (seen) seen->insert(got.kind);
  }
}

TEST(Walk, MatchesBruteForceOnRandomMapsOfTheWholeSphere) {
  std::mt19937_64 rng(14);
  std::set<Location::Kind> seen;
  for (int round = 0; round < 40; ++round) {
    const Subdivision S = random_map(rng, 5 + round, round % 7 * 2, round % 3);
    expect_walk_matches_brute(S, queries(S, rng, 60), rng, &seen);
  }
  EXPECT_EQ(seen.size(), 4u);  // faces, edges, vertices and the complement were all met
}

TEST(Walk, MatchesBruteForceOnFrontDelaunayMaps) {
  std::mt19937_64 rng(27);
  std::uniform_int_distribution<int> c(-40, 40);
  for (int round = 0; round < 10; ++round) {
    std::set<std::pair<int, int>> xy;
    while (xy.size() < 50u + 20u * round) xy.insert({c(rng), c(rng)});
    std::vector<Point> P;
    for (auto [x, y] : xy) P.push_back(Point::cartesian(x, y));
    const t2::Triangulation T = t2::delaunay(P);
    Faces F;
    for (const auto& t : T.finite_triangles()) F.push_back({t[0], t[1], t[2]});
    const Subdivision S(P, F);
    expect_walk_matches_brute(S, queries(S, rng, 200), rng);
  }
}

// The visibility walk that `walk(S, p, from, face)` tries first (walk.cpp) must give the same
// answers where it may circle or give up: Delaunay triangulations of grid points (four points on
// a circle everywhere), triangulations that are not Delaunay (the sweep of chapter 09: long thin
// fans), both with queries on vertices, edges, the back and Ω. And `convex_triangle` is Δ > 0.
TEST(Walk, FromAFaceMatchesBruteForceOnCocircularAndNonDelaunayTriangulations) {
  std::mt19937_64 rng(31);
  for (int round = 0; round < 8; ++round) {
    std::vector<Point> P;
    const int m = 4 + round;
    for (int x = 0; x < m; ++x)
      for (int y = 0; y < m + round % 3; ++y) P.push_back(Point::cartesian(x - m / 2, y - m / 2));
    std::uniform_int_distribution<int> c(-9, 9);
    std::set<std::pair<int, int>> xy;
    while (xy.size() < 40u) xy.insert({c(rng), c(rng)});
    std::vector<Point> R;
    for (auto [x, y] : xy) R.push_back(Point::cartesian(x, y));
    const std::pair<const std::vector<Point>*, t2::Triangulation> maps[] = {{&P, t2::delaunay(P)},
                                                                          {&R, t2::triangulate(R)}};
    for (const auto& [points, T] : maps) {
      Faces F;
      for (const auto& t : T.finite_triangles()) F.push_back({t[0], t[1], t[2]});
      const Subdivision S(*points, F);
      for (Index f = 0; f < S.faces(); ++f) {
        const Index h = S.first(f);
        EXPECT_EQ(S.convex_triangle(f), t2::orient(S.points()[S.org(h)], S.points()[S.org(h + 1)],
                                                   S.points()[S.org(h + 2)]) == t2::POSITIVE);
      }
      expect_walk_matches_brute(S, queries(S, rng, 150), rng);
    }
  }
}

TEST(Walk, RecordsTheRegionsItCrosses) {
  std::mt19937_64 rng(5);
  const Subdivision S = random_map(rng, 30, 0, 4);
  for (Index f = 0; f < S.faces(); ++f) {
    // The sum of the three vertices of a triangle is inside it.
    double w = 0, x = 0, y = 0;
    for (Index h = S.first(f); h < S.first(f) + 3; ++h) {
      const Point& a = S.points()[S.org(h)];
      w += a.w(), x += a.x(), y += a.y();
    }
    std::vector<Index> crossed;
    const Location l = t2::walk(S, Point(w, x, y), Index(rng() % S.points().size()), &crossed);
    EXPECT_EQ(to_string(l), "face " + std::to_string(f));
    ASSERT_FALSE(crossed.empty());
    EXPECT_EQ(crossed.back(), f);
    EXPECT_LE(crossed.size(), S.half_edges() + S.points().size() + 1);
  }
}

TEST(Subdivision, SharesEdgesAndRejectsOverlaps) {
  std::vector<Point> P;
  Faces F;
  octahedron(P, F);
  const Subdivision S(P, F);
  EXPECT_TRUE(S.boundary().empty());  // the octahedron covers T²
  for (Index h = 0; h < S.half_edges(); ++h) {
    ASSERT_NE(S.twin(h), Subdivision::none);
    EXPECT_EQ(S.twin(S.twin(h)), h);
    EXPECT_EQ(S.org(S.twin(h)), S.dest(h));
  }
  for (Index v = 0; v < P.size(); ++v) EXPECT_EQ(S.corners(v).size(), 4u);
  Faces twice = F;
  twice.push_back(F[0]);  // the same face again: its edges twice in one direction
  EXPECT_THROW(Subdivision(P, twice), t2::MapError);
  Faces clockwise = F;
  std::swap(clockwise[3][1], clockwise[3][2]);
  EXPECT_THROW(Subdivision(P, clockwise), t2::MapError);
  // Two triangles at the vertex 0 whose corners overlap, with no edge in common.
  const std::vector<Point> Q{Point::cartesian(0, 0), Point::cartesian(4, 0), Point::cartesian(0, 4),
                             Point::cartesian(4, 1), Point::cartesian(1, 4)};
  try {
    Subdivision(Q, Faces{{0, 1, 2}, {0, 3, 4}});
    ADD_FAILURE() << "overlap not seen";
  } catch (const t2::MapError& e) {
    EXPECT_EQ(e.face(), 1u);
  }
  EXPECT_NO_THROW(Subdivision(Q, Faces{{0, 1, 3}, {0, 4, 2}}));
}

TEST(Subdivision, MergesEqualPointsOfPolygons) {
  // Two front squares sharing an edge, the second written with scaled coordinates.
  const std::vector<t2::Polygon> faces{
      {Point(1, 0, 0), Point(1, 1, 0), Point(1, 1, 1), Point(1, 0, 1)},
      {Point(2, 2, 0), Point(2, 4, 0), Point(2, 4, 2), Point(2, 2, 2)}};
  const Subdivision S(faces);
  EXPECT_EQ(S.points().size(), 6u);
  EXPECT_EQ(S.boundary().size(), 6u);
  EXPECT_EQ(to_string(t2::walk(S, Point::cartesian(1, 0.5), 0)), "edge 0 1");
  EXPECT_EQ(to_string(t2::walk(S, Point(3, 3, 3), 0)), "vertex 0 2");
  EXPECT_EQ(to_string(t2::walk(S, Point::cartesian(1.5, 0.5), 0)), "face 1");
  EXPECT_EQ(to_string(t2::walk(S, Point(-1, 0.5, 0.5), 0)), "outside");   // the back
  EXPECT_EQ(to_string(t2::walk(S, Point(0, 1, 0), 0)), "outside");       // Ω
}

}  // namespace

namespace {

// A hand map (as in test_locate_cli.cpp): a front triangle, the region beyond its long edge up
// to Ω, and a triangle from the front through Ω to the back; the walk from every vertex.
TEST(Walk, HandMapAcrossOmegaFromEveryVertex) {
  const std::vector<t2::Polygon> faces{
      {Point::cartesian(0, 0), Point::cartesian(4, 0), Point::cartesian(0, 4)},
      {Point::cartesian(0, 4), Point::cartesian(4, 0), Point(0, 1, 0), Point(0, 1, 1)},
      {Point(1, -1, -1), Point(-1, 1, 2), Point(-1, -1, 1)}};
  const Subdivision S(faces);
  std::mt19937_64 rng(3);
  const std::vector<Point> Q = queries(S, rng, 300);
  for (Index q = 0; q < S.points().size(); ++q)
    for (const Point& p : Q) {
      const Location want = t2::locate_brute(S, p);
      ASSERT_EQ(to_string(t2::walk(S, p, q)), to_string(want))
          << "p = " << p.w() << " " << p.x() << " " << p.y() << " from " << q;
    }
}

}  // namespace
