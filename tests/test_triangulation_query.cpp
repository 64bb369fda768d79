// The queries of t2::Triangulation (triangulation.hpp): the vertex link, edges(), the stars of a
// vertex (incident_faces, neighbors), the public exact locate and nearest_vertex. Every answer is
// checked against an independent oracle computed from the flat face list alone: a scan of the
// triangles for the link, the set of face sides and Euler's formula for the edges, brute force
// (exact orient) for locate, brute force (exact compare_distance) for nearest_vertex.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "t2/kernel/distance.hpp"
#include "t2/kernel/lexicographic.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "t2/triangulation/divide.hpp"
#include "t2/triangulation/lawson.hpp"
#include "t2/triangulation/triangulate.hpp"
#include "t2/triangulation/triangulate_t2.hpp"
#include "t2/triangulation/triangulation.hpp"

namespace t2 {
namespace {

using Index = Triangulation::Index;
constexpr Index inf = Triangulation::infinite;
constexpr Index none = Triangulation::none;
using Location = Triangulation::Location;

/// n points with integer coordinates in [0, 2·side) that are even (so midpoints are integers):
/// small grids give duplicates, collinear and cocircular points.
std::vector<Point> grid_points(std::size_t n, int side, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> d(0, side - 1);
  std::vector<Point> p;
  for (std::size_t k = 0; k < n; ++k) p.push_back(Point::cartesian(2 * d(rng), 2 * d(rng)));
  return p;
}

/// The vertices of tr found by a scan of its triangles (v∞ included), with their triangles.
std::map<Index, std::set<Index>> scan_stars(const Triangulation& tr) {
  std::map<Index, std::set<Index>> star;
  for (Index t = 0; t < tr.size(); ++t)
    for (int i = 0; i < 3; ++i) star[tr.vertex(t, i)].insert(t);
  return star;
}

/// The link holds for every vertex (a triangle that has it) and is `none` for every point
/// that is not a vertex: an independent scan of the triangles.
std::string link_error(const Triangulation& tr) {
  const auto star = scan_stars(tr);
  for (Index v = 0; v < tr.points().size(); ++v) {
    const auto it = star.find(v);
    const Index f = tr.face_of(v);
    if (it == star.end() && f != none) return "point " + std::to_string(v) + " is no vertex but has a face";
    if (it != star.end() && !it->second.count(f)) return "vertex " + std::to_string(v) + ": face_of is not its face";
  }
  const auto it = star.find(inf);
  const Index f = tr.face_of(inf);
  if (it == star.end() ? f != none : !it->second.count(f)) return "v-infinity: wrong face_of";
  return "";
}

/// edges(): each side of a triangle exactly once, 3F/2 of them, V − E + F = 2.
void check_edges(const Triangulation& tr) {
  std::map<std::pair<Index, Index>, int> sides;  // undirected side -> number of triangles
  for (Index t = 0; t < tr.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const Index a = tr.vertex(t, (i + 1) % 3), b = tr.vertex(t, (i + 2) % 3);
      ++sides[{std::min(a, b), std::max(a, b)}];
    }
  std::map<std::pair<Index, Index>, int> seen;
  const std::vector<Index> edges = tr.edges();
  for (Index h : edges) {
    const Index a = tr.org(h), b = tr.dest(h);
    ++seen[{std::min(a, b), std::max(a, b)}];
    // the half-edge's endpoints are the side opposite its slot
    EXPECT_EQ(a, tr.vertex(h / 3, (h % 3 + 1) % 3));
    EXPECT_EQ(tr.org(tr.twin(h)), b);
    EXPECT_EQ(tr.dest(tr.twin(h)), a);
  }
  EXPECT_EQ(seen.size(), sides.size());
  for (const auto& [e, k] : seen) EXPECT_EQ(k, 1) << e.first << "-" << e.second;
  for (const auto& [e, k] : sides) EXPECT_TRUE(seen.count(e)) << e.first << "-" << e.second;
  EXPECT_EQ(2 * edges.size(), 3 * tr.size());
  const std::size_t V = scan_stars(tr).size();
  EXPECT_EQ(V + tr.size(), edges.size() + 2);  // V − E + F = 2
}

/// incident_faces and neighbors against the scan: the same sets, each once, and counter-clockwise
/// (face k + 1 is the triangle across the edge from v to neighbour k + 1 ... of face k).
void check_stars(const Triangulation& tr) {
  for (const auto& [v, faces] : scan_stars(tr)) {
    std::vector<Index> f(tr.incident_faces(v).begin(), tr.incident_faces(v).end());
    std::vector<Index> n(tr.neighbors(v).begin(), tr.neighbors(v).end());
    ASSERT_EQ(f.size(), faces.size()) << "vertex " << v;
    ASSERT_EQ(n.size(), f.size());
    EXPECT_EQ(std::set<Index>(f.begin(), f.end()), faces);
    std::set<Index> adjacent;  // brute force: every other vertex of v's triangles
    for (Index t : faces)
      for (int i = 0; i < 3; ++i)
        if (tr.vertex(t, i) != v) adjacent.insert(tr.vertex(t, i));
    EXPECT_EQ(std::set<Index>(n.begin(), n.end()), adjacent);
    EXPECT_EQ(std::set<Index>(n.begin(), n.end()).size(), n.size());
    for (std::size_t k = 0; k < f.size(); ++k) {
      // face k is (v, n[k], n[k+1]) in counter-clockwise order
      const int s = tr.slot(f[k], v);
      ASSERT_GE(s, 0);
      EXPECT_EQ(tr.vertex(f[k], (s + 1) % 3), n[k]);
      EXPECT_EQ(tr.vertex(f[k], (s + 2) % 3), n[(k + 1) % n.size()]);
    }
  }
}

/// Counter-clockwise in the plane, for a front triangulation: the finite neighbours of v are in
/// the cyclic order of their exact angle around v (an oracle by sorting, not by the faces).
void check_angular_order(const Triangulation& tr) {
  for (const auto& [v, faces] : scan_stars(tr)) {
    if (v == inf) continue;
    const Point& c = tr.point(v);
    std::vector<Index> n;
    for (Index w : tr.neighbors(v))
      if (w != inf) n.push_back(w);
    auto half = [&](const Point& p) {  // 0: angle in [0, π), 1: in [π, 2π)
      return p.y() > c.y() || (p.y() == c.y() && p.x() > c.x()) ? 0 : 1;
    };
    std::vector<Index> sorted = n;
    std::sort(sorted.begin(), sorted.end(), [&](Index a, Index b) {
      const Point &p = tr.point(a), &q = tr.point(b);
      if (half(p) != half(q)) return half(p) < half(q);
      return orient(c, p, q) == POSITIVE;
    });
    auto it = std::find(n.begin(), n.end(), sorted.front());
    std::rotate(n.begin(), it, n.end());
    EXPECT_EQ(n, sorted) << "vertex " << v;
  }
}

void check_all(const Triangulation& tr) {
  ASSERT_EQ(link_error(tr), "");  // the stars below start from the link
  EXPECT_EQ(tr.validate(), "");
  check_edges(tr);
  check_stars(tr);
}

/// The finite triangles do not overlap (each one's centroid lies in no other closed triangle)
/// and the hull is convex (no vertex strictly beyond a hull edge).
std::string embedding_error(const Triangulation& tr) {
  for (Index t = 0; t < tr.size(); ++t) {
    if (tr.is_infinite(t)) continue;
    const Point &a = tr.point(tr.vertex(t, 0)), &b = tr.point(tr.vertex(t, 1)), &c = tr.point(tr.vertex(t, 2));
    const Point g(3, a.x() + b.x() + c.x(), a.y() + b.y() + c.y());
    for (Index u = 0; u < tr.size(); ++u) {
      if (u == t || tr.is_infinite(u)) continue;
      bool in = true;
      for (int i = 0; i < 3; ++i)
        in = in && orient(tr.point(tr.vertex(u, (i + 1) % 3)), tr.point(tr.vertex(u, (i + 2) % 3)), g) >= 0;
      if (in) return "triangles " + std::to_string(t) + " and " + std::to_string(u) + " overlap";
    }
  }
  for (auto [a, b] : tr.hull_edges())  // the hull is convex: no vertex strictly beyond a hull edge
    for (const auto& [v, faces] : scan_stars(tr))
      if (v != inf && orient(tr.point(a), tr.point(b), tr.point(v)) < 0)
        return "vertex " + std::to_string(v) + " beyond the hull edge " + std::to_string(a) + "-" + std::to_string(b);
  return "";
}

/// Where p is, by brute force over the finite triangles with exact orient: a vertex, the
/// endpoints of an edge (sorted), the vertices of a triangle (sorted), or nothing (outside).
struct Brute {
  Location::Kind kind;
  std::vector<Index> ids;  // empty: outside the hull
};

Brute brute_locate(const Triangulation& tr, const Point& p) {
  for (const auto& [v, faces] : scan_stars(tr))
    if (v != inf && tr.point(v) == p) return {Location::vertex, {v}};
  std::set<std::pair<Index, Index>> on;
  for (Index t = 0; t < tr.size(); ++t) {
    if (tr.is_infinite(t)) continue;
    Sign s[3];
    for (int i = 0; i < 3; ++i) s[i] = orient(tr.point(tr.vertex(t, (i + 1) % 3)), tr.point(tr.vertex(t, (i + 2) % 3)), p);
    if (s[0] < 0 || s[1] < 0 || s[2] < 0) continue;
    std::vector<Index> ids = {tr.vertex(t, 0), tr.vertex(t, 1), tr.vertex(t, 2)};
    std::sort(ids.begin(), ids.end());
    if (s[0] > 0 && s[1] > 0 && s[2] > 0) return {Location::face, ids};
    for (int i = 0; i < 3; ++i)  // not a vertex, so exactly one zero
      if (s[i] == 0) {
        const Index a = tr.vertex(t, (i + 1) % 3), b = tr.vertex(t, (i + 2) % 3);
        on.insert({std::min(a, b), std::max(a, b)});
      }
  }
  if (on.size() == 1) return {Location::edge, {on.begin()->first, on.begin()->second}};
  EXPECT_TRUE(on.empty()) << "a point on two edges that is no vertex";
  return {Location::face, {}};
}

void check_locate(const Triangulation& tr, const Point& p, Index hint) {
  const Location loc = tr.locate(p, hint);
  const Brute b = brute_locate(tr, p);
  ASSERT_EQ(loc.kind, b.kind) << to_string(p);
  std::vector<Index> ids;
  if (loc.kind == Location::vertex) {
    ids = {tr.vertex(loc.t, loc.i)};
  } else if (loc.kind == Location::edge) {
    ids = {tr.vertex(loc.t, (loc.i + 1) % 3), tr.vertex(loc.t, (loc.i + 2) % 3)};
  } else if (!tr.is_infinite(loc.t)) {
    ids = {tr.vertex(loc.t, 0), tr.vertex(loc.t, 1), tr.vertex(loc.t, 2)};
  } else {  // outside: p strictly beyond the hull edge of the infinite triangle
    const int k = tr.slot(loc.t, inf);
    EXPECT_EQ(orient(tr.point(tr.vertex(loc.t, (k + 1) % 3)), tr.point(tr.vertex(loc.t, (k + 2) % 3)), p), POSITIVE);
  }
  std::sort(ids.begin(), ids.end());
  EXPECT_EQ(ids, b.ids) << to_string(p);
}

/// The nearest vertex by brute force: every vertex compared exactly; the answer must be at the
/// minimum distance (one of the tied ones).
void check_nearest(const Triangulation& tr, const Point& q, Index hint) {
  const Index v = tr.nearest_vertex(q, hint);
  ASSERT_NE(v, inf);
  ASSERT_NE(tr.face_of(v), none) << "not a vertex";
  for (const auto& [w, faces] : scan_stars(tr)) {
    if (w == inf) continue;
    EXPECT_NE(compare_distance(tr.point(w), tr.point(v), q), NEGATIVE) << to_string(q);
  }
}

/// Queries: random points around and beyond the points, every vertex, the midpoint of every
/// edge, and points on the lines of the hull edges beyond their ends.
std::vector<Point> queries(const Triangulation& tr, int side, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> d(-4, 2 * side + 4);
  std::vector<Point> q;
  for (int k = 0; k < 200; ++k) q.push_back(Point::cartesian(d(rng), d(rng)));
  for (const Point& p : tr.points()) q.push_back(p);
  for (Index h : tr.edges()) {
    if (tr.org(h) == inf || tr.dest(h) == inf) continue;
    const Point &a = tr.point(tr.org(h)), &b = tr.point(tr.dest(h));
    q.push_back(Point::cartesian((a.x() + b.x()) / 2, (a.y() + b.y()) / 2));
  }
  for (auto [a, b] : tr.hull_edges()) {
    const Point &p = tr.point(a), &r = tr.point(b);
    q.push_back(Point::cartesian(2 * r.x() - p.x(), 2 * r.y() - p.y()));
    q.push_back(Point::cartesian(3 * p.x() - 2 * r.x(), 3 * p.y() - 2 * r.y()));
  }
  return q;
}

TEST(TriangulationQuery, DelaunayStarsEdgesAndLink) {
  for (unsigned seed = 1; seed <= 12; ++seed) {
    const int side = seed % 3 == 0 ? 4 : seed % 3 == 1 ? 10 : 1000;  // dense grids: degeneracies
    const auto pts = grid_points(60 + 20 * seed, side, seed);
    const Triangulation tr = delaunay(pts);
    ASSERT_EQ(tr.dimension(), 2);
    check_all(tr);
    check_angular_order(tr);
  }
}

TEST(TriangulationQuery, OtherConstructionsKeepTheLink) {
  const auto pts = grid_points(300, 12, 7);
  check_all(delaunay(std::vector<Point>(pts)));  // the result takes the points: renumber in place
  check_all(delaunay_by_flips(pts));              // the sweep, then Lawson's flips
  check_all(triangulate(pts));
  check_all(delaunay_divide(pts));                // built on the quad-edge, then assign
  check_angular_order(delaunay_divide(pts));
}

TEST(TriangulationQuery, TwoSidedInputKeepsTheLink) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> d(-20, 20), w(-1, 1);
  for (int round = 0; round < 6; ++round) {
    std::vector<Point> pts;
    for (int k = 0; k < 80; ++k) {
      int ww = round < 2 ? w(rng) : (k % 2 == 0 ? 1 : -1);  // rounds 0, 1: Ω sites too
      int x = d(rng), y = d(rng);
      if (ww == 0 && x == 0 && y == 0) x = 1;
      pts.push_back(Point(ww, x, y));
    }
    if (round == 5) pts.push_back(antipode(pts[0]));  // an antipodal pair
    const Triangulation dt = delaunay(pts);  // the T² Delaunay (assign)
    check_all(dt);
    const TriangulationT2 at = triangulate_t2(pts);  // Algorithm 9
    check_all(at.tr);
    const TriangulationT2 ai = triangulate_t2(pts, InsertionOrder::input);
    check_all(ai.tr);
  }
}

/// Random insertions (located by the public locate) and random flips of strictly convex
/// quadrilaterals; after every operation the link is checked by the independent scan.
TEST(TriangulationQuery, LinkAfterRandomInsertionsAndFlips) {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    const auto pts = grid_points(120, seed % 2 ? 6 : 100, seed);
    Triangulation tr(pts);
    Index a = 0, b = 1, c = 2;
    while (b < pts.size() && pts[b] == pts[a]) ++b;
    for (c = b + 1; c < pts.size() && orient(pts[a], pts[b], pts[c]) == ZERO; ++c) {}
    ASSERT_LT(c, pts.size());
    if (orient(pts[a], pts[b], pts[c]) > 0) tr.make_triangle(a, b, c); else tr.make_triangle(b, a, c);
    ASSERT_EQ(link_error(tr), "");
    std::mt19937 rng(seed);
    std::vector<Index> kept(pts.size(), none);  // the vertex each dropped duplicate went to
    for (Index p = 1; p < pts.size(); ++p) {
      if (p == b || p == c) continue;
      const Location loc = tr.locate(pts[p], static_cast<Index>(rng() % tr.size()));
      check_locate(tr, pts[p], 0);
      if (loc.kind == Location::vertex) {
        const Index v = tr.vertex(loc.t, loc.i);
        if (rng() % 2) tr.rename_vertex(loc.t, v, p);  // the new point takes the old one's place
      } else if (loc.kind == Location::face) {
        const bool outside = tr.is_infinite(loc.t);
        tr.insert_in_face(loc.t, p);
        ASSERT_EQ(link_error(tr), "") << "after inserting " << p;
        if (outside) {  // flip the reflex angles at p away (triangulate.hpp)
          const Index n = static_cast<Index>(tr.size());
          for (Index f : {loc.t, n - 2, n - 1})
            if (tr.vertex(f, 1) == inf || tr.vertex(f, 2) == inf) detail::flip_hull_chain(tr, f);
        }
      } else {
        tr.insert_on_edge(loc.t, loc.i, p);
      }
      ASSERT_EQ(link_error(tr), "") << "after inserting " << p;
      ASSERT_EQ(embedding_error(tr), "") << "after inserting " << p << " " << loc.kind;
      for (int f = 0; f < 3; ++f) {  // a few random flips where the quadrilateral is strictly convex
        const Index t = static_cast<Index>(rng() % tr.size());
        const int i = static_cast<int>(rng() % 3);
        const Index u = tr.neighbor(t, i);
        if (tr.is_infinite(t) || tr.is_infinite(u)) continue;
        const Index e = tr.twin(t, i);
        const Point &P = tr.point(tr.vertex(t, i)), &Q = tr.point(tr.vertex(t, (i + 1) % 3)),
                    &R = tr.point(tr.vertex(t, (i + 2) % 3)), &D = tr.point(tr.vertex(u, static_cast<int>(e % 3)));
        if (orient(P, Q, D) <= 0 || orient(P, D, R) <= 0) continue;
        tr.flip(t, i);
        ASSERT_EQ(link_error(tr), "") << "after a flip";
        ASSERT_EQ(embedding_error(tr), "") << "after a flip";
      }
    }
    check_all(tr);
    flip_to_delaunay(tr);
    check_all(tr);
    for (const Point& q : queries(tr, seed % 2 ? 6 : 100, seed)) check_locate(tr, q, static_cast<Index>(rng() % tr.size()));
  }
}

TEST(TriangulationQuery, LocateOnANonDelaunayTriangulation) {
  const auto pts = grid_points(200, 40, 3);
  const Triangulation tr = triangulate(pts);  // the sweep: long thin triangles
  std::mt19937 rng(3);
  for (const Point& q : queries(tr, 40, 3)) check_locate(tr, q, static_cast<Index>(rng() % tr.size()));
}

TEST(TriangulationQuery, LocateRejectsWhatItCannotAnswer) {
  const Triangulation line = delaunay(std::vector<Point>{Point::cartesian(0, 0), Point::cartesian(1, 1)});
  EXPECT_THROW(line.locate(Point::cartesian(0, 0)), std::logic_error);  // no triangle
  // back points and points of Ω are answered (test_locate_t2.cpp): outside this hull
  const Triangulation tr = delaunay(grid_points(30, 10, 1));
  for (const Point& q : {Point(-1, 3, 4), Point(0, 3, 4)}) {
    const Location loc = tr.locate(q);
    EXPECT_TRUE(loc.kind == Location::face && tr.is_infinite(loc.t)) << to_string(q);
  }
}

TEST(TriangulationQuery, LocateAndNearestVertexAgainstBruteForce) {
  for (unsigned seed = 1; seed <= 8; ++seed) {
    const int side = seed % 2 ? 5 : 300;
    const auto pts = grid_points(150, side, 100 + seed);
    const Triangulation tr = delaunay(pts);
    std::mt19937 rng(seed);
    auto qs = queries(tr, side, seed);
    // ties: the centres of the grid squares (four vertices equally near on a full grid)
    for (int x = 1; x < 2 * side && x < 20; x += 2)
      for (int y = 1; y < 2 * side && y < 20; y += 2) qs.push_back(Point::cartesian(x, y));
    qs.push_back(Point::cartesian(1e9, -1e9));  // far away
    for (const Point& q : qs) {
      check_locate(tr, q, static_cast<Index>(rng() % tr.size()));
      check_nearest(tr, q, static_cast<Index>(rng() % tr.size()));
    }
    // from every triangle, infinite ones included, to one point
    for (Index t = 0; t < tr.size(); ++t) check_locate(tr, Point::cartesian(side, side + 1), t);
  }
}

TEST(TriangulationQuery, NearestVertexOnAFullGrid) {
  std::vector<Point> pts;  // a full 8 × 8 grid: all cocircular quadruples, many ties
  for (int x = 0; x < 8; ++x)
    for (int y = 0; y < 8; ++y) pts.push_back(Point::cartesian(2 * x, 2 * y));
  const Triangulation tr = delaunay(pts);
  for (int x = -3; x < 19; ++x)
    for (int y = -3; y < 19; ++y) {
      for (Index hint : {Index(0), static_cast<Index>(tr.size() - 1)}) check_nearest(tr, Point::cartesian(x, y), hint);
    }
}

}  // namespace
}  // namespace t2
