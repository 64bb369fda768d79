// The Delaunay complex of T² (t2/voronoi/complex.hpp), by exact certificates computed from its
// face list alone: the faces close up into a sphere (each directed edge once, its reverse once,
// V − E + F = 2), every face's disk in T²'s two-sided sense (incircle.hpp) is empty of sites,
// and for front-only sites the faces beyond the hull are exactly the farthest-point Delaunay
// triangles found by brute force (a triangle of sites whose circle holds every site).
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "t2/kernel/error.hpp"
#include "t2/kernel/incircle.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "t2/voronoi/complex.hpp"
#include "voronoi_inputs.hpp"

namespace t2 {
namespace {

using testing::grid_sites;
using testing::scattered_sites;

using Index = Triangulation::Index;
using Face = std::array<Index, 3>;


/// Empty when the faces form a closed oriented surface of genus 0 on the distinct sites.
std::string sphere_error(const DelaunayComplex& dc) {
  std::map<std::pair<Index, Index>, int> count;
  std::set<Index> used;
  for (const Face& t : dc.faces) {
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) return "a face repeats a vertex";
    for (int i = 0; i < 3; ++i) {
      ++count[{t[i], t[(i + 1) % 3]}];
      used.insert(t[i]);
    }
  }
  for (auto [e, c] : count) {
    if (c != 1) return "the edge " + std::to_string(e.first) + "->" + std::to_string(e.second) + " is in " +
                       std::to_string(c) + " faces";
    if (!count.count({e.second, e.first})) return "an edge has no reverse";
  }
  std::set<Index> dropped;
  for (auto [d, k] : dc.duplicates) dropped.insert(d);
  for (Index k = 0; k < dc.points.size(); ++k)
    if (!dropped.count(k) && !used.count(k)) return "site " + std::to_string(k) + " is no vertex";
  const long V = long(used.size()), E = long(count.size()) / 2, F = long(dc.faces.size());
  if (V - E + F != 2) return "V - E + F = " + std::to_string(V - E + F);
  return "";
}

/// Empty when `twins` links each half-edge to the reverse edge of another face (an involution
/// without fixed points), checked against the face list, and `turns` holds each face's
/// orientation when its sites are on one side (else ZERO).
std::string twin_error(const DelaunayComplex& dc) {
  if (dc.twins.size() != 3 * dc.faces.size()) return "twins: " + std::to_string(dc.twins.size()) + " half-edges";
  auto ends = [&](Index h) {
    const Face& t = dc.faces[h / 3];
    return std::make_pair(t[(h + 1) % 3], t[(h + 2) % 3]);
  };
  for (Index h = 0; h < dc.twins.size(); ++h) {
    const Index e = dc.twins[h];
    if (e >= dc.twins.size() || dc.twins[e] != h || e / 3 == h / 3) return "twins: not an involution at " + std::to_string(h);
    const auto [u, v] = ends(h);
    if (ends(e) != std::make_pair(v, u)) return "twins: the half-edge " + std::to_string(h) + " is not reversed";
  }
  if (dc.turns.size() != dc.faces.size()) return "turns: " + std::to_string(dc.turns.size()) + " faces";
  for (std::size_t f = 0; f < dc.faces.size(); ++f) {  // the kind, from the sites by orient
    const Point &a = dc.points[dc.faces[f][0]], &b = dc.points[dc.faces[f][1]], &c = dc.points[dc.faces[f][2]];
    const bool one_side = a.w() != 0 && sign_of(a.w()) == sign_of(b.w()) && sign_of(b.w()) == sign_of(c.w());
    if (dc.turns[f] != (one_side ? orient(a, b, c) : ZERO)) return "turns: face " + std::to_string(f);
  }
  return "";
}

/// Empty when every face of three sites on one side, not collinear, has no site strictly inside
/// its disk (in_circle: for a clockwise face the disk is the complement of the circle's).
std::string disk_error(const DelaunayComplex& dc) {
  const auto& p = dc.points;
  for (const Face& t : dc.faces) {
    const Point &a = p[t[0]], &b = p[t[1]], &c = p[t[2]];
    if (!(sign_of(a.w()) == sign_of(b.w()) && sign_of(b.w()) == sign_of(c.w()) && a.w() != 0)) continue;
    if (orient(a, b, c) == ZERO) continue;
    for (const Point& d : p)
      if (in_circle(a, b, c, d) == POSITIVE)
        return "a site is inside the disk of " + to_string(a) + ", " + to_string(b) + ", " + to_string(c);
  }
  return "";
}

/// Checks the complex of `pts`; returns false when it is undefined, which it must be exactly
/// when delaunay_t2.hpp rejects the input too (a tie on Ω).
bool check(const std::vector<Point>& pts, const char* what) {
  DelaunayComplex dc;
  try {
    dc = delaunay_complex(pts);
  } catch (const Undefined&) {
    EXPECT_THROW(delaunay(pts), Undefined) << what;
    return false;
  }
  EXPECT_EQ(sphere_error(dc), "") << what;
  EXPECT_EQ(twin_error(dc), "") << what;
  EXPECT_EQ(disk_error(dc), "") << what;
  return true;
}

TEST(DelaunayComplex, FrontGridsCloseIntoASphereWithEmptyDisks) {
  std::mt19937 rng(1);
  for (int r = 0; r < 60; ++r) check(grid_sites(3 + r % 25, 2 + r % 5, 1, rng), "front grid");
}

TEST(DelaunayComplex, BackAndMixedInput) {
  std::mt19937 rng(2);
  int defined = 0;
  for (int r = 0; r < 40; ++r) {
    check(grid_sites(3 + r % 20, 3, -1, rng), "back grid");
    auto f = grid_sites(2 + r % 9, 4, 1, rng), b = grid_sites(2 + r % 7, 4, -1, rng);
    f.insert(f.end(), b.begin(), b.end());
    defined += check(f, "both sides");
    auto s = scattered_sites(5 + r % 20, 1, rng), t = scattered_sites(1 + r % 4, -1, rng);
    for (auto& q : t) q = Point(q.w(), q.x() * 0.01 + 3, q.y() * 0.01);  // a hull: back sites near one point
    s.insert(s.end(), t.begin(), t.end());
    EXPECT_TRUE(check(s, "both sides with a hull"));
  }
  EXPECT_GT(defined, 20);  // ties on Ω are rare enough on these grids
}

TEST(DelaunayComplex, AntipodalPairsAndSitesOnOmega) {
  std::mt19937 rng(3);
  int defined = 0;
  for (int r = 0; r < 30; ++r) {
    auto f = grid_sites(3 + r % 8, 3, 1, rng);
    const std::size_t n = f.size();
    for (std::size_t k = 0; k < n; k += 2) f.push_back(antipode(f[k]));
    defined += check(f, "antipodal pairs");
    auto g = grid_sites(3 + r % 8, 3, 1, rng), h = grid_sites(3 + r % 8, 3, -1, rng);
    g.insert(g.end(), h.begin(), h.end());
    g.push_back(Point::at_infinity(1, 2));
    g.push_back(Point::at_infinity(-3, 1));
    defined += check(g, "both sides and Omega");
  }
  EXPECT_GT(defined, 30);
}

TEST(DelaunayComplex, CollinearFewAndDuplicateSites) {
  std::vector<Point> line;
  for (int k = 0; k < 6; ++k) line.push_back(Point::cartesian(k, 2 * k + 1));
  line.push_back(line[2]);
  const DelaunayComplex dc = delaunay_complex(line);
  EXPECT_EQ(sphere_error(dc), "");
  EXPECT_EQ(twin_error(dc), "");
  EXPECT_EQ(dc.faces.size(), 2u * (6 - 2));  // two flat hexagons, cut into four triangles each
  for (const Face& t : dc.faces) EXPECT_EQ(orient(line[t[0]], line[t[1]], line[t[2]]), ZERO);
  EXPECT_EQ(delaunay_complex(std::vector<Point>{}).dimension, -1);
  const std::vector<Point> one{Point::cartesian(1, 1), Point::cartesian(1, 1)};
  EXPECT_EQ(delaunay_complex(one).dimension, 0);
  const std::vector<Point> two{Point::cartesian(1, 1), Point(-1, 0, 0), Point::cartesian(1, 1)};
  const DelaunayComplex d2 = delaunay_complex(two);
  EXPECT_EQ(d2.dimension, 1);
  EXPECT_TRUE(d2.faces.empty());
  EXPECT_EQ(d2.duplicates.size(), 1u);
  const std::vector<Point> three{Point::cartesian(0, 0), Point::cartesian(1, 0), Point::cartesian(0, 1)};
  const DelaunayComplex d3 = delaunay_complex(three);
  EXPECT_EQ(sphere_error(d3), "");
  EXPECT_EQ(d3.faces.size(), 2u);  // the triangle and its back
}

TEST(DelaunayComplex, AnEmptySideWithTwoSitesOnOmegaIsUndefined) {
  const std::vector<Point> p{Point::cartesian(0, 0), Point::cartesian(1, 0), Point::cartesian(0, 1),
                             Point::at_infinity(1, 0), Point::at_infinity(0, 1)};
  EXPECT_THROW(delaunay_complex(p), Undefined);
}

/// The brute-force farthest-point Delaunay triangles of front sites: counter-clockwise triples
/// of distinct sites (smallest index first) whose circle holds every site (in_circle ≥ 0).
std::set<Face> farthest_brute(const std::vector<Point>& p) {
  std::set<Face> out;
  const Index n = static_cast<Index>(p.size());
  for (Index a = 0; a < n; ++a)
    for (Index b = 0; b < n; ++b)
      for (Index c = 0; c < n; ++c) {
        if (!(a < b && a < c) || orient(p[a], p[b], p[c]) != POSITIVE) continue;
        bool all = true;
        for (const Point& d : p) all = all && in_circle(p[a], p[b], p[c], d) != NEGATIVE;
        if (all) out.insert({a, b, c});
      }
  return out;
}

Face rotated(Face t) {
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

TEST(DelaunayComplex, FrontOnlyBackFacesAreTheFarthestPointDelaunayTriangles) {
  std::mt19937 rng(4);
  for (int r = 0; r < 40; ++r) {
    const auto p = scattered_sites(4 + r % 14, 1, rng);  // general position: the oracle's set is exact
    const DelaunayComplex dc = delaunay_complex(p);
    ASSERT_EQ(sphere_error(dc), "");
    EXPECT_EQ(twin_error(dc), "");
    std::set<Face> back;
    for (const Face& t : dc.faces)
      if (orient(p[t[0]], p[t[1]], p[t[2]]) == NEGATIVE) back.insert(rotated({t[0], t[2], t[1]}));
    EXPECT_EQ(back, farthest_brute(p)) << "round " << r;
  }
  for (int r = 0; r < 40; ++r) {  // grids: cocircular corners, so any fan is right: a subset
    const auto p = grid_sites(4 + r % 14, 3, 1, rng);
    const DelaunayComplex dc = delaunay_complex(p);
    const std::set<Face> brute = farthest_brute(p);
    for (const Face& t : dc.faces) {
      if (orient(p[t[0]], p[t[1]], p[t[2]]) == NEGATIVE) {
        EXPECT_TRUE(brute.count(rotated({t[0], t[2], t[1]})));
      }
    }
  }
}

TEST(DelaunayComplex, FarthestDelaunayOfCocircularCornersIsAFan) {
  std::vector<Point> c{Point::cartesian(5, 0), Point::cartesian(3, 4), Point::cartesian(0, 5), Point::cartesian(-4, 3),
                       Point::cartesian(-5, 0), Point::cartesian(0, -5), Point::cartesian(4, -3)};
  const auto f = farthest_delaunay(c);
  ASSERT_EQ(f.size(), c.size() - 2);
  for (const Face& t : f) {
    EXPECT_EQ(orient(c[t[0]], c[t[1]], c[t[2]]), POSITIVE);
    for (const Point& d : c) EXPECT_EQ(in_circle(c[t[0]], c[t[1]], c[t[2]], d), ZERO);
  }
}

}  // namespace
}  // namespace t2
