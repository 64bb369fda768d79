// The sweep of chapter 09 animated (t2/trace/sweep_recorder.hpp, `t2 animate triangulate` on
// front points, as `t2 triangulate` runs it): the recorder changes nothing in t2::triangulate;
// the lecture level has one step per distinct point (the first triangle, each point on its first
// edge, each swept point's fan); after each point the triangles are a triangulation of the
// points swept so far, checked against an independent count (Euler, 2k - h - 2, with h the
// points on the hull's boundary by brute force) and the hull so far holds exactly those boundary
// points; each swept point's fan is one triangle more than its flips; the last step is t2
// triangulate's answer, on points behind too (Algorithm 9 on T², as t2 triangulate runs it).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>
#include <span>
#include <sstream>
#include <vector>

#include "animate_testing.hpp"
#include "cli_testing.hpp"
#include "t2/gen/generate.hpp"
#include "t2/kernel/lexicographic.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/trace/sweep_recorder.hpp"
#include "t2/triangulation/triangulate.hpp"

namespace t2::testing {
namespace {

using trace::Depth;
using trace::Recording;
using trace::Step;

// The points of S on the boundary of their hull, by brute force: p is on it when some line
// through p and another point of S has all of S on one side (or on it).
std::set<std::size_t> boundary(const std::vector<Point>& P, const std::set<std::size_t>& S) {
  std::set<std::size_t> out;
  for (std::size_t p : S)
    for (std::size_t q : S) {
      if (q == p) continue;
      bool left = true;
      for (std::size_t r : S) left = left && orient(P[p], P[q], P[r]) >= 0;
      if (left) out.insert(p), out.insert(q);
    }
  return out;
}

// Inputs: random, on a circle, on a square's boundary (points inside hull edges), on a grid
// (the smallest points collinear: points on the first edge; duplicates with n not a square).
std::vector<std::vector<Point>> inputs() {
  std::vector<std::vector<Point>> v;
  gen::Options o;
  for (o.seed = 1; o.seed <= 3; ++o.seed)
    for (gen::Kind k : {gen::Kind::uniform, gen::Kind::circle, gen::Kind::boundary, gen::Kind::grid}) {
      o.n = 9 + 6 * o.seed;
      v.push_back(gen::points(k, o));
    }
  std::vector<Point> line;  // the first four on a line (two on the first edge), a duplicate
  for (const auto& [x, y] : {std::pair{0, 0}, {1, 0}, {2, 0}, {3, 0}, {1, 2}, {2, 0}, {4, 1}})
    line.push_back(Point::cartesian(x, y));
  v.push_back(line);
  return v;
}

TEST(SweepRecorder, OneLectureStepPerPointEachATriangulationOfThePointsSoFar) {
  for (const auto& P : inputs()) {
    Recording rec;
    trace::SweepRecorder r(rec);
    const Triangulation t = triangulate(std::span<const Point>(P), r);
    const Triangulation plain = triangulate(P);
    ASSERT_EQ(sorted_triangles(t), sorted_triangles(plain));  // the trace changes nothing
    ASSERT_EQ(t.hull_edges(), plain.hull_edges());
    const std::size_t distinct = P.size() - t.duplicates().size();
    const auto lecture = rec.at(Depth::lecture);
    ASSERT_EQ(lecture.size(), distinct - 2) << "the first triangle, then one step per point";
    std::set<std::size_t> so_far;  // the points swept so far
    std::size_t flips = 0;
    for (const Step& s : rec.steps()) {
      ASSERT_FALSE(s.points.empty()) << s.text;
      const std::size_t v = s.points[0];
      if (s.kind == "flip") {
        ++flips;
        EXPECT_EQ(s.depth, Depth::debugging);
        ASSERT_EQ(s.touched.size(), 1u) << s.text;  // the hull edge's new triangle, at v
        EXPECT_TRUE(std::count(s.touched[0].begin(), s.touched[0].end(), v)) << s.text;
        continue;
      }
      if (s.kind == "insert" && s.depth == Depth::debugging) {
        flips = 0;
        EXPECT_EQ(s.touched.size(), 1u) << s.text;  // joined to one hull edge
        continue;
      }
      // A lecture step: the state after point v.
      so_far.insert(s.points.begin(), s.points.end());
      std::set<std::size_t> used;
      for (const auto& f : s.triangles) used.insert(f.begin(), f.end());
      EXPECT_EQ(used, so_far) << s.text;
      const auto h = boundary(P, so_far);
      EXPECT_EQ(s.triangles.size(), 2 * so_far.size() - h.size() - 2) << s.text;
      EXPECT_EQ(std::set<std::size_t>(s.chain.begin(), s.chain.end()), h) << s.text;
      EXPECT_EQ(s.chain.size(), h.size()) << s.text;
      if (s.kind == "fan") {
        EXPECT_EQ(s.touched.size(), flips + 1) << s.text;
        for (const auto& f : s.touched) EXPECT_TRUE(std::count(f.begin(), f.end(), v)) << s.text;
      }
    }
    EXPECT_EQ(so_far.size(), distinct);
    EXPECT_EQ(lecture.back().triangles, sorted_triangles(plain));
  }
}

// Fewer than three points off a line: no hook, nothing recorded.
TEST(SweepRecorder, NoTriangleNoStep) {
  for (const std::vector<Point>& P : {std::vector<Point>{}, {Point::cartesian(0, 0), Point::cartesian(1, 1), Point::cartesian(2, 2)}}) {
    Recording rec;
    trace::SweepRecorder r(rec);
    (void)triangulate(std::span<const Point>(P), r);
    EXPECT_TRUE(rec.empty());
  }
}

class AnimateSweep : public CliTest {};

TEST_F(AnimateSweep, EndsWithTheAnswerOfT2Triangulate) {
  gen::Options o;
  o.n = 8;
  o.seed = 5;
  write("d.t2", gen::to_text(gen::Kind::disk, o));
  const Result r = t2("animate triangulate d.t2 -o s.html");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(has(r.out, "s.html: ")) << r.out;
  EXPECT_TRUE(has(r.out, "(8 at the lecture level)")) << r.out;  // input, first triangle, 5 fans, answer
  // t2 triangulate's answer for `file` (its lines "a b c"), sorted as a page's steps hold it
  auto answer_of = [&](const std::string& file) {
    const Result tri = t2("triangulate " + file);
    EXPECT_EQ(tri.status, 0) << tri.err;
    std::vector<std::array<std::size_t, 3>> expected;
    std::istringstream lines(tri.out);
    for (std::size_t a, b, c; lines >> a >> b >> c;) expected.push_back({a, b, c});
    std::sort(expected.begin(), expected.end());
    return expected;
  };
  const auto want = answer_of("d.t2");
  const std::string page = slurp(dir_ / "s.html");
  const auto steps = page_steps(page);  // decoded apart from the player (animate_testing.hpp)
  const std::string html = page_data(page);  // the steps as JSON text
  ASSERT_GE(steps.size(), 3u);
  EXPECT_EQ(steps.back().triangles, want);                 // the answer
  EXPECT_EQ(steps[steps.size() - 2].triangles, want);      // and the last fan
  EXPECT_TRUE(has(html, "\"kind\":\"fan\""));
  EXPECT_TRUE(has(html, "\"kind\":\"flip\""));
  // A point behind: t2 triangulate runs Algorithm 9 on T², and so does the animation
  // (test_animate_t2.cpp follows it): one name, one algorithm.
  write("back.t2", "0 0\n1 0\n2 1\n-1 0 -1\n");
  const Result back = t2("animate triangulate back.t2 -o b.html");
  ASSERT_EQ(back.status, 0) << back.err;
  EXPECT_EQ(page_steps(slurp(dir_ / "b.html")).back().triangles, answer_of("back.t2"));
}

}  // namespace
}  // namespace t2::testing
