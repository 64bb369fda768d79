// Algorithm 9 on T² animated (t2/trace/triangulate_t2_recorder.hpp, `t2 animate triangulate` on
// input with points behind or on Ω): the recorder changes nothing in t2::triangulate_t2; the
// lecture level has one step per point after the first triangle (n − 2 in all); every step's
// faces and hull satisfy Euler's formula (F + h = 2(V + 1) − 4 with v∞ while the hull exists,
// F = 2V − 4 once it is gone), counted from the step's own triangles; each flip and each face
// replacement is a debugging step; the page's last step is t2 triangulate's answer; bad and
// undefined input exit 2 and 3 naming the file.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "animate_testing.hpp"
#include "cli_testing.hpp"
#include "t2/gen/generate.hpp"
#include "t2/trace/triangulate_t2_recorder.hpp"
#include "t2/triangulation/insert_t2.hpp"

namespace t2::testing {
namespace {

using trace::Depth;
using trace::Recording;
using trace::Step;

std::vector<std::vector<Point>> inputs() {
  std::vector<std::vector<Point>> v;
  gen::Options o;
  for (o.seed = 1; o.seed <= 3; ++o.seed)
    for (gen::Kind k : {gen::Kind::antipodal, gen::Kind::both_sides, gen::Kind::infinity}) {
      o.n = 10 + 7 * o.seed;
      v.push_back(gen::points(k, o));
    }
  // figures 5.18-5.20 of seed 000 (lunes, a flat face, the lunes gone) and a duplicate
  const Point z = Point::cartesian(0, 0), w = Point::cartesian(2, 0), u = Point::cartesian(3, 4);
  v.push_back({z, w, u, antipode(z), Point::cartesian(1, 0), Point(0, -2, -1), Point(2, 0, 0)});
  // a point that waits: its antipode inside the hull edge z -> w until ¬(2, 1) arrives
  v.push_back({z, w, u, antipode(Point::cartesian(1, 0)), antipode(Point::cartesian(2, 1))});
  return v;
}

TEST(TriangulateT2Recorder, OneLectureStepPerPointAndEulerAtEveryStep) {
  int waits = 0, replaced = 0, flips = 0;
  for (const auto& P : inputs()) {
    for (InsertionOrder how : {InsertionOrder::spatial, InsertionOrder::input}) {
      SCOPED_TRACE(fmt::format("{} points, {}", P.size(), how == InsertionOrder::input ? "input" : "spatial"));
      Recording rec;
      trace::TriangulateT2Recorder r(rec);
      const TriangulationT2 t = triangulate_t2(std::span<const Point>(P), how, r);
      const TriangulationT2 plain = triangulate_t2(P, how);
      ASSERT_EQ(sorted_triangles(t.tr), sorted_triangles(plain.tr));  // the trace changes nothing
      ASSERT_EQ(rec.at(Depth::lecture).size(), P.size() - 2) << "the first triangle, then one step per point";
      for (const Step& s : rec.steps()) {
        ASSERT_FALSE(s.points.empty()) << s.text;
        std::set<std::size_t> V;
        for (const auto& f : s.triangles) V.insert(f.begin(), f.end());
        V.insert(s.chain.begin(), s.chain.end());
        if (s.chain.empty())
          EXPECT_EQ(s.triangles.size(), 2 * V.size() - 4) << s.kind << ": " << s.text;
        else
          EXPECT_EQ(s.triangles.size() + s.chain.size(), 2 * (V.size() + 1) - 4) << s.kind << ": " << s.text;
        EXPECT_EQ(s.depth == Depth::debugging, s.kind == "flip" || s.kind == "join" || s.kind == "replace" ||
                                                   s.kind == "wait")
            << s.kind;
        for (const auto& f : s.touched) EXPECT_TRUE(std::binary_search(s.triangles.begin(), s.triangles.end(), f));
        waits += s.kind == "wait";
        replaced += s.kind == "replace";
        flips += s.kind == "flip";
      }
      EXPECT_EQ(rec.steps().back().triangles, sorted_triangles(plain.tr));
    }
  }
  EXPECT_GT(waits, 0);
  EXPECT_GT(replaced, 10);
  EXPECT_GT(flips, 10);
}

class AnimateT2 : public CliTest {};

TEST_F(AnimateT2, EndsWithTheAnswerOfT2Triangulate) {
  for (const char* kind : {"antipodal", "both-sides", "infinity"}) {
    ASSERT_EQ(t2(std::string("gen ") + kind + " --n 12 --seed 4 -o p.t2").status, 0);
    const Result r = t2("animate triangulate p.t2 -o t.html");
    ASSERT_EQ(r.status, 0) << kind << r.err;
    EXPECT_TRUE(has(r.out, "(12 at the lecture level)")) << r.out;  // input, 10 steps, answer
    const Result tri = t2("triangulate p.t2");
    ASSERT_EQ(tri.status, 0) << tri.err;
    std::vector<std::array<std::size_t, 3>> expected;
    std::istringstream lines(tri.out);
    for (std::size_t a, b, c; lines >> a >> b >> c;) expected.push_back({a, b, c});
    std::sort(expected.begin(), expected.end());
    const std::string page = slurp(dir_ / "t.html");
    const auto steps = page_steps(page);  // decoded apart from the player (animate_testing.hpp)
    const std::string html = page_data(page);  // the steps as JSON text
    ASSERT_FALSE(steps.empty());
    EXPECT_EQ(steps.back().step.at("kind"), "answer") << kind;
    EXPECT_EQ(steps.back().triangles, expected) << kind;
    // no open hemisphere holds the antipodal points: the hull goes, v∞'s faces are replaced;
    // the other two keep a hull, and points outside it join its edges
    EXPECT_TRUE(has(html, std::string(kind) == "antipodal" ? "\"kind\":\"replace\"" : "\"kind\":\"join\"")) << kind;
  }
}

TEST_F(AnimateT2, UndefinedAndBadInputExitWithTheFileNamed) {
  write("out.html", "old");
  write("edge.t2", "0 0\n2 0\n1 2\n-1 -1 0\n");  // the antipode of p3 inside the hull edge p0 p1
  Result r = t2("animate triangulate edge.t2 -o out.html");
  EXPECT_EQ(r.status, 3);
  EXPECT_TRUE(has(r.err, "edge.t2")) << r.err;
  EXPECT_TRUE(has(r.err, "inside the hull edge")) << r.err;
  write("circle.t2", "0 1 0\n0 -1 1\n0 -1 -1\n");  // around Ω: no triangle, no hull
  r = t2("animate triangulate circle.t2 -o out.html");
  EXPECT_EQ(r.status, 3);
  EXPECT_TRUE(has(r.err, "one great circle")) << r.err;
  write("bad.t2", "0 0\n-1 1 x\n");
  r = t2("animate triangulate bad.t2 -o out.html");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(has(r.err, "bad.t2:2")) << r.err;
  EXPECT_EQ(slurp(dir_ / "out.html"), "old");
  r = t2("animate delaunay edge.t2 -o out.html");  // the T² Delaunay is not animated
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(has(r.err, "front points only")) << r.err;
}

}  // namespace
}  // namespace t2::testing
