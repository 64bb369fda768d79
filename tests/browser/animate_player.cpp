// The page of `t2 animate` in headless Chromium, loaded from the file system: it starts paused at
// the first step; the buttons and the arrow keys step forward and back, changing the frame and
// the explanation; stepping back from the first step stays there; play advances; the level
// selector adds the debugging steps; the last step is the algorithm's answer (computed here by
// the library). The page reads #step=..., &level=..., &click=..., &keys=... from its URL.
// Label "browser"; skips when chromium is not installed.
#include <algorithm>
#include <regex>
#include <set>
#include <span>

#include "cli_testing.hpp"
#include "oracle.hpp"
#include "t2/gen/generate.hpp"
#include "t2/hull.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "t2/triangulation/triangulate.hpp"

namespace t2::testing {
namespace {

#define T2_NEEDS_CHROMIUM() \
  if (!have_program("chromium")) GTEST_SKIP() << "chromium is not installed (scripts/deps.sh): skipped"

// What the page shows after loading with a fragment.
struct Shown {
  int step = -1, pos = -1;      // the recorded step on screen and its place at the level
  std::string counter;          // "step 3 of 18"
  std::string explanation;      // the explanation text
  std::string chain, triangles; // the data structure's data attributes
  std::string view;             // the frame (the SVG on screen)
  bool prev_disabled = false;
};

class PlayerInChromium : public CliTest {
 protected:
  std::vector<Point> make(const std::string& algo, gen::Kind k, std::size_t n) {
    gen::Options o;
    o.n = n;
    o.seed = 11;
    write("in.t2", gen::to_text(k, o));
    const Result r = t2("animate " + algo + " in.t2 -o page.html");
    EXPECT_EQ(r.status, 0) << r.err;
    return gen::points(k, o);
  }

  Shown load(const std::string& fragment) {
    const fs::path profile = dir_ / "profile";
    const Shell r = shell(
        "chromium --headless --no-sandbox --disable-gpu --no-first-run --disable-background-networking "
        "--disable-component-update --disable-sync --user-data-dir=" + profile.string() +
        " --virtual-time-budget=2500 --dump-dom 'file://" + (dir_ / "page.html").string() + "#" + fragment + "' 2>/dev/null",
        dir_, "", false);
    const std::string& dom = r.out;
    Shown s;
    std::smatch m;
    auto grab = [&](const char* re, std::string& out) {
      if (std::regex_search(dom, m, std::regex(re))) out = m[1].str();
    };
    std::string step, pos, prev;
    grab(R"re(<div id="view" data-step="(\d+)")re", step);
    grab(R"re(<div id="view" data-step="\d+" data-pos="(\d+)")re", pos);
    grab(R"re(<span id="counter">([^<]*)</span>)re", s.counter);
    grab(R"re(<div id="explanation">([^<]*)</div>)re", s.explanation);
    grab(R"re(<ul id="structure" data-chain="([^"]*)")re", s.chain);
    grab(R"re(<ul id="structure" data-chain="[^"]*" data-triangles="([^"]*)")re", s.triangles);
    grab(R"re(<button id="prev"([^>]*)>)re", prev);
    const auto v = dom.find("<div id=\"view\"");
    if (v != std::string::npos) s.view = dom.substr(v, dom.find("<div id=\"side\"", v) - v);
    s.step = step.empty() ? -1 : std::stoi(step);
    s.pos = pos.empty() ? -1 : std::stoi(pos);
    s.prev_disabled = prev.find("disabled") != std::string::npos;
    return s;
  }
};

std::vector<std::size_t> numbers(const std::string& s) {
  std::vector<std::size_t> v;
  static const std::regex num(R"(\d+)");
  for (auto it = std::sregex_iterator(s.begin(), s.end(), num); it != std::sregex_iterator(); ++it)
    v.push_back(std::stoul(it->str()));
  return v;
}

TEST_F(PlayerInChromium, StepsForwardAndBackAndEndsWithGrahamsHull) {
  if (std::getenv("T2_SANITIZED")) GTEST_SKIP() << "the browser tests do not run under sanitizers";
  T2_NEEDS_CHROMIUM();
  const auto P = make("graham", gen::Kind::uniform, 10);
  const Shown first = load("");
  ASSERT_EQ(first.pos, 0) << "the page did not render its first step";
  EXPECT_TRUE(has(first.explanation, "The input")) << first.explanation;
  EXPECT_TRUE(has(first.view, "<svg")) << "no frame on screen";
  EXPECT_TRUE(first.prev_disabled);
  const Shown next = load("click=next");
  const Shown two = load("click=next,next");
  const Shown back = load("click=next,next,prev");
  EXPECT_EQ(next.pos, 1);
  EXPECT_EQ(two.pos, 2);
  EXPECT_EQ(back.pos, 1);
  EXPECT_NE(next.explanation, first.explanation);
  EXPECT_NE(two.explanation, next.explanation);
  EXPECT_EQ(back.explanation, next.explanation);  // back is the same step again, frame and all
  EXPECT_EQ(back.view, next.view);
  EXPECT_NE(next.view, first.view);
  EXPECT_NE(two.view, next.view);
  const Shown keys = load("keys=ArrowRight,ArrowRight,ArrowLeft");
  EXPECT_EQ(keys.pos, 1);
  EXPECT_EQ(keys.explanation, next.explanation);
  const Shown stuck = load("click=prev,prev&keys=ArrowLeft");  // stepping back from the start
  EXPECT_EQ(stuck.pos, 0);
  EXPECT_EQ(stuck.explanation, first.explanation);
  const Shown last = load("step=last");
  const auto hull = convex_hull(P, HullAlgorithm::graham);
  EXPECT_EQ(numbers(last.chain), hull) << last.explanation;
  EXPECT_TRUE(has(last.explanation, "The hull")) << last.explanation;
  const Shown beyond = load("step=last&click=next");  // and forward from the end
  EXPECT_EQ(beyond.pos, last.pos);
  // The debugging level shows more steps, and the same last one.
  const Shown debug = load("step=last&level=debugging");
  EXPECT_GT(numbers(debug.counter).at(1), numbers(last.counter).at(1)) << debug.counter << " vs " << last.counter;
  EXPECT_EQ(debug.chain, last.chain);
  // Play runs on its own (Chromium's virtual time lets the timer fire), then can be paused.
  const Shown played = load("click=play");
  EXPECT_GE(played.pos, 1) << played.counter;
}

TEST_F(PlayerInChromium, DelaunayEndsWithTheLibrarysTriangulation) {
  if (std::getenv("T2_SANITIZED")) GTEST_SKIP() << "the browser tests do not run under sanitizers";
  T2_NEEDS_CHROMIUM();
  const auto P = make("delaunay", gen::Kind::disk, 10);
  auto tris = delaunay(P).finite_triangles();
  std::sort(tris.begin(), tris.end());
  std::vector<std::size_t> expected;
  for (const auto& t : tris) expected.insert(expected.end(), t.begin(), t.end());
  const Shown last = load("step=last");
  EXPECT_EQ(numbers(last.triangles), expected) << last.explanation;
  const Shown flip = load("step=5&level=debugging&click=prev");
  EXPECT_EQ(flip.pos, 4);
  EXPECT_FALSE(flip.explanation.empty());
}

// The sweep (chapter 09): the last step is t2::triangulate's answer; the debugging level adds
// the joins and the flips of step 35, and steps back through them.
TEST_F(PlayerInChromium, SweepEndsWithTheSweepsTriangulation) {
  if (std::getenv("T2_SANITIZED")) GTEST_SKIP() << "the browser tests do not run under sanitizers";
  T2_NEEDS_CHROMIUM();
  const auto P = make("triangulate", gen::Kind::disk, 9);
  auto tris = triangulate(P).finite_triangles();
  std::sort(tris.begin(), tris.end());
  std::vector<std::size_t> expected;
  for (const auto& t : tris) expected.insert(expected.end(), t.begin(), t.end());
  const Shown last = load("step=last");
  EXPECT_EQ(numbers(last.triangles), expected) << last.explanation;
  EXPECT_EQ(numbers(last.counter).at(1), 9u) << last.counter;  // input, first triangle, 6 fans, answer
  const Shown debug = load("step=last&level=debugging");
  EXPECT_GT(numbers(debug.counter).at(1), 9u) << debug.counter;
  const Shown join = load("step=2&level=debugging&click=next,prev");
  EXPECT_EQ(join.pos, 2);
  EXPECT_TRUE(has(join.explanation, "the next point in (x, y) order")) << join.explanation;
}

// Jarvis's march: the last step is the library's Jarvis hull; the debugging level steps back
// through the candidates one at a time.
TEST_F(PlayerInChromium, JarvisEndsWithTheMarchsHull) {
  if (std::getenv("T2_SANITIZED")) GTEST_SKIP() << "the browser tests do not run under sanitizers";
  T2_NEEDS_CHROMIUM();
  const auto P = make("jarvis", gen::Kind::disk, 10);
  const Shown last = load("step=last");
  EXPECT_EQ(numbers(last.chain), convex_hull(P, HullAlgorithm::jarvis)) << last.explanation;
  const Shown fourth = load("step=4&level=debugging");
  const Shown third = load("step=4&level=debugging&click=prev");
  EXPECT_EQ(third.pos + 1, fourth.pos);
  EXPECT_NE(third.explanation, fourth.explanation);
  EXPECT_NE(third.view, fourth.view);
}

// The merge on both sides of T²: the lecture level's second and third steps are the positive
// and the negative half's hulls; the last is merge_hull's answer.
TEST_F(PlayerInChromium, MergeHullShowsBothHalvesThenEndsWithTheMerge) {
  if (std::getenv("T2_SANITIZED")) GTEST_SKIP() << "the browser tests do not run under sanitizers";
  T2_NEEDS_CHROMIUM();
  const auto P = make("merge", gen::Kind::both_sides, 12);
  const Shown positive = load("click=next");
  EXPECT_EQ(positive.pos, 1);
  EXPECT_TRUE(has(positive.explanation, "The hull of the positive half")) << positive.explanation;
  const Shown negative = load("click=next,next");
  EXPECT_EQ(negative.pos, 2);
  EXPECT_TRUE(has(negative.explanation, "The hull of the negative half")) << negative.explanation;
  EXPECT_NE(positive.view, negative.view);
  const Shown last = load("step=last");
  EXPECT_EQ(numbers(last.chain), merge_hull(std::span<const Point>(P))) << last.explanation;
  const Shown before = load("step=last&click=prev");
  EXPECT_EQ(before.pos + 1, last.pos);
  EXPECT_NE(before.view, last.view);
}

// Algorithm 9 (triangulate-t2, insertion in spatial order): the last step is a triangulation of
// the points, checked exactly: every triangle counter-clockwise, 2n - h - 2 of them, every point
// a vertex, and their areas adding up to the hull's.
TEST_F(PlayerInChromium, TriangulateT2EndsWithATriangulationOfThePoints) {
  if (std::getenv("T2_SANITIZED")) GTEST_SKIP() << "the browser tests do not run under sanitizers";
  T2_NEEDS_CHROMIUM();
  const auto P = make("triangulate-t2", gen::Kind::uniform, 12);
  const Shown last = load("step=last");
  const auto v = numbers(last.triangles);
  const auto hull = convex_hull(P);
  ASSERT_EQ(v.size(), 3 * (2 * P.size() - hull.size() - 2)) << last.explanation;
  auto area2 = [&](std::size_t a, std::size_t b, std::size_t c) {
    const Pos A = pos(P[a]), B = pos(P[b]), C = pos(P[c]);
    return Rational((B[0] - A[0]) * (C[1] - A[1]) - (B[1] - A[1]) * (C[0] - A[0]));
  };
  Rational sum = 0, whole = 0;
  for (std::size_t k = 0; k < v.size(); k += 3) {
    const Rational a = area2(v[k], v[k + 1], v[k + 2]);
    EXPECT_GT(a, 0) << "triangle " << v[k] << " " << v[k + 1] << " " << v[k + 2];
    sum += a;
  }
  for (std::size_t k = 1; k + 1 < hull.size(); ++k) whole += area2(hull[0], hull[k], hull[k + 1]);
  EXPECT_EQ(sum, whole);
  EXPECT_EQ(std::set<std::size_t>(v.begin(), v.end()).size(), P.size());
  const Shown third = load("step=3&click=prev");
  const Shown fourth = load("step=3");
  EXPECT_EQ(third.pos + 1, fourth.pos);
  EXPECT_NE(third.triangles, fourth.triangles);
}

}  // namespace
}  // namespace t2::testing
