// `t2 animate walk` and `t2 animate kdtree` (tools/t2/algorithms/location.cpp, range.cpp), the
// recorders called through the registry and the pages through the tool:
// - walk: each query's recorded answer is the untraced t2::walk's, t2::locate_brute's and that
//   of an oracle of this file (exact orient tests on every triangle, least face first); each
//   region the walk enters shares the crossed edge (or the vertex left) with the one before;
//   the located step's path is the triangles of its debugging steps, in order; one lecture
//   step per query;
// - kdtree: the answer is KdTree::report's untraced answer and the brute force of `contains`;
//   each split drawn at a level passes through one of that level's splitting points (exact
//   orient) and runs along the right axis; as many splits as the tree has inner nodes; as many
//   node steps as KdTree::visits counts; each node's drawn cell holds the points the step names
//   (exact point-in-polygon of T², closed);
// - trapezoid: the answers are the walk's; each insertion is an edge of the map, as many as the
//   maps have segments; each query's node steps are the DAG nodes the untraced query visits;
// - pages of 100 and 200 points weigh at most 1 MB (printed; the trapezoidal map's at 100, its
//   200-point page taking half a minute to draw); bad input exits 2 or 3.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <set>
#include <string>
#include <vector>

#include "algorithms/location.hpp"
#include "algorithms/range.hpp"
#include "algorithms/registry.hpp"
#include "cli_testing.hpp"
#include "t2/gen/generate.hpp"
#include "t2/kernel/bbox.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/kernel/point_in_polygon.hpp"
#include "t2/location/trapezoid_locate.hpp"
#include "t2/location/walk.hpp"
#include "t2/range/kdtree.hpp"
#include "t2/trace/recording.hpp"

namespace t2::testing {
namespace {

using trace::Depth;
using trace::Recording;
using trace::Step;
using Index = Subdivision::Index;

Recording record(const char* algo, const std::vector<Point>& P) {
  const auto* a = t2cli::algorithms::find(algo);
  EXPECT_TRUE(a != nullptr && a->record) << algo;
  Recording rec;
  a->record(P, "input.t2", rec);
  return rec;
}

std::vector<std::vector<Point>> inputs() {
  std::vector<std::vector<Point>> v;
  gen::Options o;
  for (o.seed = 1; o.seed <= 3; ++o.seed) {
    o.n = 20 + 30 * o.seed;
    v.push_back(gen::points(gen::Kind::uniform, o));
    v.push_back(gen::points(gen::Kind::grid, o));  // collinear triples, points on edges
    v.push_back(gen::points(gen::Kind::both_sides, o));
  }
  return v;
}

// The oracle: the least face whose closed triangle (Δ > 0: the cone of its vertices) holds q,
// by the signs of the three edges, then what of it q is.
std::string oracle(const Subdivision& S, const Point& q) {
  const auto& P = S.points();
  for (Index f = 0; f < S.faces(); ++f) {
    std::array<Index, 3> v{};
    for (Index k = 0; k < 3; ++k) v[k] = S.org(S.first(f) + k);
    EXPECT_EQ(orient(P[v[0]], P[v[1]], P[v[2]]), POSITIVE);
    std::array<Sign, 3> s{};
    for (Index k = 0; k < 3; ++k) s[k] = orient(P[v[k]], P[v[(k + 1) % 3]], q);
    if (std::any_of(s.begin(), s.end(), [](Sign x) { return x == NEGATIVE; })) continue;
    for (Index k = 0; k < 3; ++k)
      if (P[v[k]] == q) return fmt::format("vertex {} {}", f, k);
    for (Index k = 0; k < 3; ++k)
      if (s[k] == ZERO) return fmt::format("edge {} {}", f, k);
    return fmt::format("face {}", f);
  }
  return "outside";
}

bool is_edge_of(const trace::Tri& t, std::size_t a, std::size_t b) {
  for (int k = 0; k < 3; ++k)
    if ((t[k] == a && t[(k + 1) % 3] == b) || (t[k] == b && t[(k + 1) % 3] == a)) return true;
  return false;
}

bool has_vertex(const trace::Tri& t, std::size_t v) { return std::find(t.begin(), t.end(), v) != t.end(); }

TEST(AnimateWalk, AnswersAreTheWalksAndTheOraclesAndEachStepIsAdjacent) {
  int crosses = 0, leaves = 0, outside = 0, vertices = 0;
  for (const auto& P : inputs()) {
    SCOPED_TRACE(fmt::format("{} points", P.size()));
    const auto map = t2cli::algorithms::delaunay_map(P);  // the Delaunay triangles
    const Subdivision& S = *map;
    const std::vector<Point> Q = t2cli::algorithms::animation_queries(P);
    ASSERT_EQ(Q.size(), 7u);
    EXPECT_LT(Q[5].w(), 0) << "a query on the back";
    EXPECT_EQ(Q[6].w(), 0) << "a query on Omega";
    const Recording rec = record("walk", P);
    ASSERT_EQ(rec.steps().front().kind, "map");
    ASSERT_EQ(rec.back().kind, "answer");
    EXPECT_EQ(rec.at(Depth::lecture).size(), 2 + Q.size()) << "the map, one step per query, the answers";
    std::size_t k = 0;
    std::vector<trace::Tri> path;
    const Step* before = nullptr;  // the last debugging step of this query
    bool in_face = false;          // the walk is in the triangle path.back()
    for (const Step& s : rec.steps()) {
      if (s.kind == "cross" || s.kind == "leave") {
        if (s.kind == "cross") {
          ASSERT_EQ(s.edges.size(), 1u);
          ++crosses;
        } else {
          ++leaves;
        }
        const bool into_face = s.touched.size() > path.size();
        if (into_face) {
          const trace::Tri& t = s.touched.back();
          if (s.kind == "cross") {
            EXPECT_TRUE(is_edge_of(t, s.edges[0][0], s.edges[0][1])) << s.text;
          } else {
            EXPECT_TRUE(has_vertex(t, s.points[0])) << s.text;
          }
          if (s.kind == "cross" && in_face) {  // across an edge of the triangle entered last
            EXPECT_TRUE(is_edge_of(path.back(), s.edges[0][0], s.edges[0][1])) << s.text;
          }
          if (s.kind == "leave") {  // from the vertex the walk stands at
            ASSERT_TRUE(before != nullptr && before->kind == "vertex") << s.text;
            EXPECT_EQ(before->points.at(0), s.points.at(0)) << s.text;
          }
          path.push_back(t);
        } else {
          ++outside;
        }
        in_face = into_face;
        EXPECT_EQ(s.touched, path) << "the path so far";
        before = &s;
      } else if (s.kind == "vertex") {
        ++vertices;
        if (in_face) {  // a corner of the triangle entered last
          EXPECT_TRUE(has_vertex(path.back(), s.points.at(0))) << s.text;
        }
        in_face = false;
        before = &s;
      } else if (s.kind == "located") {
        ASSERT_LT(k, Q.size());
        const std::string want = to_string(t2::walk(S, Q[k], S.org(0)));  // untraced
        EXPECT_EQ(want, to_string(locate_brute(S, Q[k])));
        EXPECT_EQ(want, oracle(S, Q[k]));
        EXPECT_NE(s.text.find("(t2 locate: " + want + ")"), std::string::npos) << s.text;
        ASSERT_FALSE(s.overlay.points.empty());
        EXPECT_EQ(s.overlay.points.back().point, Q[k]);
        EXPECT_EQ(s.overlay.points.back().style.label, fmt::format("q{}", k));
        // the path, then (for a face) the answer triangle first
        std::vector<trace::Tri> drawn = s.touched;
        if (want.rfind("face", 0) == 0) {
          ASSERT_FALSE(drawn.empty());
          const Index f = static_cast<Index>(std::stoul(want.substr(5)));
          EXPECT_EQ(drawn.front(), (trace::Tri{S.org(S.first(f)), S.org(S.first(f) + 1), S.org(S.first(f) + 2)}));
          drawn.erase(drawn.begin());
          EXPECT_EQ(path.back(), s.touched.front()) << "the walk ends in the answer";
        }
        EXPECT_EQ(drawn, path);
        ++k;
        path.clear();
        before = nullptr;
        in_face = false;
      }
    }
    EXPECT_EQ(k, Q.size());
  }
  EXPECT_GT(crosses, 100);
  EXPECT_GT(leaves, 5);
  EXPECT_GT(outside, 5);
  EXPECT_GT(vertices, 5);
}

// The number of inner nodes of the kd-tree of m points (kdtree.hpp: a node of more than kLeaf
// points splits at its median m/2 into m/2 and m − m/2 − 1 points).
std::size_t inner_nodes(std::size_t m) {
  return m <= KdTree::kLeaf ? 0 : 1 + inner_nodes(m / 2) + inner_nodes(m - m / 2 - 1);
}

TEST(AnimateKdTree, AnswerIsTheTreesAndBruteForceAndEverySplitPassesThroughItsPoint) {
  std::vector<std::vector<Point>> in = inputs();
  gen::Options o;
  o.n = 200, o.seed = 7;
  in.push_back(gen::points(gen::Kind::uniform, o));
  std::vector<Point> back;
  for (const auto& p : in[0]) back.push_back(antipode(p));  // the back side alone
  back.push_back(Point(0, 1, 2));
  in.push_back(back);
  for (const auto& P : in) {
    SCOPED_TRACE(fmt::format("{} points", P.size()));
    const auto r = t2cli::algorithms::animation_window(P);
    ASSERT_TRUE(r.has_value());
    const KdTree T{std::span<const Point>(P)};
    std::vector<std::size_t> brute;
    for (std::size_t i = 0; i < P.size(); ++i)
      if (contains(*r, to_exact(P[i]))) brute.push_back(i);
    ASSERT_EQ(T.report(*r), brute);
    EXPECT_FALSE(brute.empty());
    const Recording rec = record("kdtree", P);
    ASSERT_EQ(rec.back().kind, "answer");
    std::vector<std::size_t> got = rec.back().points;
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, brute);
    std::size_t splits = 0, nodes = 0, objects = 0, cells = 0;
    for (const Step& s : rec.steps()) {
      if (s.kind == "node") {
        ++nodes;
        if (s.overlay.polygons.size() == 2) {  // the window and the node's cell (not the root's)
          const Polygon cell = s.overlay.polygons[1].polygon();
          for (const std::size_t i : s.points) EXPECT_NE(locate(cell, P[i]), NEGATIVE) << s.text << " p" << i;
          ++cells;
        }
      }
      if (s.kind != "level") continue;
      const int depth = std::stoi(s.text.substr(6));
      const Point along = depth % 2 ? Point(0, 1, 0) : Point(0, 0, 1);  // the split's direction
      std::vector<std::pair<Point, Point>> lines;
      for (const auto& l : s.overlay.lines) lines.emplace_back(l.a.point, l.b.point);
      for (const auto& g : s.overlay.segments) lines.emplace_back(g.a.point, g.b.point);
      ASSERT_GT(lines.size(), objects);
      for (std::size_t j = objects; j < lines.size(); ++j) {  // the splits new at this level
        const auto [a, b] = lines[j];
        EXPECT_EQ(orient(a, b, along), ZERO) << s.text;
        EXPECT_TRUE(std::any_of(s.points.begin(), s.points.end(),
                                [&, a = a, b = b](std::size_t i) { return orient(a, b, P[i]) == ZERO; }))
            << s.text;
      }
      objects = lines.size();
      splits += s.points.size();
    }
    EXPECT_EQ(splits, inner_nodes(T.tree_order(0).size()) + inner_nodes(T.tree_order(1).size()));
    EXPECT_EQ(nodes, T.visits(*r));
    EXPECT_GT(cells, 0u);
  }
}

class AnimateLocation : public CliTest {};

TEST(AnimateTrapezoid, AnswersAreTheWalksAndEachInsertionIsAnEdgeOfTheMap) {
  for (const auto& P : inputs()) {
    SCOPED_TRACE(fmt::format("{} points", P.size()));
    const auto map = t2cli::algorithms::delaunay_map(P);  // the Delaunay triangles
    const Subdivision& S = *map;
    const Recording rec = record("trapezoid", P), walk = record("walk", P);
    ASSERT_EQ(rec.steps().front().kind, "map");
    ASSERT_EQ(rec.back().kind, "answer");
    EXPECT_EQ(rec.back().text, walk.back().text) << "the same answers as the walk";
    EXPECT_EQ(rec.back().triangles, walk.back().triangles);
    const TrapezoidLocator L(S, 0x7A9E201D);  // the recorder's seed
    std::size_t segments = 0;
    for (const auto side : {TrapezoidLocator::front, TrapezoidLocator::back})
      if (L.chart(side)) segments += L.chart(side)->segments();
    const std::vector<Point> Q = t2cli::algorithms::animation_queries(P);
    EXPECT_EQ(rec.at(Depth::lecture).size(), 1 + segments + 1 + Q.size() + 1)
        << "the map, one step per insertion, the maps built, one per query, the answers";
    std::size_t inserts = 0, nodes = 0, k = 0;
    for (const Step& s : rec.steps()) {
      if (s.kind == "insert") {
        ++inserts;
        ASSERT_EQ(s.edges.size(), 1u);
        bool edge = false;
        for (Index h = 0; h < S.half_edges(); ++h) edge = edge || (S.org(h) == s.edges[0][0] && S.dest(h) == s.edges[0][1]) ||
                                                           (S.org(h) == s.edges[0][1] && S.dest(h) == s.edges[0][0]);
        EXPECT_TRUE(edge) << s.text;
      } else if (s.kind == "node") {
        ++nodes;
      } else if (s.kind == "located") {
        ASSERT_LT(k, Q.size());
        const Point& q = Q[k++];
        const int side = q.w() > 0 ? 0 : q.w() < 0 ? 1 : -1;
        const TrapezoidMap* M = side < 0 ? nullptr : L.chart(side == 0 ? TrapezoidLocator::front : TrapezoidLocator::back);
        EXPECT_EQ(nodes, M ? M->locate(side == 0 ? q : antipode(q)).steps : 0u) << s.text;
        nodes = 0;
      }
    }
    EXPECT_EQ(inserts, segments);
    EXPECT_EQ(k, Q.size());
  }
}

TEST_F(AnimateLocation, PagesOfTwoHundredPointsWeighAtMostOneMegabyte) {
  for (const char* algo : {"walk", "kdtree"})
    for (int n : {200}) {  // the maximum (100 points: about half as heavy)
      ASSERT_EQ(t2(fmt::format("gen uniform --n {} --seed 5 -o p.t2", n)).status, 0);
      const Result r = t2(fmt::format("animate {} p.t2 -o page.html", algo));
      ASSERT_EQ(r.status, 0) << r.err;
      const auto bytes = fs::file_size(dir_ / "page.html");
      std::cout << "t2 animate " << algo << ", " << n << " points: " << bytes << " bytes\n";
      EXPECT_LE(bytes, 1000000u) << algo << " " << n;
    }
  ASSERT_EQ(t2("gen uniform --n 100 --seed 5 -o p.t2").status, 0);
  ASSERT_EQ(t2("animate trapezoid p.t2 -o page.html").status, 0);
  std::cout << "t2 animate trapezoid, 100 points: " << fs::file_size(dir_ / "page.html") << " bytes\n";
  EXPECT_LE(fs::file_size(dir_ / "page.html"), 1000000u);
  ASSERT_EQ(t2("gen both-sides --n 60 --seed 2 -o b.t2").status, 0);
  for (const char* algo : {"walk", "kdtree", "trapezoid"})
    EXPECT_EQ(t2(fmt::format("animate {} b.t2 -o b.html", algo)).status, 0);
}

TEST_F(AnimateLocation, BadAndUndefinedInputExitWithTheFileNamed) {
  write("out.html", "old");
  write("line.t2", "0 0\n1 1\n2 2\n");  // no triangle: nothing to locate in
  Result r = t2("animate walk line.t2 -o out.html");
  EXPECT_EQ(r.status, 3);
  EXPECT_TRUE(has(r.err, "line.t2")) << r.err;
  EXPECT_TRUE(has(r.err, "no triangle")) << r.err;
  r = t2("animate trapezoid line.t2 -o out.html");
  EXPECT_EQ(r.status, 3);
  EXPECT_TRUE(has(r.err, "line.t2")) << r.err;
  write("omega.t2", "0 1 0\n0 1 1\n");  // no point off Omega: no window
  r = t2("animate kdtree omega.t2 -o out.html");
  EXPECT_EQ(r.status, 3);
  EXPECT_TRUE(has(r.err, "omega.t2")) << r.err;
  write("bad.t2", "0 0\n1 x\n");
  for (const char* algo : {"walk", "kdtree", "trapezoid"}) {
    r = t2(fmt::format("animate {} bad.t2 -o out.html", algo));
    EXPECT_EQ(r.status, 2);
    EXPECT_TRUE(has(r.err, "bad.t2:2")) << r.err;
  }
  EXPECT_EQ(slurp(dir_ / "out.html"), "old");
}

}  // namespace
}  // namespace t2::testing
