// The walk (location/walk.hpp) against CGAL's Delaunay_triangulation_2::locate on the same
// front Delaunay triangulation: the face, edge or vertex each query lands on, by its vertices.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "cgal/cgal_oracle.hpp"
#include "t2/location/walk.hpp"
#include "t2/triangulation/delaunay.hpp"

namespace {

using t2::Location;
using t2::Point;
using t2::Subdivision;
using Index = Subdivision::Index;

// The walk's answer in CGAL's terms: kind and sorted vertices.
t2::testing::cgal::DelaunayLocation as_cgal(const Subdivision& S, const Location& l) {
  t2::testing::cgal::DelaunayLocation c;
  const auto vertex = [&](Index k) { return S.org(S.first(l.face) + k % Index(S.size(l.face))); };
  switch (l.kind) {
    case Location::Kind::face: c = {0, {vertex(0), vertex(1), vertex(2)}}; break;
    case Location::Kind::edge: c = {1, {vertex(l.k), vertex(l.k + 1)}}; break;
    case Location::Kind::vertex: c = {2, {vertex(l.k)}}; break;
    case Location::Kind::outside: break;
  }
  std::sort(c.vertices.begin(), c.vertices.end());
  return c;
}

TEST(WalkCgal, AgreesWithCgalLocateOnFrontDelaunayMaps) {
  std::mt19937_64 rng(1414);
  // Integer coordinates in a wide range: general position in practice, and a + b over 2 is
  // exact, so edge midpoints are exactly on their edges for both libraries.
  std::uniform_int_distribution<int> c(-1000000, 1000000);
  for (int round = 0; round < 6; ++round) {
    std::vector<Point> P;
    for (int k = 0; k < 200 + 300 * round; ++k) P.push_back(Point::cartesian(c(rng), c(rng)));
    std::sort(P.begin(), P.end(), [](const Point& a, const Point& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
    P.erase(std::unique(P.begin(), P.end(), [](const Point& a, const Point& b) { return a.x() == b.x() && a.y() == b.y(); }), P.end());
    const t2::Triangulation T = t2::delaunay(P);
    std::vector<std::vector<Index>> F;
    for (const auto& t : T.finite_triangles()) F.push_back({t[0], t[1], t[2]});
    const Subdivision S(P, F);
    std::vector<Point> Q(P.begin(), P.begin() + 50);
    for (Index h = 0; h < S.half_edges(); h += 7) {
      const Point &a = P[S.org(h)], &b = P[S.dest(h)];
      Q.push_back(Point::cartesian((a.x() + b.x()) / 2, (a.y() + b.y()) / 2));
    }
    for (int k = 0; k < 500; ++k) Q.push_back(Point::cartesian(c(rng) * 1.2, c(rng) * 1.2));
    const auto want = t2::testing::cgal::delaunay_locate(P, Q);
    int kinds[4] = {0, 0, 0, 0};
    for (std::size_t i = 0; i < Q.size(); ++i) {
      const auto got = as_cgal(S, t2::walk(S, Q[i], Index(rng() % P.size())));
      ASSERT_EQ(got, want[i]) << "query " << i << ": kind " << got.kind << " against CGAL's " << want[i].kind;
      ++kinds[got.kind];
    }
    EXPECT_GT(kinds[0], 0);
    EXPECT_GT(kinds[1], 0);
    EXPECT_GT(kinds[2], 0);
    EXPECT_GT(kinds[3], 0);
  }
}

}  // namespace
