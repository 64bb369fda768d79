// The trapezoidal map with its history DAG (location/trapezoid_map.hpp) and the locator of T²
// built on it (location/trapezoid_locate.hpp), against the brute-force oracle (every face tested
// with point_in_polygon.hpp's exact locate) and the walk: Delaunay maps, grids with vertical
// edges and shared x-coordinates, maps on the back, on both sides, a face around the whole
// sphere, maps crossing Ω (the walk answers), queries on vertices, edges, Ω and the back; the
// map's own certificates (neighbour links, the trapezoid of each query, size and depth); and its
// trace (trace/hook.hpp) against the map it builds and the predicates it reports.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <vector>

#include "t2/kernel/lexicographic.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/location/trapezoid_locate.hpp"
#include "t2/location/walk.hpp"
#include "t2/trace/hook.hpp"
#include "t2/triangulation/delaunay.hpp"

namespace {

using t2::Location;
using t2::Point;
using t2::Subdivision;
using t2::TrapezoidMap;
using Index = Subdivision::Index;
using Faces = std::vector<std::vector<Index>>;

// Delaunay triangles of n distinct integer points of [-r, r]², each written with the weight w.
Subdivision delaunay_map(std::mt19937_64& rng, std::size_t n, int r, double w = 1) {
  std::uniform_int_distribution<int> c(-r, r);
  std::set<std::pair<int, int>> xy;
  while (xy.size() < n) xy.insert({c(rng), c(rng)});
  std::vector<Point> P;
  for (auto [x, y] : xy) P.push_back(Point::cartesian(x, y));
  Faces F;
  for (const auto& t : t2::delaunay(P).finite_triangles()) F.push_back({t[0], t[1], t[2]});
  for (auto& p : P) p = Point(w, w * p.x(), w * p.y());
  return Subdivision(P, F);
}

// An m × m grid of unit squares at (x0, y0): vertical edges, columns of vertices with one x.
// Some squares are cut into two triangles, some are left out (holes in the complement).
void grid(std::mt19937_64& rng, int m, int x0, int y0, std::vector<Point>& P, Faces& F) {
  const auto base = Index(P.size());
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= m; ++j) P.push_back(Point::cartesian(x0 + i, y0 + j));
  const auto v = [&](int i, int j) { return Index(base + i * (m + 1) + j); };
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      const auto r = rng() % 5;
      if (r == 0) continue;
      if (r == 1) {
        F.push_back({v(i, j), v(i + 1, j), v(i + 1, j + 1)});
        F.push_back({v(i, j), v(i + 1, j + 1), v(i, j + 1)});
      } else {
        F.push_back({v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)});
      }
    }
}

// The map of the antipodes: every point negated, every face listed backwards (the antipode
// turns orientations around).
void antipodes(std::vector<Point>& P, Faces& F) {
  const auto base = Index(P.size());
  const auto faces = F.size();
  for (Index v = 0; v < base; ++v) P.push_back(t2::antipode(P[v]));
  for (std::size_t f = 0; f < faces; ++f) {
    std::vector<Index> g(F[f].rbegin(), F[f].rend());
    for (auto& v : g) v += base;
    F.push_back(g);
  }
}

// Queries: every vertex, a point inside every edge (a + b), and random small integer points of
// the front, the back and Ω (many on the vertical lines and at the heights of the vertices).
std::vector<Point> queries(const Subdivision& S, std::mt19937_64& rng, int random, int r) {
  std::vector<Point> Q = S.points();
  for (Index h = 0; h < S.half_edges(); ++h) {
    const Point &a = S.points()[S.org(h)], &b = S.points()[S.dest(h)];
    Q.emplace_back(a.w() + b.w(), a.x() + b.x(), a.y() + b.y());
  }
  std::uniform_int_distribution<int> c(-r, r), w(-2, 2);
  for (int k = 0; k < random; ++k) {  // draws named: a call's arguments have no order
    const int s = w(rng), x = c(rng), y = c(rng);
    if (s == 0) Q.emplace_back(0, x | 1, y);
    else Q.emplace_back(s, s * x, s * y);  // the grid points of both sides
  }
  std::uniform_real_distribution<double> d(-r, r);
  for (int k = 0; k < random; ++k) {
    const double x = d(rng), y = d(rng);
    Q.push_back(Point::cartesian(x, y));
  }
  return Q;
}

// Every query: the locator's answer is the brute force's and the walk's.
void expect_matches(const Subdivision& S, const std::vector<Point>& Q, std::set<Location::Kind>* seen = nullptr) {
  const t2::TrapezoidLocator L(S);
  for (const Point& p : Q) {
    const Location want = t2::locate_brute(S, p);
    ASSERT_EQ(to_string(L.locate(p)), to_string(want)) << "p = " << p.w() << " " << p.x() << " " << p.y();
    ASSERT_EQ(to_string(t2::walk(S, p, S.org(0))), to_string(want));  // from a vertex of a face
    if (seen) seen->insert(want.kind);
  }
}

TEST(TrapezoidLocator, MatchesBruteForceAndWalkOnDelaunayMaps) {
  std::mt19937_64 rng(6);
  std::set<Location::Kind> seen;
  for (int round = 0; round < 4; ++round) {
    const Subdivision S = delaunay_map(rng, 20 + 10 * round, 30, round % 2 ? 3 : 1);
    const t2::TrapezoidLocator L(S);
    ASSERT_NE(L.chart(t2::TrapezoidLocator::front), nullptr);
    ASSERT_NE(L.chart(t2::TrapezoidLocator::back), nullptr);  // no edge there: closed, empty
    expect_matches(S, queries(S, rng, 80, 33), &seen);
  }
  EXPECT_EQ(seen.size(), 4u);
}

TEST(TrapezoidLocator, MatchesOnGridsWithVerticalEdgesOnBothSides) {
  std::mt19937_64 rng(15);
  std::set<Location::Kind> seen;
  for (int round = 0; round < 4; ++round) {
    std::vector<Point> P;
    Faces F;
    grid(rng, 2 + round, -3, -2, P, F);
    if (round % 2) antipodes(P, F);                       // the same grid on the back as well
    if (round == 2) grid(rng, 2, 5 + round, 0, P, F);     // and a second one on the front
    const Subdivision S(P, F);
    const t2::TrapezoidLocator L(S);
    ASSERT_NE(L.chart(t2::TrapezoidLocator::front), nullptr);
    ASSERT_NE(L.chart(t2::TrapezoidLocator::back), nullptr);
    expect_matches(S, queries(S, rng, 150, 10), &seen);
  }
  EXPECT_EQ(seen.size(), 4u);
}

TEST(TrapezoidLocator, MatchesOnBackMaps) {
  std::mt19937_64 rng(16);
  for (int round = 0; round < 3; ++round) {
    const Subdivision D = delaunay_map(rng, 30, 12, 1 + round);
    std::vector<Point> P = D.points();
    Faces F;
    for (Index f = 0; f < D.faces(); ++f) F.push_back({D.org(D.first(f)), D.org(D.first(f) + 1), D.org(D.first(f) + 2)});
    const std::size_t n = P.size();
    antipodes(P, F);
    P.erase(P.begin(), P.begin() + long(n));  // keep only the back copy
    F.erase(F.begin(), F.begin() + long(F.size() / 2));
    for (auto& f : F)
      for (auto& v : f) v -= Index(n);
    const Subdivision S(P, F);
    expect_matches(S, queries(S, rng, 120, 14));
  }
}

TEST(TrapezoidLocator, FaceAroundTheSphere) {
  // A front triangle and the face on its other side: the rest of T², Ω and the back included.
  // The back chart has no segment; its unbounded region is that face.
  const std::vector<Point> P{Point::cartesian(0, 0), Point::cartesian(4, 0), Point::cartesian(0, 4)};
  const Subdivision S(P, Faces{{0, 1, 2}, {0, 2, 1}});
  const t2::TrapezoidLocator L(S);
  ASSERT_NE(L.chart(t2::TrapezoidLocator::back), nullptr);
  EXPECT_EQ(L.chart(t2::TrapezoidLocator::back)->segments(), 0u);
  EXPECT_EQ(to_string(L.locate(Point(-1, 5, 5))), "face 1");
  EXPECT_EQ(to_string(L.locate(Point(-1, -1, -1))), "face 1");  // antipode of a point inside face 0
  EXPECT_EQ(to_string(L.locate(Point(1, 1, 1))), "face 0");
  EXPECT_EQ(to_string(L.locate(Point(1, 9, -1))), "face 1");
  EXPECT_EQ(to_string(L.locate(Point(1, 2, 2))), "edge 0 1");
  EXPECT_EQ(to_string(L.locate(Point(2, 0, 8))), "vertex 0 2");
  EXPECT_EQ(to_string(L.locate(Point(0, 1, 0))), "face 1");
  std::mt19937_64 rng(3);
  expect_matches(S, queries(S, rng, 200, 6));
}

TEST(TrapezoidLocator, MapsThatCrossOmegaAreWalked) {
  // F0 on the front, F1 from the front across Ω to the back vertex [−1, 1, 1]: its edges to it
  // join the two sides, so neither chart is closed and the walk answers every query.
  const std::vector<Point> P{Point(1, 0, 0), Point(1, 1, 0), Point(1, 0, 1), Point(-1, 1, 1)};
  const Subdivision S(P, Faces{{0, 1, 2}, {2, 1, 3}});
  const t2::TrapezoidLocator L(S);
  EXPECT_EQ(L.chart(t2::TrapezoidLocator::front), nullptr);
  EXPECT_EQ(L.chart(t2::TrapezoidLocator::back), nullptr);
  std::mt19937_64 rng(4);
  expect_matches(S, queries(S, rng, 300, 4));
}

TEST(TrapezoidLocator, RejectsCrossingEdges) {
  // Two triangles whose edges cross without a common vertex (the subdivision does not see it).
  const std::vector<Point> P{Point::cartesian(0, 0), Point::cartesian(4, 0), Point::cartesian(0, 4),
                             Point::cartesian(2, -1), Point::cartesian(6, 3), Point::cartesian(5, -2)};
  const Subdivision S(P, Faces{{0, 1, 2}, {3, 5, 4}});
  EXPECT_THROW(t2::TrapezoidLocator{S}, t2::MapError);
  // A vertex inside another face's edge (a T-junction).
  const std::vector<Point> Q{Point::cartesian(0, 0), Point::cartesian(4, 0), Point::cartesian(0, 4),
                             Point::cartesian(2, 0), Point::cartesian(4, -3), Point::cartesian(0, -3)};
  EXPECT_THROW(t2::TrapezoidLocator{Subdivision(Q, Faces{{0, 1, 2}, {3, 5, 4}})}, t2::MapError);
}

// The certificates of one map of n segments: every neighbour link is mutual and joins
// trapezoids of the final map across one vertical line; 1 + n + V ≤ 3n + 1 trapezoids (de Berg
// et al., Lemma 6.2, counted with shared endpoints); each query's trapezoid holds it strictly.
void expect_certified(const TrapezoidMap& M, const std::vector<Point>& P, const std::vector<Point>& Q) {
  const auto& T = M.trapezoids();
  std::size_t live = 0;
  for (Index i = 0; i < T.size(); ++i) {
    const auto& t = T[i];
    if (t.node == TrapezoidMap::none) continue;
    ++live;
    for (const auto& [n, back] : {std::pair{t.ur, &TrapezoidMap::Trapezoid::ul}, {t.lr, &TrapezoidMap::Trapezoid::ll}})
      if (n != TrapezoidMap::none) {
        ASSERT_NE(T[n].node, TrapezoidMap::none);
        EXPECT_EQ(T[n].*back, i);
        EXPECT_EQ(T[n].leftp, t.rightp);
      }
  }
  // Exactly 1 + n + V, V the endpoints: one trapezoid unbounded to the left, and right of each
  // endpoint v one more than the segments that start at v (chapter 14, Lemma 5).
  std::set<Index> ends;
  for (Index s = 0; s < M.segments(); ++s) ends.insert(M.segment(s).first), ends.insert(M.segment(s).second);
  EXPECT_EQ(live, 1 + M.segments() + ends.size());
  EXPECT_LE(live, 3 * M.segments() + 1);
  for (const Point& p : Q) {
    const TrapezoidMap::Hit h = M.locate(p);
    if (h.kind != TrapezoidMap::Hit::Kind::trapezoid) continue;
    const auto& t = T[h.id];
    if (t.leftp != TrapezoidMap::none) {
      EXPECT_EQ(t2::compare_xy(P[t.leftp], p), t2::NEGATIVE);
    }
    if (t.rightp != TrapezoidMap::none) {
      EXPECT_EQ(t2::compare_xy(p, P[t.rightp]), t2::NEGATIVE);
    }
    if (t.top != TrapezoidMap::none) {
      const auto [a, b] = M.segment(t.top);
      EXPECT_EQ(t2::orient(P[a], P[b], p), t2::NEGATIVE);
    }
    if (t.bottom != TrapezoidMap::none) {
      const auto [a, b] = M.segment(t.bottom);
      EXPECT_EQ(t2::orient(P[a], P[b], p), t2::POSITIVE);
    }
  }
}

TEST(TrapezoidMap, CertificatesOnGridsAndDelaunayMaps) {
  std::mt19937_64 rng(9);
  for (int round = 0; round < 4; ++round) {
    std::vector<Point> P;
    Faces F;
    grid(rng, 4 + 2 * round, 0, 0, P, F);
    const Subdivision S(P, F);
    std::vector<std::pair<Index, Index>> seg;
    for (Index h = 0; h < S.half_edges(); ++h)
      if (S.twin(h) == Subdivision::none || S.twin(h) > h) seg.push_back({S.org(h), S.dest(h)});
    const TrapezoidMap M(S.points(), seg, rng());
    expect_certified(M, S.points(), queries(S, rng, 200, 12));
  }
}

// Size and depth (de Berg et al., Theorems 6.3 and Lemma 6.8): the expected number of DAG nodes
// is O(n) — at most 3n + 1 leaves, and an expected O(1) new nodes per insertion; 20n is a loose
// bound on what a random order gives. The mean number of nodes a query visits is at most
// 1 + 12 H_n in expectation, and the longest path exceeds 3·20·ln(n + 1) with probability at
// most 2/(n + 1)^(20 ln 1.25 − 3) < 2/(n + 1)^1.46.
TEST(TrapezoidMap, SizeAndDepthAreWithinTheBounds) {
  std::mt19937_64 rng(10);
  for (const std::size_t n : {300u, 3000u}) {
    const Subdivision S = delaunay_map(rng, n, 4000);
    std::vector<std::pair<Index, Index>> seg;
    for (Index h = 0; h < S.half_edges(); ++h)
      if (S.twin(h) == Subdivision::none || S.twin(h) > h) seg.push_back({S.org(h), S.dest(h)});
    const TrapezoidMap M(S.points(), seg, rng());
    expect_certified(M, S.points(), {});
    const double m = double(seg.size());
    EXPECT_LE(double(M.nodes()), 20 * m);
    EXPECT_GE(M.nodes(), seg.size());  // not a tautology the other way: every segment has a y-node
    EXPECT_LE(double(M.depth()), 60 * std::log(m + 1));
    double H = 0;
    for (std::size_t i = 1; i <= seg.size(); ++i) H += 1.0 / double(i);
    std::uniform_real_distribution<double> d(-4000, 4000);
    double steps = 0;
    std::size_t longest = 0;
    const int k = 2000;
    for (int i = 0; i < k; ++i) {
      const double x = d(rng), y = d(rng);  // in this order (a call's arguments have none)
      const std::size_t s = M.locate(Point::cartesian(x, y)).steps;
      steps += double(s), longest = std::max(longest, s);
    }
    EXPECT_LE(steps / k, 1 + 12 * H);
    EXPECT_LE(longest, M.depth());  // depth() is the longest path of all
    RecordProperty("nodes_per_segment_" + std::to_string(n), std::to_string(double(M.nodes()) / m));
    RecordProperty("depth_" + std::to_string(n), std::to_string(M.depth()));
  }
}

// The traced construction builds the same map, and tells each insertion once: the segment, left
// to right; the trapezoids it crosses, which end destroyed; and the new ones, numbered on from
// the last insertion's. The traced query gives the same answer, one report per node it visits,
// each with the sign of the predicate the node asks, and a leaf exactly when it ends in one.
TEST(TrapezoidMap, TheTraceIsWhatTheMapDoes) {
  namespace tr = t2::trace;
  std::mt19937_64 rng(11);
  for (int round = 0; round < 3; ++round) {
    std::vector<Point> P;
    Faces F;
    grid(rng, 3 + 2 * round, -round, 1, P, F);  // vertical edges: ties in x
    const Subdivision S(P, F);
    std::vector<std::pair<Index, Index>> seg;
    for (Index h = 0; h < S.half_edges(); ++h)
      if (S.twin(h) == Subdivision::none || S.twin(h) > h) seg.push_back({S.org(h), S.dest(h)});
    const std::uint64_t seed = rng();
    std::vector<tr::Report> heard;
    std::vector<std::vector<Index>> crossed;
    const TrapezoidMap M(S.points(), seg, seed, [&](const tr::Report& r) {
      heard.push_back(r);
      crossed.emplace_back(r.face_list.begin(), r.face_list.end());
    });
    const TrapezoidMap U(S.points(), seg, seed);
    ASSERT_EQ(M.trapezoids().size(), U.trapezoids().size());
    EXPECT_EQ(M.nodes(), U.nodes());
    ASSERT_EQ(heard.size(), seg.size());
    std::set<std::pair<std::size_t, std::size_t>> told;
    std::uint32_t next = 1;  // trapezoid 0 is the first, the whole chart
    for (std::size_t k = 0; k < heard.size(); ++k) {
      const tr::Report& r = heard[k];
      EXPECT_EQ(r.event, tr::Event::trapezoid_split);
      EXPECT_EQ(r.trapezoids, &M);
      EXPECT_EQ(t2::compare_xy(P[r.at[0]], P[r.at[1]]), t2::NEGATIVE);
      told.insert({r.at[0], r.at[1]});
      EXPECT_EQ(r.faces[0], next);
      EXPECT_GT(r.faces[1], r.faces[0] + 1) << "at least the two trapezoids over and under it";
      next = r.faces[1];
      ASSERT_FALSE(crossed[k].empty());
      for (const Index t : crossed[k]) {
        EXPECT_LT(t, r.faces[0]);
        EXPECT_EQ(M.trapezoids()[t].node, TrapezoidMap::none) << "a crossed trapezoid is destroyed";
      }
    }
    EXPECT_EQ(next, M.trapezoids().size());
    for (const auto& [a, b] : seg) EXPECT_TRUE(told.count(std::minmax<std::size_t>(a, b)) || told.count({b, a}));
    std::uniform_int_distribution<int> c(-2 * round - 2, 2 * round + 8);
    for (int i = 0; i < 300; ++i) {
      const int x = c(rng), y = c(rng);
      const Point q = i % 3 ? Point::cartesian(x, y) : Point::cartesian(x + 0.5, y);  // vertices, edges
      std::vector<tr::Report> path;
      const TrapezoidMap::Hit h = M.locate(q, [&](const tr::Report& r) { path.push_back(r); });
      const TrapezoidMap::Hit u = U.locate(q);
      ASSERT_EQ(int(h.kind), int(u.kind));
      EXPECT_EQ(h.id, u.id);
      ASSERT_EQ(path.size(), h.steps);
      for (const tr::Report& r : path) {
        if (r.event == tr::Event::dag_x) EXPECT_EQ(r.sign, t2::compare_xy(q, P[r.at[0]]));
        if (r.event == tr::Event::dag_y) EXPECT_EQ(r.sign, t2::orient(P[r.at[0]], P[r.at[1]], q));
      }
      const bool leaf = path.back().event == tr::Event::dag_leaf;
      EXPECT_EQ(leaf, h.kind == TrapezoidMap::Hit::Kind::trapezoid);
      if (leaf) EXPECT_EQ(path.back().faces[0], h.id);
    }
  }
}

// On the back, the locator's trace names the subdivision's vertices: `input_of` maps each point
// of the back map to the vertex whose antipode it is, and the reports' points are those vertices.
TEST(TrapezoidLocator, TheTraceNamesTheVerticesOfTheMapOnEachSide) {
  namespace tr = t2::trace;
  std::mt19937_64 rng(12);
  const Subdivision D = delaunay_map(rng, 25, 10);
  std::vector<Point> P = D.points();
  Faces F;
  for (Index f = 0; f < D.faces(); ++f) F.push_back({D.org(D.first(f)), D.org(D.first(f) + 1), D.org(D.first(f) + 2)});
  antipodes(P, F);  // the same map on the back too: two closed charts
  const Subdivision S(P, F);
  std::size_t splits[2] = {0, 0};
  const t2::TrapezoidLocator L(S, 5, [&](const tr::Report& r) {
    ASSERT_EQ(r.event, tr::Event::trapezoid_split);
    const bool back = S.points()[r.at[0]].w() < 0;
    ++splits[back];
    EXPECT_EQ(S.points()[r.at[1]].w() < 0, back);
    for (std::size_t k = 0; k < r.input_of.size(); ++k) {
      const Point& v = S.points()[r.input_of[k]];
      EXPECT_EQ(r.trapezoids->point(Index(k)), back ? t2::antipode(v) : v);
    }
  });
  ASSERT_NE(L.chart(t2::TrapezoidLocator::front), nullptr);
  ASSERT_NE(L.chart(t2::TrapezoidLocator::back), nullptr);
  EXPECT_EQ(splits[0], L.chart(t2::TrapezoidLocator::front)->segments());
  EXPECT_EQ(splits[1], L.chart(t2::TrapezoidLocator::back)->segments());
  for (const Point& q : queries(S, rng, 100, 12)) {
    std::size_t nodes = 0;
    const Location l = L.locate(q, [&](const tr::Report& r) {
      if (r.event == tr::Event::dag_x) EXPECT_TRUE(S.points()[r.at[0]].w() != 0);
      nodes += r.event == tr::Event::dag_x || r.event == tr::Event::dag_y || r.event == tr::Event::dag_leaf;
    });
    EXPECT_EQ(l, L.locate(q));
    if (q.w() != 0) EXPECT_GT(nodes, 0u) << t2::to_string(q);
  }
}

}  // namespace
