// The public exact locate on all of T² (triangulation_query.cpp) and the one face record of the
// T² triangulations (face_kind.hpp), on the outputs of both T² constructions: the T² Delaunay
// (`delaunay`) and Algorithm 9 (`triangulate_t2`, both orders). Oracles: a brute force over all
// faces with the exact sides (side_of_edge: orient, and the recorded bisector of an antipodal
// edge), which also counts how many open faces hold each point (the tiling); face kinds
// recomputed from the exact GMP determinant and the signs of w.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "t2/kernel/orient.hpp"
#include "t2/triangulation/antipodal_edge.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "t2/triangulation/face_kind.hpp"
#include "t2/triangulation/triangulate_t2.hpp"
#include "t2/triangulation/triangulation.hpp"
#include "t2_query_inputs.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

using Index = Triangulation::Index;
using Location = Triangulation::Location;
constexpr Index inf = Triangulation::infinite;

std::vector<Point> points(std::size_t n, const std::vector<int>& ws, int side, unsigned seed) {
  return testing::side_points(n, ws, side, seed);
}

/// Queries: random points of T² (front, back, Ω) on a finer grid, every vertex and its
/// antipode, and the T² midpoint of every edge between points that are not antipodal.
std::vector<Point> queries(const Triangulation& tr, int side, unsigned seed) {
  std::vector<Point> q = points(300, {4, -4, 0}, 4 * side, seed + 1000);  // a grid 4 times finer
  for (Index v = 0; v < tr.points().size(); ++v) {
    if (tr.face_of(v) == Triangulation::none) continue;
    q.push_back(tr.point(v));
    q.push_back(antipode(tr.point(v)));
  }
  for (Index h : tr.edges()) {
    if (tr.org(h) == inf || tr.dest(h) == inf) continue;
    const Point &a = tr.point(tr.org(h)), &b = tr.point(tr.dest(h));
    if (a == antipode(b)) continue;
    // scale both to |w| = 1 or keep on Ω so that the sum is the T² midpoint direction, exactly
    q.push_back(mix(1.0, a, 1.0, b));
  }
  return q;
}

/// The brute force: every finite face that is not flat, with the exact sides.
struct Brute {
  Index vertex = Triangulation::none;  // p is this vertex
  std::vector<Index> open;             // faces whose interior holds p
  std::set<std::pair<Index, Index>> edges;  // edges (sorted ends) whose relative interior holds p
  bool closed = false;                 // p is in some closed finite face
};

Brute brute(const Triangulation& tr, const Point& p) {
  Brute b;
  for (Index v = 0; v < tr.points().size(); ++v)
    if (tr.face_of(v) != Triangulation::none && tr.point(v) == p) b.vertex = v;
  for (Index t = 0; t < tr.size(); ++t) {
    if (tr.is_infinite(t) || face_kind(tr, t) == FaceKind::flat) continue;
    Sign s[3];
    for (int i = 0; i < 3; ++i) s[i] = side_of_edge(tr, t, i, p);
    if (s[0] < 0 || s[1] < 0 || s[2] < 0) continue;
    b.closed = true;
    if (s[0] > 0 && s[1] > 0 && s[2] > 0) b.open.push_back(t);
    for (int i = 0; i < 3; ++i) {
      if (s[i] != 0 || b.vertex != Triangulation::none) continue;
      const Index x = tr.vertex(t, (i + 1) % 3), y = tr.vertex(t, (i + 2) % 3);
      const Point &a = tr.point(x), &c = tr.point(y);
      if (a == antipode(c) || inside_arc(a, c, p)) b.edges.insert({std::min(x, y), std::max(x, y)});
    }
  }
  return b;
}

/// locate(p, hint) against the brute force; the open faces holding p are counted (≤ 1, and 1
/// for a point on no edge when the faces cover the sphere).
void check_locate(const Triangulation& tr, const Point& p, Index hint) {
  const Location loc = tr.locate(p, hint);
  const Brute b = brute(tr, p);
  SCOPED_TRACE(to_string(p));
  ASSERT_LE(b.open.size(), 1u) << "two faces overlap";
  if (b.vertex != Triangulation::none) {
    ASSERT_EQ(loc.kind, Location::vertex);
    EXPECT_EQ(tr.vertex(loc.t, loc.i), b.vertex);
    return;
  }
  ASSERT_NE(loc.kind, Location::vertex);
  if (!b.open.empty()) {
    ASSERT_EQ(loc.kind, Location::face);
    EXPECT_EQ(loc.t, b.open[0]);
    EXPECT_TRUE(b.edges.empty());
    return;
  }
  if (!b.edges.empty()) {
    ASSERT_EQ(loc.kind, Location::edge);
    const Index x = tr.vertex(loc.t, (loc.i + 1) % 3), y = tr.vertex(loc.t, (loc.i + 2) % 3);
    EXPECT_TRUE(b.edges.count({std::min(x, y), std::max(x, y)}));
    EXPECT_NE(face_kind(tr, loc.t), FaceKind::flat);
    return;
  }
  // p in no closed finite face: outside the hull, strictly beyond the hull edge answered
  ASSERT_FALSE(b.closed);
  ASSERT_NE(tr.face_of(inf), Triangulation::none) << "a point of T² in no face of a triangulation without a hull";
  ASSERT_EQ(loc.kind, Location::face);
  ASSERT_TRUE(tr.is_infinite(loc.t));
  const int k = tr.slot(loc.t, inf);
  EXPECT_EQ(loc.i, k);
  EXPECT_EQ(orient(tr.point(tr.vertex(loc.t, (k + 1) % 3)), tr.point(tr.vertex(loc.t, (k + 2) % 3)), p), POSITIVE);
}

/// The kind recomputed independently: the exact GMP determinant and the signs of w.
FaceKind oracle_kind(const Triangulation& tr, Index t) {
  if (tr.is_infinite(t)) return FaceKind::infinite;
  const ExactPoint e[3] = {to_exact(tr.point(tr.vertex(t, 0))), to_exact(tr.point(tr.vertex(t, 1))),
                           to_exact(tr.point(tr.vertex(t, 2)))};
  const Integer det = e[0].w() * (e[1].x() * e[2].y() - e[1].y() * e[2].x()) -
                      e[0].x() * (e[1].w() * e[2].y() - e[1].y() * e[2].w()) +
                      e[0].y() * (e[1].w() * e[2].x() - e[1].x() * e[2].w());
  if (sgn(det) == 0) {
    for (int i = 0; i < 3; ++i) {
      const ExactPoint &a = e[i], &b = e[(i + 1) % 3];  // antipodal: b = −λa, λ > 0
      if (a.w() * b.x() == a.x() * b.w() && a.w() * b.y() == a.y() * b.w() && a.x() * b.y() == a.y() * b.x() &&
          sgn(a.w() * b.w() + a.x() * b.x() + a.y() * b.y()) < 0)
        return FaceKind::lune;
    }
    return FaceKind::flat;
  }
  int pos = 0, neg = 0;
  for (const ExactPoint& a : e) pos += sgn(a.w()) > 0, neg += sgn(a.w()) < 0;
  return pos == 3 ? FaceKind::front : neg == 3 ? FaceKind::back : pos + neg == 3 ? FaceKind::band : FaceKind::omega;
}

/// The face record of tr: kinds as the oracle says; every lune's third vertex strictly on the
/// lune's side of its recorded antipodal edge (the one rule of face_kind.hpp); invariant 6.
/// Returns the kinds found.
std::set<FaceKind> check_record(const Triangulation& tr) {
  EXPECT_EQ(tr.validate(), "");
  std::set<FaceKind> kinds;
  for (Index t = 0; t < tr.size(); ++t) {
    const FaceKind k = face_kind(tr, t);
    EXPECT_EQ(k, oracle_kind(tr, t)) << "face " << t;
    kinds.insert(k);
    if (k != FaceKind::lune) continue;
    for (int i = 0; i < 3; ++i) {
      const Point &a = tr.point(tr.vertex(t, (i + 1) % 3)), &b = tr.point(tr.vertex(t, (i + 2) % 3));
      if (a == antipode(b)) {
        EXPECT_EQ(side_of_edge(tr, t, i, tr.point(tr.vertex(t, i))), POSITIVE) << "lune " << t;
      }
    }
  }
  return kinds;
}

/// The triangulations of pts: T² Delaunay and Algorithm 9 in both orders.
std::vector<Triangulation> both(const std::vector<Point>& pts) {
  std::vector<Triangulation> out;
  out.push_back(delaunay(pts));
  out.push_back(triangulate_t2(pts).tr);
  out.push_back(triangulate_t2(pts, InsertionOrder::input).tr);
  return out;
}

/// How many answers of each sort the queries gave (so that a test sees it asked what it meant).
struct Tally {
  int vertex = 0, edge = 0, face = 0, infinite = 0, lune = 0;
};

Tally check_all(const std::vector<Point>& pts, int side, unsigned seed) {
  std::mt19937 rng(seed);
  Tally n;
  int m = 0;
  for (const Triangulation& tr : both(pts)) {
    SCOPED_TRACE(m++ == 0 ? "delaunay" : m == 2 ? "triangulate_t2, spatial order" : "triangulate_t2, input order");
    if (tr.dimension() != 2) continue;
    check_record(tr);
    for (const Point& q : queries(tr, side, seed)) {
      const Index hint = static_cast<Index>(rng() % tr.size());
      check_locate(tr, q, hint);
      const Location loc = tr.locate(q, hint);
      n.vertex += loc.kind == Location::vertex, n.edge += loc.kind == Location::edge;
      n.face += loc.kind == Location::face && !tr.is_infinite(loc.t);
      n.infinite += loc.kind == Location::face && tr.is_infinite(loc.t);
      n.lune += loc.kind == Location::face && face_kind(tr, loc.t) == FaceKind::lune;
    }
  }
  return n;
}

TEST(LocateT2, BothSidesWithoutHull) {
  for (int seed = 1; seed <= 4 * testing::scale(); ++seed) {
    SCOPED_TRACE(seed);
    const Tally n = check_all(points(40 + 10 * seed, {1, -1}, seed % 2 ? 3 : 1000, seed), seed % 2 ? 3 : 1000, seed);
    EXPECT_GT(n.vertex, 0);
    EXPECT_GT(n.edge, 0);
    EXPECT_GT(n.face, 0);
    EXPECT_EQ(n.infinite, 0);
  }
}

TEST(LocateT2, OmegaSites) {
  for (int seed = 1; seed <= 4 * testing::scale(); ++seed) {
    SCOPED_TRACE(seed);
    std::vector<Point> p;
    try {
      p = points(50, seed % 2 ? std::vector<int>{1, -1, 0} : std::vector<int>{1, 0}, 5, 10 + seed);
      (void)delaunay(p);  // front and Ω only may have no T² Delaunay (Ω in no open half)
    } catch (const Undefined&) {
      continue;
    }
    try {
      check_all(p, 5, seed);
    } catch (const Undefined&) {  // Algorithm 9 may refuse the same input (an antipode in a hull edge)
    }
  }
}

// A hull: front points, and front points with a few back points near Ω (all in an open
// hemisphere): infinite faces, and queries behind and on Ω outside the hull.
TEST(LocateT2, WithAHull) {
  for (int seed = 1; seed <= 4 * testing::scale(); ++seed) {
    SCOPED_TRACE(seed);
    std::vector<Point> p = points(60, {1}, seed % 2 ? 4 : 1000, 20 + seed);
    const int side = seed % 2 ? 4 : 1000;
    EXPECT_GT(check_all(p, side, seed).infinite, 0);
    // behind, with x > 2·side: all in the open hemisphere 2·side·w + x > 0 (a hull); coordinates
    // off the grid, so that no back point lies on the line of a front hull edge (a tie on Ω)
    for (int k = 0; k < 5; ++k) p.emplace_back(-1, 3.37 * side + 1.13 * k, 0.29 * side + 2.71 * k);
    EXPECT_GT(check_all(p, side, seed).infinite, 0);
  }
}

// Antipodal pairs: lunes in both constructions, located through the recorded bisector.
TEST(LocateT2, AntipodalPairs) {
  int lunes = 0;  // queries answered by a lune
  for (int seed = 1; seed <= 6 * testing::scale(); ++seed) {
    SCOPED_TRACE(seed);
    std::vector<Point> p = points(30, {1, -1}, seed % 2 ? 3 : 50, 30 + seed);
    for (int k = 0; k < 4; ++k) p.push_back(antipode(p[static_cast<std::size_t>(k)]));
    check_all(p, seed % 2 ? 3 : 50, seed);
    // figure 5.18 at random: front points and the antipode of a hull corner (the largest x)
    std::vector<Point> f = points(25, {1}, 50, 60 + seed);
    const Point corner = *std::max_element(f.begin(), f.end(), [](const Point& a, const Point& b) {
      return a.x() / a.w() < b.x() / b.w() || (a.x() / a.w() == b.x() / b.w() && a.y() < b.y());
    });
    f.push_back(antipode(corner));
    lunes += check_all(f, 50, seed).lune;
  }
  EXPECT_GT(lunes, 0);
  // Figure 5.18 of seed 000: a hull triangle and the antipode of one vertex; the edge z → ¬z
  // runs along (−2, −1) from z: on it, the points answer the edge, beside it the lunes.
  const std::vector<Point> P = {Point::cartesian(0, 0), Point::cartesian(2, 0), Point::cartesian(3, 4),
                                antipode(Point::cartesian(0, 0))};
  for (const Triangulation& tr : both(P)) {
    check_record(tr);
    ASSERT_EQ(tr.antipodal_edges().size(), 1u);
    for (const Point& q : {Point::cartesian(-2, -1), Point(0, -2, -1), Point(-1, -2, -1)}) {
      const Location loc = tr.locate(q);
      ASSERT_EQ(loc.kind, Location::edge) << to_string(q);
      EXPECT_TRUE(tr.point(tr.vertex(loc.t, (loc.i + 1) % 3)) == antipode(tr.point(tr.vertex(loc.t, (loc.i + 2) % 3))));
      check_locate(tr, q, 1);
    }
    for (const Point& q : {Point::cartesian(-2, -1.001), Point::cartesian(-2, -0.999)}) {
      const Location loc = tr.locate(q);
      ASSERT_EQ(loc.kind, Location::face);
      EXPECT_EQ(face_kind(tr, loc.t), FaceKind::lune);
      check_locate(tr, q, 2);
    }
  }
}

// Figure 5.19: a flat face; points on its edges answer an edge of a face that is not flat, its
// middle vertex (hidden inside the edge z → w of the proper face next to it) the vertex.
TEST(LocateT2, FlatFace) {
  const std::vector<Point> P = {Point::cartesian(0, 0), Point::cartesian(2, 0), Point::cartesian(3, 4),
                                antipode(Point::cartesian(0, 0)), Point::cartesian(1, 0)};
  const Triangulation tr = triangulate_t2(P, InsertionOrder::input).tr;
  EXPECT_TRUE(check_record(tr).count(FaceKind::flat));
  for (Index hint = 0; hint < tr.size(); ++hint)
    for (const Point& q : {Point::cartesian(0.5, 0), Point::cartesian(1.5, 0), Point::cartesian(1, 0), Point(-1, -0.5, 0),
                           Point(0, 1, 0), Point(0, -1, 0), Point::cartesian(5, 0)})
      check_locate(tr, q, hint);
  const Location loc = tr.locate(Point::cartesian(1, 0));  // t, inside the old hull edge z → w
  ASSERT_EQ(loc.kind, Location::vertex);
  EXPECT_EQ(tr.vertex(loc.t, loc.i), 4u);
}

// One record for both constructions on the same input: the kinds come from the vertices alone,
// so a face (vertex triple) of both has one kind; sides present give the same kinds.
TEST(LocateT2, KindsAgreeAcrossConstructions) {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    SCOPED_TRACE(seed);
    const std::vector<int> ws = seed <= 2 ? std::vector<int>{1} : seed <= 4 ? std::vector<int>{1, -1} : std::vector<int>{1, -1, 0};
    std::vector<Point> p = points(40, ws, 6, 40 + seed);
    if (seed == 4) p.push_back(antipode(p[0]));
    std::vector<Triangulation> trs;
    try {
      trs = both(p);
    } catch (const Undefined&) {
      continue;
    }
    std::map<std::set<Index>, FaceKind> seen;
    std::set<FaceKind> kinds[3];
    for (std::size_t m = 0; m < trs.size(); ++m) {
      kinds[m] = check_record(trs[m]);
      for (Index t = 0; t < trs[m].size(); ++t) {
        if (trs[m].is_infinite(t)) continue;
        const std::set<Index> f = {trs[m].vertex(t, 0), trs[m].vertex(t, 1), trs[m].vertex(t, 2)};
        const auto [it, fresh] = seen.emplace(f, face_kind(trs[m], t));
        if (!fresh) {
          EXPECT_EQ(it->second, face_kind(trs[m], t));
        }
      }
    }
    for (const auto& k : kinds) {
      EXPECT_EQ(k.count(FaceKind::front), 1u);
      EXPECT_EQ(k.count(FaceKind::back), ws.size() > 1 ? 1u : 0u);
      EXPECT_EQ(k.count(FaceKind::infinite), ws.size() > 1 ? 0u : 1u);
      EXPECT_EQ(k.count(FaceKind::omega) > 0, ws.size() > 2);
    }
  }
}

TEST(LocateT2, RejectsWhatItCannotAnswer) {
  const Triangulation line = delaunay(std::vector<Point>{Point::cartesian(0, 0), Point::cartesian(1, 1)});
  EXPECT_THROW(line.locate(Point::cartesian(0, 0)), std::logic_error);  // no triangle
}

}  // namespace
}  // namespace t2
