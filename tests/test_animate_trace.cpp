// The trace recorders of t2/trace: what they record last is the algorithm's answer, computed by
// the algorithm itself (recording changes nothing), and the recorded steps agree with
// properties of the answer that the recorder does not know (a popped point is no vertex; the
// candidate Jarvis names before a vertex is that vertex; a flip's two triangles are in the
// triangulation after it). The steps' indices are the input's: every claim a step makes is
// checked with the exact predicates on the input points of those indices, so a step that named
// a point of the algorithm's private order would fail.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <numeric>
#include <set>
#include <span>
#include <vector>

#include "animate_testing.hpp"
#include "t2/gen/generate.hpp"
#include "t2/hull.hpp"
#include "t2/kernel/incircle.hpp"
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
    HullRecorder r(HullAlgo::graham, P, rec);
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
    HullRecorder r(HullAlgo::jarvis, P, rec);
    const auto h = jarvis(std::span<const Point>(P), iota_of(P.size()), front_chart(), r);
    std::vector<std::size_t> vertices;
    const trace::Step* before = nullptr;  // the last consider step
    std::size_t u = h.front();            // the last vertex
    for (const auto& s : rec.steps()) {
      if (s.kind == "vertex") {
        vertices.push_back(s.points[0]);
        if (before != nullptr) {
          EXPECT_EQ(before->points[1], s.points[0]);  // the candidate it named
        }
        u = s.points[0];
        continue;
      }
      ASSERT_EQ(s.kind, "consider");
      // What the step says of i against u → candidate, checked on the input points.
      const std::size_t i = s.points[0];
      if (before != nullptr && before->kind == "consider" && s.text.find("first candidate") == std::string::npos) {
        const std::size_t q = before->points[1];
        const Sign o = orient(P[u], P[q], P[i]);
        EXPECT_EQ(s.text.find(" lies right of ") != std::string::npos, o < 0) << s.text;
        EXPECT_EQ(s.text.find(" lies left of ") != std::string::npos, o > 0) << s.text;
        EXPECT_EQ(s.points[1], o < 0 ? i : o > 0 ? q : s.points[1]) << s.text;
      }
      before = &s;
    }
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
    HullRecorder r(HullAlgo::merge, P, rec);
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
    HullRecorder r(HullAlgo::merge, P, rec);
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
    HullRecorder r(HullAlgo::merge, *P, rec);
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
  HullRecorder r(HullAlgo::graham, P, rec);
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
    const Triangulation t = delaunay_with(std::span<const Point>(P), DelaunayTraits{}, trace::DelaunayRecorder(P, rec));
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

// Every claim of a Delaunay step, checked with the exact predicates on the input points that
// the step names: an insertion's triangles are counter-clockwise and hold the new point; an
// in-circle test's answer is the sign of in_circle (random points: no four on a circle, so no
// perturbation); a flip's point lies inside the circle it names, and its two new triangles turn
// counter-clockwise. A step naming the algorithm's private numbering would fail these.
TEST(DelaunayRecorder, StepsNameInputIndices) {
  std::size_t circles = 0, flips = 0;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const auto P = make(gen::Kind::uniform, 40, seed);
    Recording rec;
    delaunay_with(std::span<const Point>(P), DelaunayTraits{}, trace::DelaunayRecorder(P, rec));
    for (const auto& s : rec.steps()) {
      const auto ccw = [&](const trace::Tri& f) { return orient(P[f[0]], P[f[1]], P[f[2]]) > 0; };
      for (const auto& f : s.touched) EXPECT_TRUE(ccw(f)) << s.text;
      for (const auto& f : s.triangles) ASSERT_TRUE(ccw(f)) << s.text;
      if (s.kind == "insert") {
        for (const auto& f : s.touched) EXPECT_TRUE(std::count(f.begin(), f.end(), s.points.at(0))) << s.text;
      }
      if (s.kind == "in-circle") {
        ++circles;
        const trace::Tri& f = s.touched.at(0);
        const Sign in = in_circle(P[f[0]], P[f[1]], P[f[2]], P[s.points.at(0)]);
        ASSERT_NE(in, ZERO);
        EXPECT_EQ(s.text.find("Yes") != std::string::npos, in > 0) << s.text;
      }
      if (s.kind == "flip" && s.touched.size() == 2) {
        ++flips;
        // "pI lies inside the circle of pQ, pS, pD": the four numbers of the text, in order
        std::vector<std::size_t> n;
        for (std::size_t k = 0; k < s.text.size(); ++k)
          if (s.text[k] == 'p' && k + 1 < s.text.size() && std::isdigit(static_cast<unsigned char>(s.text[k + 1])))
            n.push_back(std::stoul(s.text.substr(k + 1)));
        ASSERT_GE(n.size(), 4u) << s.text;
        EXPECT_EQ(n[0], s.points.at(0));
        EXPECT_GT(in_circle(P[n[1]], P[n[2]], P[n[3]], P[n[0]]) * orient(P[n[1]], P[n[2]], P[n[3]]), 0) << s.text;
      }
    }
  }
  EXPECT_GT(circles, 100u);
  EXPECT_GT(flips, 50u);
}

// The circle a step speaks of is in its overlay: one circle through the three points it names
// (its boundary point is one of them, exactly; its centre, an exact construction rounded once
// to doubles, is as far from the other two up to that rounding), and no circle in other steps.
TEST(DelaunayRecorder, TheOverlayCarriesTheCircle) {
  const auto P = make(gen::Kind::disk, 30, 3);
  Recording rec;
  delaunay_with(std::span<const Point>(P), DelaunayTraits{}, trace::DelaunayRecorder(P, rec));
  std::size_t drawn = 0;
  for (const auto& s : rec.steps()) {
    const bool speaks = s.text.find("circle") != std::string::npos;
    ASSERT_EQ(s.overlay.circles.size(), speaks ? 1u : 0u) << s.text;
    if (!speaks) continue;
    ++drawn;
    const Circle c = s.overlay.circles[0].circle();
    std::vector<std::size_t> on;  // the named points of the circle: the touched triangle's, or the text's
    for (std::size_t i = 0; i < P.size(); ++i)
      if (s.text.find(point_name(i) + ",") != std::string::npos || s.text.find(point_name(i) + "?") != std::string::npos ||
          s.text.find(point_name(i) + ":") != std::string::npos)
        on.push_back(i);
    ASSERT_EQ(on.size(), 3u) << s.text;
    EXPECT_TRUE(std::any_of(on.begin(), on.end(), [&](std::size_t i) { return P[i] == c.boundary_point(); }));
    const double cx = c.center().x() / c.center().w(), cy = c.center().y() / c.center().w();
    const auto d2 = [&](std::size_t i) {
      const mpq_class dx = mpq_class(P[i].x()) / P[i].w() - cx, dy = mpq_class(P[i].y()) / P[i].w() - cy;
      return mpq_class(dx * dx + dy * dy);
    };
    for (std::size_t i : on) EXPECT_LT(mpq_class(abs(d2(i) - d2(on[0]))).get_d(), 1e-12 * d2(on[0]).get_d()) << s.text;
  }
  EXPECT_GT(drawn, 20u);
}

TEST(DelaunayRecorder, RecordsNothingForT2InputAndChangesNothing) {
  gen::Options o;
  o.n = 30;
  o.seed = 4;
  const auto P = gen::points(gen::Kind::both_sides, o);  // each side triangulated apart
  Recording rec;
  trace::DelaunayRecorder k(P, rec);
  EXPECT_EQ(sorted_triangles(delaunay_with(std::span<const Point>(P), DelaunayTraits{}, k)),
            sorted_triangles(delaunay(P)));
  EXPECT_TRUE(rec.empty());
}

}  // namespace
}  // namespace t2
