// Kruskal's spanning tree and the largest empty circle animated (chapter 12; `t2 animate emst`,
// `t2 animate lec`, tools/t2/algorithms/proximity.cpp). Against facts found apart from the
// algorithms: the tree that Kruskal's reports build equals the untraced answer, Kruskal on all
// pairs by exact weights, and Prim's sorted weights (proximity_oracle.hpp); n − 1 edges are
// taken for distinct front sites; every dropped edge's ends were already joined by the edges
// taken before it (a union–find of the test's own); every candidate circle of the largest empty
// circle is empty (exact rational distances, and in_circle for a Voronoi vertex), passes through
// the sites that define it, and the answer's radius is the largest candidate's; the divide and
// conquer closest pair's last new closest is the answer, the brute force's, and each split
// divides its sites at its line; the pages of 200 points weigh at most 1 MB; bad and undefined
// input exit 2 and 3.
#include <fmt/format.h>
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "animate_testing.hpp"
#include "cli_testing.hpp"
#include "proximity_oracle.hpp"
#include "t2/gen/generate.hpp"
#include "t2/kernel/incircle.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/proximity/closest_pair.hpp"
#include "t2/proximity/empty_circle.hpp"
#include "t2/proximity/spanning_tree.hpp"
#include "t2/proximity/union_find.hpp"

namespace t2::testing {
namespace {

using trace::Event;
using trace::Report;

// The tree a traced run reports, and its dropped edges in order (each after the taken ones).
struct KruskalLog {
  std::vector<Edge> taken;
  std::vector<std::pair<Edge, std::size_t>> dropped;  // the edge, and how many were taken before it
  int candidates = 0;                                 // side triangulations shown
  bool forest_agrees = true;                          // the lent forest says what the event says
};

KruskalLog kruskal_log(const std::vector<Point>& P, std::vector<Edge>& answer) {
  KruskalLog log;
  answer = minimum_spanning_tree(std::span<const Point>(P), [&](const Report& r) {
    if (r.event == Event::candidates) {
      ++log.candidates;
      if (r.tr == nullptr || r.input_of.empty()) log.forest_agrees = false;
      return;
    }
    const Edge e{static_cast<std::uint32_t>(r.at[0]), static_cast<std::uint32_t>(r.at[1])};
    if (r.forest == nullptr || r.forest->root(e.first) != r.forest->root(e.second)) log.forest_agrees = false;
    if (r.event == Event::tree_edge) log.taken.push_back(e);
    if (r.event == Event::cycle_edge) log.dropped.emplace_back(e, log.taken.size());
  });
  return log;
}

std::vector<Point> small_integer_sites(std::mt19937& rng, int n, int range) {
  std::uniform_int_distribution<int> c(-range, range);
  std::vector<Point> P;
  for (int k = 0; k < n; ++k) P.emplace_back(1, c(rng), c(rng));
  return P;
}

TEST(KruskalTrace, TheReportedTreeIsTheAnswerAndAMinimumOne) {
  std::mt19937 rng(25);
  int dropped = 0;
  for (Parts parts : {Parts::front, Parts::back, Parts::mixed, Parts::front_omega, Parts::mixed_omega, Parts::omega})
    for (int n : {2, 3, 7, 16, 30}) {
      const std::vector<Point> P = proximity_sites_random(rng, parts, n, 6);
      SCOPED_TRACE(fmt::format("parts {}, n {}", static_cast<int>(parts), n));
      std::vector<Edge> answer;
      const KruskalLog log = kruskal_log(P, answer);
      EXPECT_EQ(log.taken, answer);
      EXPECT_EQ(answer, minimum_spanning_tree(std::span<const Point>(P)));  // the trace changes nothing
      EXPECT_EQ(answer, kruskal_all_pairs(P));
      EXPECT_EQ(tree_weights(P, answer), prim_weights(P));
      EXPECT_TRUE(log.forest_agrees);
      // a dropped edge's ends are joined by the edges taken before it
      for (const auto& [e, before] : log.dropped) {
        UnionFind uf(P.size());
        for (std::size_t k = 0; k < before; ++k) uf.join(log.taken[k].first, log.taken[k].second);
        EXPECT_EQ(uf.find(e.first), uf.find(e.second)) << e.first << " " << e.second;
        ++dropped;
      }
      const bool front = std::any_of(P.begin(), P.end(), [](const Point& p) { return p.w() > 0; }),
                 back = std::any_of(P.begin(), P.end(), [](const Point& p) { return p.w() < 0; });
      EXPECT_EQ(log.candidates, (n >= 2) * (int(front) + int(back))) << "one triangulation a side with sites";
    }
  EXPECT_GT(dropped, 20);
}

TEST(KruskalTrace, DistinctFrontSitesTakeNMinusOneDelaunayEdges) {
  gen::Options o;
  for (o.seed = 1; o.seed <= 4; ++o.seed) {
    o.n = 40 * o.seed;
    const std::vector<Point> P = gen::points(gen::Kind::uniform, o);
    std::vector<Edge> answer;
    const KruskalLog log = kruskal_log(P, answer);
    EXPECT_EQ(log.taken.size(), P.size() - 1);
    EXPECT_EQ(log.candidates, 1);
    EXPECT_GT(log.dropped.size(), 0u);
    EXPECT_EQ(tree_weights(P, answer), prim_weights(P));
  }
}

// A drawn position, exact.
struct Q {
  mpq_class x, y;
};
Q drawn(const Point& p) { return {mpq_class(p.x()) / mpq_class(p.w()), mpq_class(p.y()) / mpq_class(p.w())}; }
Q drawn(const ExactPoint& p) { return {mpq_class(p.x()) / mpq_class(p.w()), mpq_class(p.y()) / mpq_class(p.w())}; }
mpq_class dist2(const Q& a, const Q& b) { return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y); }

TEST(EmptyCircleTrace, EveryCandidateIsEmptyAndTheAnswerIsTheLargest) {
  std::mt19937 rng(13);
  int vertices = 0, crossings = 0, outside = 0, midpoints = 0;
  std::vector<std::vector<Point>> inputs;
  for (int n : {3, 5, 9, 20, 40}) inputs.push_back(small_integer_sites(rng, n, 9));
  for (int n : {6, 25}) inputs.push_back(proximity_sites_random(rng, Parts::back, n, 9));
  inputs.push_back({Point(1, 0, 0), Point(1, 4, 2), Point(1, 6, 3), Point(1, 10, 5)});  // collinear
  gen::Options o;
  o.n = 60;
  inputs.push_back(gen::points(gen::Kind::uniform, o));
  inputs.push_back(gen::points(gen::Kind::grid, o));
  for (const auto& P : inputs) {
    SCOPED_TRACE(fmt::format("{} sites", P.size()));
    bool have = false;
    mpq_class largest;
    const EmptyCircle c = largest_empty_circle(std::span<const Point>(P), [&](const Report& r) {
      ASSERT_EQ(r.event, Event::empty_circle);
      ASSERT_NE(r.circle, nullptr);
      const EmptyCircle& k = *r.circle;
      const Q z = drawn(k.center);
      ASSERT_GE(k.on_circle.size(), 2u);
      ASSERT_EQ((k.center.w() > 0), (P[0].w() > 0)) << "the centre is on the sites' side";
      for (auto s : k.on_circle) EXPECT_EQ(dist2(z, drawn(P[s])), k.radius2) << "p" << s << " is on the circle";
      for (const Point& p : P) EXPECT_GE(dist2(z, drawn(p)), k.radius2) << "no site inside";
      if (k.on_circle.size() == 3) {
        ++vertices;
        outside += r.sign == NEGATIVE;
        const Point &a = P[r.at[0]], &b = P[r.at[1]], &d = P[r.at[2]];
        const int o3 = static_cast<int>(orient(a, b, d));
        ASSERT_NE(o3, 0);
        if (P[0].w() > 0) {  // in_circle of three front sites: POSITIVE inside when counter-clockwise
          for (const Point& p : P) EXPECT_LE(o3 * static_cast<int>(in_circle(a, b, d, p)), 0) << "in_circle: inside";
        }
      } else if (r.at[2] != Report::none) {
        ++crossings;  // the centre lies on the hull edge at[2] at[3]
        const Q a = drawn(P[r.at[2]]), b = drawn(P[r.at[3]]);
        EXPECT_EQ((b.x - a.x) * (z.y - a.y), (b.y - a.y) * (z.x - a.x));
        EXPECT_LE((z.x - a.x) * (z.x - b.x) + (z.y - a.y) * (z.y - b.y), 0) << "between its ends";
      } else {
        ++midpoints;
      }
      if (r.sign == POSITIVE) {
        EXPECT_TRUE(!have || k.radius2 >= largest) << "a new best is no smaller";
        largest = k.radius2;
        have = true;
      } else if (r.sign == ZERO) {
        EXPECT_TRUE(have && k.radius2 <= largest) << "no better than the best";
      }
    });
    const EmptyCircle plain = largest_empty_circle(std::span<const Point>(P));
    EXPECT_EQ(c.center, plain.center);
    EXPECT_EQ(c.on_circle, plain.on_circle);
    ASSERT_TRUE(have);
    EXPECT_EQ(plain.radius2, largest) << "the answer's radius is the largest candidate's";
  }
  EXPECT_GT(vertices, 10);
  EXPECT_GT(crossings, 10);
  EXPECT_GT(outside, 0);
  EXPECT_GT(midpoints, 0);
}

// Shamos–Hoey traced: the last new closest pair is the answer, which is the brute force's; every
// split's halves are the sites left and right of its line, and every strip lies in a split.
TEST(DivideTrace, TheLastNewClosestIsTheAnswerAndTheSplitsDivide) {
  std::mt19937 rng(7);
  int splits = 0, compared = 0;
  for (int n : {2, 3, 4, 9, 30, 80}) {
    const std::vector<Point> P = small_integer_sites(rng, n, 40);
    SCOPED_TRACE(n);
    std::pair<std::size_t, std::size_t> last{Report::none, Report::none};
    std::map<std::size_t, std::vector<std::size_t>> split_at;  // a split's sites, by its line's site
    const auto got = closest_pair_divide(std::span<const Point>(P), [&](const Report& r) {
      if (r.event == Event::split) {
        ++splits;
        const std::vector<std::size_t> v(r.chain.begin(), r.chain.end());
        const auto at = std::find(v.begin(), v.end(), r.at[0]);
        ASSERT_NE(at, v.end());
        ASSERT_GE(at - v.begin(), 1);
        const mpq_class xm = drawn(P[r.at[0]]).x;
        for (auto it = v.begin(); it != v.end(); ++it)  // sorted by x: left of the line, then right
          EXPECT_TRUE(it < at ? drawn(P[*it]).x <= xm : drawn(P[*it]).x >= xm);
        split_at[r.at[0]] = v;
      } else if (r.event == Event::strip) {  // after both halves: the strip of the split at its line
        ASSERT_TRUE(split_at.count(r.at[0]));
        const auto& v = split_at[r.at[0]];
        for (std::size_t i : r.chain) EXPECT_NE(std::find(v.begin(), v.end(), i), v.end());
      } else if (r.event == Event::compare_pair) {
        ++compared;
        if (r.sign == POSITIVE) last = std::minmax(r.at[0], r.at[1]);
      }
    });
    const auto brute = closest_pair_brute(std::span<const Point>(P));
    EXPECT_EQ(got, closest_pair_divide(std::span<const Point>(P)));
    EXPECT_EQ(got, brute);
    EXPECT_EQ(pair_weight(P[got.first], P[got.second]), pair_weight(P[brute.first], P[brute.second]));
    if (P[0].w() > 0 && !(P[got.first] == P[got.second])) {
      EXPECT_EQ(last.first, got.first);
      EXPECT_EQ(last.second, got.second);
    }
  }
  EXPECT_GT(splits, 20);
  EXPECT_GT(compared, 100);
}

class AnimateProximity : public CliTest {
 protected:
  /// `t2 animate algo p.t2`'s page, which must weigh at most 1 MB, decoded; and in `plain` what
  /// `t2 command p.t2` prints.
  std::vector<PageStep> page(const std::string& algo, const std::string& command, std::string& plain) {
    const Result r = t2("animate " + algo + " p.t2 -o page.html");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_LE(fs::file_size(dir_ / "page.html"), 1u << 20) << algo;
    const Result p = t2(command + " p.t2");
    EXPECT_EQ(p.status, 0) << p.err;
    plain = p.out;
    auto steps = page_steps(slurp(dir_ / "page.html"));
    EXPECT_GE(steps.size(), 3u);
    if (!steps.empty()) {
      EXPECT_EQ(steps.back().step.at("kind"), "answer") << algo;
    }
    return steps;
  }
};

TEST_F(AnimateProximity, PagesEndWithTheAnswerAndWeighAtMostAMegabyte) {
  ASSERT_EQ(t2("gen uniform --n 200 --seed 3 -o p.t2").status, 0);  // the most t2 animate takes
  // emst: one lecture step per tree edge, the triangulation first, the answer last
  std::string plain;
  auto steps = page("emst", "emst", plain);
  ASSERT_GE(steps.size(), 3u);
  std::vector<std::vector<std::size_t>> expected, got;
  std::istringstream lines(plain);
  for (std::size_t a, b; lines >> a >> b;) expected.push_back({a, b});
  EXPECT_EQ(steps[1].step.at("kind"), "candidates");
  for (const auto& e : steps.back().edges) got.push_back({e[0], e[1]});
  EXPECT_EQ(got, expected);
  std::size_t takes = 0, lecture = 0;
  for (const auto& s : steps) {
    takes += s.step.at("kind") == "take";
    lecture += s.step.at("depth") == 0;
  }
  EXPECT_EQ(takes, 199u);
  EXPECT_EQ(lecture, 199u + 3) << "the input, the triangulation, each edge taken, the answer";
  // lec: the answer is t2 lec's, its circle drawn
  steps = page("lec", "lec", plain);
  ASSERT_GE(steps.size(), 3u);
  std::istringstream out(plain);
  std::string w, x, y;
  out >> w >> x >> y;
  EXPECT_TRUE(has(steps.back().step.at("text").get<std::string>(), fmt::format("centre [{}, {}, {}]", w, x, y)))
      << steps.back().step.at("text") << " vs " << plain;
  EXPECT_TRUE(has(steps.back().svg, "stroke-dasharray")) << "the circle is drawn";
  // closest-pair-divide: the answer is t2 closest-pair --algorithm divide's
  steps = page("closest-pair-divide", "closest-pair --algorithm divide", plain);
  ASSERT_GE(steps.size(), 3u);
  std::istringstream po(plain);
  std::size_t i = 0, j = 0;
  po >> i >> j;
  EXPECT_EQ(steps.back().step.at("chain"), nlohmann::json({i, j})) << plain;
}

TEST_F(AnimateProximity, BothSidesAndOmegaAnimateTheTreeButNotTheEmptyCircle) {
  write("mixed.t2", "0 0\n3 0\n0 4\n-1 1 1\n-1 2 5\n0 1 1\n");
  Result r = t2("animate emst mixed.t2 -o e.html");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto steps = page_steps(slurp(dir_ / "e.html"));
  EXPECT_EQ(steps.back().edges.size(), 5u);
  EXPECT_TRUE(has(slurp(dir_ / "e.html"), "beyond infinity") || has(slurp(dir_ / "e.html"), "Omega"));
  write("out.html", "old");
  r = t2("animate lec mixed.t2 -o out.html");
  EXPECT_EQ(r.status, 3);
  EXPECT_TRUE(has(r.err, "mixed.t2")) << r.err;
  EXPECT_TRUE(has(r.err, "Omega")) << r.err;
  write("same.t2", "1 1\n2 2 2\n");
  r = t2("animate lec same.t2 -o out.html");
  EXPECT_EQ(r.status, 3);
  EXPECT_TRUE(has(r.err, "all sites equal")) << r.err;
  write("empty.t2", "# nothing\n");
  r = t2("animate lec empty.t2 -o out.html");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(has(r.err, "empty.t2")) << r.err;
  r = t2("animate closest-pair-divide mixed.t2 -o out.html");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(has(r.err, "front points only")) << r.err;
  write("bad.t2", "0 0\n1 x\n");
  for (const char* algo : {"emst", "lec", "closest-pair-divide"}) {
    r = t2(std::string("animate ") + algo + " bad.t2 -o out.html");
    EXPECT_EQ(r.status, 2) << algo;
    EXPECT_TRUE(has(r.err, "bad.t2:2")) << r.err;
  }
  EXPECT_EQ(slurp(dir_ / "out.html"), "old");
  r = t2("animate emst empty.t2 -o e.html");  // no point: no edge, but a page
  EXPECT_EQ(r.status, 0) << r.err;
}

}  // namespace
}  // namespace t2::testing
