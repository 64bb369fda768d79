// The trace recorders of t2/trace: what they record last is the algorithm's answer, computed by
// the algorithm itself (recording changes nothing), and the recorded steps agree with
// properties of the answer that the recorder does not know (a popped point is no vertex; the
// candidate Jarvis's recorder follows is the vertex the march chose; a flip's two triangles
// are in the triangulation after it).
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <set>
#include <span>
#include <vector>

#include "animate_testing.hpp"
#include "t2/gen/generate.hpp"
#include "t2/hull.hpp"
#include "t2/trace/delaunay_recorder.hpp"
#include "t2/trace/hull_recorder.hpp"
#include "t2/trace/recording.hpp"
#include "t2/triangulation/delaunay.hpp"

namespace t2 {
namespace {

using t2::testing::sorted_triangles;

using trace::Depth;
using trace::HullAlgo;
using trace::HullRecorder;
using trace::Recording;

std::vector<Point> make(gen::Kind k, std::size_t n, std::uint64_t seed) {
  gen::Options o;
  o.n = n;
  o.seed = seed;
  return gen::points(k, o);
}

std::vector<std::size_t> iota_of(std::size_t n) {
  std::vector<std::size_t> v(n);
  std::iota(v.begin(), v.end(), std::size_t{0});
  return v;
}

// Front inputs of several shapes: random, in a disk, on a circle (all vertices), on a square's
// boundary (points inside hull edges), on an integer grid (collinear triples and duplicates).
std::vector<std::vector<Point>> front_inputs() {
  std::vector<std::vector<Point>> v;
  for (std::uint64_t seed = 1; seed <= 4; ++seed)
    for (gen::Kind k : {gen::Kind::uniform, gen::Kind::disk, gen::Kind::circle, gen::Kind::boundary, gen::Kind::grid})
      v.push_back(make(k, 10 + 7 * seed, seed));
  return v;
}

TEST(HullRecorder, GrahamRecordsItsAnswerLastAndPopsNoVertex) {
  for (const auto& P : front_inputs()) {
    Recording rec;
    HullRecorder r(HullAlgo::graham, P, front_chart(), rec);
    const auto h = graham(std::span<const Point>(P), iota_of(P.size()), front_chart(), r);
    ASSERT_FALSE(rec.empty());
    EXPECT_EQ(rec.back().chain, h);
    EXPECT_EQ(h, graham(std::span<const Point>(P), iota_of(P.size()), front_chart()));  // NoTrace: the same
    std::size_t pushes = 0, pops = 0, considers = 0;
    for (const auto& s : rec.steps()) {
      if (s.kind == "pop") {
        ++pops;
        ASSERT_FALSE(s.points.empty());
        EXPECT_EQ(std::count(h.begin(), h.end(), s.points[0]), 0) << s.text;  // popped: never a vertex
        EXPECT_EQ(s.depth, Depth::lecture);
      }
      if (s.kind == "push") ++pushes;
      if (s.kind == "consider") {
        ++considers;
        EXPECT_EQ(s.depth, Depth::debugging);
      }
    }
    EXPECT_EQ(pushes, considers);         // every considered point is pushed once
    EXPECT_EQ(pushes + 1 - pops, h.size());  // the pivot, plus the pushes, less the pops
  }
}

TEST(HullRecorder, JarvisFollowsTheCandidateToEveryVertex) {
  for (const auto& P : front_inputs()) {
    Recording rec;
    HullRecorder r(HullAlgo::jarvis, P, front_chart(), rec);
    const auto h = jarvis(std::span<const Point>(P), iota_of(P.size()), front_chart(), r);
    EXPECT_TRUE(r.consistent());
    std::vector<std::size_t> vertices;
    for (const auto& s : rec.steps())
      if (s.kind == "vertex") vertices.push_back(s.points[0]);
    EXPECT_EQ(vertices, h);
    EXPECT_EQ(rec.back().chain, h);
    // The last candidate is the first vertex: the march closes the hull.
    ASSERT_EQ(rec.back().kind, "consider");
    EXPECT_EQ(rec.back().points[1], h.front());
  }
}

// Points on both sides of T² (a share 0.4 behind), 12 + seed of them.
std::vector<Point> both_sides(std::uint64_t seed) {
  gen::Options o;
  o.n = 12 + seed;
  o.seed = seed;
  o.back = 0.4;
  return gen::points(gen::Kind::both_sides, o);
}

TEST(HullRecorder, MergeRecordsTheHullAtItsLastBridge) {
  std::size_t bridged = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const auto P = both_sides(seed);
    Recording rec;
    HullRecorder r(HullAlgo::merge, P, lex_chart(), rec);
    const auto h = merge_hull(std::span<const Point>(P), r);
    EXPECT_EQ(h, merge_hull(std::span<const Point>(P)));
    // After the last bridge no insertion changes a hull of three or more vertices untraced.
    auto last = std::find_if(rec.steps().rbegin(), rec.steps().rend(), [](const auto& s) { return s.kind == "bridge"; });
    if (last == rec.steps().rend()) continue;
    ++bridged;
    EXPECT_EQ(last->chain, h);
    EXPECT_TRUE(last->closed);
    // Cyclically the same hull as Graham's in a chart of the hull (an independent algorithm).
    EXPECT_EQ(std::set<std::size_t>(h.begin(), h.end()).size(), convex_hull(P, HullAlgorithm::graham).size());
  }
  EXPECT_GT(bridged, 6u);  // the inputs do exercise the merge
}

// Graham's hull (in the plain front chart, an algorithm independent of the merge) of the
// points P[i] with `side` · w > 0, in input indices: for the back side, Graham's hull of their
// antipodes (front points), antipodal again, read backwards. Rotated to start at `first`.
std::vector<std::size_t> graham_of_side(const std::vector<Point>& P, int side, std::size_t first) {
  std::vector<Point> front;
  std::vector<std::size_t> index;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (side * sign_of(P[i].w()) > 0) front.push_back(side > 0 ? P[i] : antipode(P[i])), index.push_back(i);
  std::vector<std::size_t> h;
  for (std::size_t k : convex_hull(front, HullAlgorithm::graham)) h.push_back(index[k]);
  if (side < 0) std::reverse(h.begin(), h.end());
  const auto at = std::find(h.begin(), h.end(), first);
  if (at != h.end()) std::rotate(h.begin(), at, h.end());
  return h;
}

// Exactly counter-clockwise: every three consecutive vertices turn left (Δ > 0), on the points
// themselves (not their antipodes).
bool turns_left(const std::vector<Point>& P, const std::vector<std::size_t>& h) {
  for (std::size_t k = 0; h.size() >= 3 && k < h.size(); ++k)
    if (orient(P[h[k]], P[h[(k + 1) % h.size()]], P[h[(k + 2) % h.size()]]) <= 0) return false;
  return true;
}

// The lecture level of the merge: each half's hull, finished, one after the other just before
// the first bridge (checked against Graham's hull of that half's points alone), then the
// bridges; the two monotone chains are debugging steps, the positive half's then the negative
// half's (its indices are input indices of back points).
TEST(HullRecorder, MergeShowsBothHalvesThenTheBridges) {
  std::size_t merged = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const auto P = both_sides(seed);
    Recording rec;
    HullRecorder r(HullAlgo::merge, P, lex_chart(), rec);
    merge_hull(std::span<const Point>(P), r);
    const auto& S = rec.steps();
    const auto is = [](const char* kind) { return [kind](const trace::Step& s) { return s.kind == kind; }; };
    ASSERT_EQ(std::count_if(S.begin(), S.end(), is("half")), 2) << "seed " << seed;
    const auto first = std::find_if(S.begin(), S.end(), is("half"));
    const auto second = std::find_if(first + 1, S.end(), is("half"));
    const auto bridge = std::find_if(S.begin(), S.end(), is("bridge"));
    if (bridge != S.end()) {
      ++merged;
      EXPECT_EQ(second + 1, bridge);
    }
    for (const auto* h : {&*first, &*second}) {
      EXPECT_EQ(h->depth, Depth::lecture);
      EXPECT_TRUE(h->closed);
      ASSERT_FALSE(h->chain.empty()) << h->text;
      EXPECT_EQ(h->chain, graham_of_side(P, h == &*first ? 1 : -1, h->chain.front())) << h->text;
      EXPECT_TRUE(turns_left(P, h->chain)) << h->text;
    }
    EXPECT_EQ(second->edges.size(), first->chain.size() > 1 ? first->chain.size() : 0u);  // the first, dashed
    std::size_t pos_chain = 0, neg_chain = 0;
    for (auto s = S.begin(); s != S.end(); ++s) {
      if (s->kind != "push" && s->kind != "pop") continue;
      EXPECT_EQ(s->depth, Depth::debugging);
      const bool front = P[s->points.at(0)].w() > 0;
      for (std::size_t k : s->chain) EXPECT_EQ(P[k].w() > 0, front) << s->text;  // one half's chain
      EXPECT_EQ(front, s < first) << s->text;  // the positive chain, then the negative one
      EXPECT_TRUE(s < second) << s->text;
      ++(front ? pos_chain : neg_chain);
    }
    EXPECT_GT(neg_chain, 0u) << "seed " << seed;
  }
  EXPECT_GT(merged, 6u);
}

// Every point in one half: that half's chain is the whole algorithm, shown at the lecture level,
// and no "half" step repeats the answer. On the front side and on the back side alike; the
// merge's hull is Graham's hull of the side (independent), and a popped vertex comes back.
TEST(HullRecorder, MergeOfOneHalfShowsItsChain) {
  const auto F = make(gen::Kind::uniform, 20, 3);
  std::vector<Point> back;
  for (const auto& p : F) back.push_back(antipode(p));
  const auto& B = back;
  for (const auto* P : {&F, &B}) {
    const int side = P == &F ? 1 : -1;
    Recording rec;
    HullRecorder r(HullAlgo::merge, *P, lex_chart(), rec);
    const auto h = merge_hull(std::span<const Point>(*P), r);
    ASSERT_FALSE(h.empty());
    EXPECT_EQ(h, graham_of_side(*P, side, h.front()));
    const auto lecture = rec.at(Depth::lecture);
    EXPECT_EQ(lecture.size(), rec.size());
    EXPECT_TRUE(std::none_of(lecture.begin(), lecture.end(), [](const auto& s) { return s.kind == "half"; }));
    std::size_t pops = 0;
    std::vector<std::size_t> stack;  // the chain replayed from the pushes and pops alone
    for (auto s = lecture.begin(); s != lecture.end(); ++s) {
      ASSERT_TRUE(s->kind == "push" || s->kind == "pop") << s->kind;
      EXPECT_EQ(s->text.find("negative half") != std::string::npos, side < 0) << s->text;
      if (s->kind == "push") stack.push_back(s->points.at(0));
      if (s->kind == "pop" && !stack.empty() && stack.back() == s->points.at(0)) stack.pop_back();
      EXPECT_EQ(s->chain, stack) << s->text;
      if (s->kind != "pop") continue;
      ++pops;
      // A vertex one chain (lower, upper) drops is one of the other: it stays on the stack (the
      // lower chain is under the upper one there) or is pushed again.
      const std::size_t i = s->points.at(0);
      if (std::count(h.begin(), h.end(), i) != 0) {
        EXPECT_TRUE(std::count(s->chain.begin(), s->chain.end(), i) == 1 ||
                    std::any_of(s + 1, lecture.end(), [i](const auto& t) { return t.kind == "push" && t.points[0] == i; }))
            << s->text;
      }
    }
    EXPECT_GT(pops, 0u);
    EXPECT_EQ(std::set<std::size_t>(lecture.back().chain.begin(), lecture.back().chain.end()),
              std::set<std::size_t>(h.begin(), h.end()));  // the chain closes on the hull
  }
}

TEST(Recording, LevelsKeepTheOrderAndTheDepth) {
  const auto P = make(gen::Kind::uniform, 30, 7);
  Recording rec;
  HullRecorder r(HullAlgo::graham, P, front_chart(), rec);
  graham(std::span<const Point>(P), iota_of(P.size()), front_chart(), r);
  const auto lecture = rec.at(Depth::lecture);
  const auto all = rec.at(Depth::debugging);
  EXPECT_EQ(all.size(), rec.size());
  EXPECT_LT(lecture.size(), all.size());
  std::size_t k = 0;  // lecture is a subsequence of all
  for (const auto& s : all)
    if (k < lecture.size() && s.text == lecture[k].text) ++k;
  EXPECT_EQ(k, lecture.size());
  for (const auto& s : lecture) EXPECT_EQ(s.depth, Depth::lecture);
}

TEST(DelaunayRecorder, RecordsTheTriangulationItReturns) {
  for (const auto& P : front_inputs()) {
    Recording rec;
    const Triangulation t = delaunay_with(std::span<const Point>(P), trace::DelaunayRecorder(P, rec));
    const auto expected = sorted_triangles(delaunay(P));  // the default traits: the same answer
    EXPECT_EQ(sorted_triangles(t), expected);
    if (t.dimension() < 2) continue;
    ASSERT_FALSE(rec.empty());
    EXPECT_EQ(rec.back().triangles, expected);
    EXPECT_EQ(rec.steps().front().kind, "start");
    std::size_t inserts = 0;
    for (const auto& s : rec.steps()) {
      inserts += s.kind == "insert";
      if (s.kind == "flip") {
        for (const auto& f : s.touched) EXPECT_TRUE(std::binary_search(s.triangles.begin(), s.triangles.end(), f));
      }
      if (s.kind == "in-circle") {
        EXPECT_EQ(s.depth, Depth::debugging);
      }
    }
    EXPECT_EQ(inserts + 3 + t.duplicates().size(), P.size());  // the first triangle, the rest inserted
  }
}

TEST(DelaunayRecorder, WithoutCirclesATriangulationOfTheSameHull) {
  std::size_t differ = 0;
  for (const auto& P : front_inputs()) {
    Recording rec;
    const Triangulation t = delaunay_with(std::span<const Point>(P), trace::DelaunayRecorder(P, rec, true));
    ASSERT_TRUE(t.valid()) << t.validate();
    if (t.dimension() < 2) continue;
    EXPECT_EQ(rec.back().triangles, sorted_triangles(t));
    // Same vertices and hull as Delaunay's, so the same number of triangles (Euler).
    const Triangulation d = delaunay(P);
    EXPECT_EQ(t.finite_triangles().size(), d.finite_triangles().size());
    EXPECT_EQ(t.hull_edges().size(), d.hull_edges().size());
    differ += sorted_triangles(t) != sorted_triangles(d);
    for (const auto& s : rec.steps()) EXPECT_NE(s.kind, "in-circle");
  }
  EXPECT_GT(differ, 0u);  // not secretly the Delaunay triangulation
}

TEST(DelaunayRecorder, RecordsNothingForT2InputAndChangesNothing) {
  gen::Options o;
  o.n = 30;
  o.seed = 4;
  const auto P = gen::points(gen::Kind::both_sides, o);  // each side triangulated apart
  Recording rec;
  const trace::DelaunayRecorder k(P, rec);
  EXPECT_FALSE(k.recording());
  EXPECT_EQ(sorted_triangles(delaunay_with(std::span<const Point>(P), k)), sorted_triangles(delaunay(P)));
  EXPECT_TRUE(rec.empty());
}

}  // namespace
}  // namespace t2
