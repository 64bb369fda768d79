// The two sweeps of chapter 13 animated (`t2 animate intersect`, Bentley-Ottmann, and `t2
// animate intersect-circular`, the circular sweep of T²; tools/t2/algorithms/intersect.cpp):
// the traced runs tell exactly the points the untraced runs and the brute force return; every
// point told lies on every segment it names (exact); every overlay intersection point of a step
// lies on both segments the step names (exact, on integer input whose meets are doubles); every
// lecture swap comes after the intersection step of its point; the sweep's events come in its
// order (xy for Bentley-Ottmann, the turn around the centre for the circular sweep); each
// neighbour test names two segments adjacent in the status; the page of 100 segments (200
// endpoints, the maximum) weighs at most 1 MB; bad and undefined input exit 2 and 3.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "algorithms/registry.hpp"
#include "animate_testing.hpp"
#include "cli_testing.hpp"
#include "t2/gen/generate.hpp"
#include "t2/intersect/intersections.hpp"
#include "t2/kernel/lexicographic.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/kernel/segment.hpp"
#include "t2/trace/hook.hpp"
#include "t2/trace/recording.hpp"

namespace t2::testing {
namespace {

namespace reg = t2cli::algorithms;
using trace::Depth;
using trace::Step;

// Segments of small integer points of T² (front only, or every side): their meets have short
// integers, so the overlay's double points are the exact points.
std::vector<Segment> integer_segments(unsigned seed, std::size_t n, bool front) {
  std::mt19937 g(seed);
  std::uniform_int_distribution<int> c(-6, 6), w(front ? 1 : -2, 2);
  std::vector<Segment> S;
  while (S.size() < n) {
    // Braces draw the numbers left to right (arguments in parentheses are drawn in an order each
    // compiler chooses: GCC and clang made different sets of the same seed).
    const std::array<int, 6> r{w(g), c(g), c(g), w(g), c(g), c(g)};
    if ((r[0] == 0 && r[1] == 0 && r[2] == 0) || (r[3] == 0 && r[4] == 0 && r[5] == 0)) continue;
    const Point a(r[0], r[1], r[2]), b(r[3], r[4], r[5]);
    if (a == antipode(b)) continue;
    S.emplace_back(a, b);
  }
  return S;
}

// Degenerate front sets: shared endpoints, vertical segments, three segments through one point,
// collinear overlaps, one-point segments.
std::vector<Segment> degenerate() {
  const auto p = [](double x, double y) { return Point::cartesian(x, y); };
  return {Segment(p(0, 0), p(4, 4)), Segment(p(0, 4), p(4, 0)), Segment(p(2, -1), p(2, 5)),  // three through (2, 2)
          Segment(p(0, 0), p(4, 0)), Segment(p(1, 0), p(3, 0)),                               // overlapping
          Segment(p(4, 0), p(4, 4)), Segment(p(4, 4), p(6, 1)),                               // shared ends
          Segment(p(3, 1), p(3, 1)), Segment(p(1, 1), p(3, 3)), Segment(p(0, 2), p(6, 2))};
}

std::vector<std::vector<Segment>> front_sets() {
  std::vector<std::vector<Segment>> v{degenerate()};
  gen::Options o;
  for (o.seed = 1; o.seed <= 3; ++o.seed) {
    o.n = 20 * o.seed;
    o.crossings = 2 * o.n;
    v.push_back(gen::segments(o));
    v.push_back(integer_segments(static_cast<unsigned>(o.seed), 12 + 8 * o.seed, true));
  }
  return v;
}

std::vector<std::vector<Segment>> t2_sets() {
  std::vector<std::vector<Segment>> v = front_sets();
  for (unsigned seed = 1; seed <= 4; ++seed) v.push_back(integer_segments(100 + seed, 10 + 10 * seed, false));
  return v;
}

bool same(const std::vector<IntersectionPoint>& a, const std::vector<IntersectionPoint>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (a[k].point.w() != b[k].point.w() || a[k].point.x() != b[k].point.x() || a[k].point.y() != b[k].point.y() ||
        a[k].segments != b[k].segments)
      return false;
  return true;
}

void sort_wxy(std::vector<IntersectionPoint>& v) {
  std::sort(v.begin(), v.end(), [](const auto& a, const auto& b) { return less_wxy(a.point, b.point); });
}

// What a traced run told: the points found, the event points, and whether each neighbour test
// named neighbours of the status told last.
struct Told {
  std::vector<IntersectionPoint> found;
  std::vector<ExactPoint> events;
  ExactPoint centre{1, 0, 0};
  int tests = 0, bad_tests = 0;
};

Told traced(const std::vector<Segment>& S, bool circular, std::vector<IntersectionPoint>& answer) {
  Told t;
  std::vector<std::size_t> status;
  const auto hook = [&](const trace::Report& r) {
    if (r.event == trace::Event::found)
      t.found.push_back({*r.point, std::vector<std::size_t>(r.chain.begin(), r.chain.end())});
    else if (r.event == trace::Event::sweep_start)
      t.centre = *r.point;
    else if (r.event == trace::Event::sweep) {
      t.events.push_back(*r.point);
      status.assign(r.chain.begin(), r.chain.end());
    } else if (r.event == trace::Event::neighbours) {
      ++t.tests;
      const auto a = std::find(status.begin(), status.end(), r.at[0]);
      t.bad_tests += !(a != status.end() && a + 1 != status.end() && a[1] == r.at[1]);
    }
  };
  answer = circular ? intersections_circular(S, hook) : intersections_sweep(S, hook);
  return t;
}

TEST(AnimateSegments, TheTracedSweepsTellWhatTheUntracedAndTheBruteForceAnswer) {
  int points = 0;
  for (bool circular : {false, true})
    for (const auto& S : circular ? t2_sets() : front_sets()) {
      SCOPED_TRACE(fmt::format("{} segments, {}", S.size(), circular ? "circular" : "Bentley-Ottmann"));
      std::vector<IntersectionPoint> answer;
      Told t = traced(S, circular, answer);
      const auto plain = circular ? intersections_circular(S) : intersections_sweep(S);
      const auto brute = intersections_brute(S);
      EXPECT_TRUE(same(answer, plain)) << "the hook changed the answer";
      EXPECT_TRUE(same(plain, brute));
      sort_wxy(t.found);
      EXPECT_TRUE(same(t.found, brute)) << "told points differ from the brute force";
      for (const auto& p : t.found)
        for (std::size_t i : p.segments)
          EXPECT_TRUE(on_segment(to_exact(S[i].source()), to_exact(S[i].target()), p.point))
              << to_string(p.point) << " is not on s" << i;
      EXPECT_EQ(t.bad_tests, 0) << "of " << t.tests << " neighbour tests";
      points += static_cast<int>(t.found.size());
    }
  EXPECT_GE(points, 300);
}

// The order of the circular sweep around o from the half-line through r = [0, 1, 0]: 0 on
// that half-line, 1 the upper half turn, 2 the opposite half-line, 3 the lower half turn.
int half(const ExactPoint& o, const ExactPoint& x) {
  const ExactPoint r(0, 1, 0), z(0, 0, 1);
  const Sign h = orient(o, r, x);
  if (h != ZERO) return h == POSITIVE ? 1 : 3;
  return orient(o, z, x) == orient(o, z, r) ? 0 : 2;
}

TEST(AnimateSegments, TheEventsComeInTheSweepsOrder) {
  for (const auto& S : front_sets()) {
    std::vector<IntersectionPoint> answer;
    const Told t = traced(S, false, answer);
    ASSERT_FALSE(t.events.empty());
    for (std::size_t k = 1; k < t.events.size(); ++k)
      ASSERT_EQ(compare_xy(t.events[k - 1], t.events[k]), NEGATIVE) << k << " of " << S.size();
  }
  for (const auto& S : t2_sets()) {
    std::vector<IntersectionPoint> answer;
    const Told t = traced(S, true, answer);
    std::vector<ExactPoint> turn;  // the events off the initial half-line, which come first or last
    for (const auto& e : t.events)
      if (half(t.centre, e) != 0) turn.push_back(e);
    for (std::size_t k = 1; k < turn.size(); ++k) {
      const int a = half(t.centre, turn[k - 1]), b = half(t.centre, turn[k]);
      ASSERT_LE(a, b) << k;
      if (a == b && a != 2) ASSERT_NE(orient(t.centre, turn[k - 1], turn[k]), NEGATIVE) << k;
    }
  }
}

const reg::Algorithm& algorithm(const char* name) {
  const reg::Algorithm* a = reg::find(name);
  if (!a || !a->record_segments) throw std::logic_error(std::string(name) + " is not animated");
  return *a;
}

// The event point of a step: where its sweep line is drawn (a vertical line through it, or the
// half-line from the centre through it).
std::optional<Point> event_of(const Step& s) {
  if (!s.overlay.lines.empty()) return s.overlay.lines[0].a.point;
  if (s.overlay.segments.size() >= 2) return s.overlay.segments[0].b.point;
  return std::nullopt;
}

TEST(AnimateSegments, TheStepsShowWhatTheySay) {
  int swaps = 0, found = 0;
  for (const char* name : {"intersect", "intersect-circular"})
    for (const auto& S : std::string(name) == "intersect" ? front_sets() : t2_sets()) {
      SCOPED_TRACE(fmt::format("{} on {} segments", name, S.size()));
      trace::Recording rec;
      algorithm(name).record_segments(S, "in.t2", rec);
      const auto answer = std::string(name) == "intersect" ? intersections_sweep(S) : intersections_circular(S);
      ASSERT_EQ(rec.back().kind, "answer");
      ASSERT_EQ(rec.back().overlay.points.size(), answer.size());  // the untraced answer, point by point
      for (std::size_t k = 0; k < answer.size(); ++k) EXPECT_EQ(rec.back().overlay.points[k].point, to_double(answer[k].point));
      const bool integer = S.size() < 100 && std::all_of(S.begin(), S.end(), [](const Segment& s) {
        return s.source().w() == std::floor(s.source().w()) && s.source().x() == std::floor(s.source().x()) &&
               s.target().x() == std::floor(s.target().x()) && s.target().y() == std::floor(s.target().y()) &&
               s.source().y() == std::floor(s.source().y()) && s.target().w() == std::floor(s.target().w());
      });
      std::vector<std::pair<Point, std::vector<std::size_t>>> found_before;  // every intersection step so far
      int n_found = 0;
      for (const Step& s : rec.steps()) {
        if (s.kind == "intersection") {
          ++n_found;
          ASSERT_EQ(s.depth, Depth::lecture);
          ASSERT_GE(s.edges.size(), 2u);
          const Point x = s.overlay.points.back().point;  // the newest point found
          ASSERT_EQ(event_of(s), x) << s.text;
          if (integer)
            for (const auto& e : s.edges)
              ASSERT_TRUE(on_segment(S[e[0] / 2].source(), S[e[0] / 2].target(), x)) << s.text;
          found_before.emplace_back(x, std::vector<std::size_t>());
          for (const auto& e : s.edges) found_before.back().second.push_back(e[0] / 2);
        } else if (s.kind == "swap") {
          ++swaps;
          std::vector<std::size_t> crossing;
          for (const auto& e : s.edges) crossing.push_back(e[0] / 2);
          const auto at = event_of(s);
          ASSERT_TRUE(at);
          ASSERT_TRUE(std::any_of(found_before.begin(), found_before.end(), [&](const auto& f) {
            return f.first == *at && std::all_of(crossing.begin(), crossing.end(), [&](std::size_t i) {
                     return std::find(f.second.begin(), f.second.end(), i) != f.second.end();
                   });
          })) << "a swap without its intersection before it: " << s.text;
        } else if (s.kind == "test") {
          ASSERT_EQ(s.depth, Depth::debugging);
          ASSERT_EQ(s.edges.size(), 2u);
          const auto a = std::find(s.chain.begin(), s.chain.end(), s.edges[0][0] / 2);  // neighbours
          ASSERT_TRUE(a != s.chain.end() && a + 1 != s.chain.end() && a[1] == s.edges[1][0] / 2) << s.text;
        }
        for (std::size_t i : s.chain) ASSERT_LT(i, S.size());
      }
      EXPECT_EQ(n_found, static_cast<int>(answer.size()));
      found += n_found;
    }
  EXPECT_GE(swaps, 100);
  EXPECT_GE(found, 300);
}

class AnimateSegmentsCli : public CliTest {};

// 100 segments, 200 endpoints: the most t2 animate takes. (Under the sanitizers, which make
// the pictures' drawing several times slower, one page of 40; the optimized tree checks 100.)
TEST_F(AnimateSegmentsCli, ThePageOf100SegmentsWeighsAtMostOneMegabyte) {
#if defined(T2_SANITIZE)
  const int n = 40;
  const std::vector<const char*> algos{"intersect-circular"};
#else
  const int n = 100;
  const std::vector<const char*> algos{"intersect", "intersect-circular"};
#endif
  for (const char* algo : algos) {
    const Result g = t2(fmt::format("gen segments --n {} --crossings {} -o s.t2", n, 3 * n / 2));
    ASSERT_EQ(g.status, 0) << g.err;
    const Result r = t2(fmt::format("animate {} s.t2 -o page.html", algo));
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string html = slurp(dir_ / "page.html");
    EXPECT_LE(html.size(), 1000000u) << algo;
    RecordProperty(std::string(algo) + "_bytes", static_cast<int>(html.size()));
    const auto steps = page_steps(html);
    ASSERT_FALSE(steps.empty());
    EXPECT_EQ(steps.back().step["kind"], "answer");
    EXPECT_TRUE(has(steps.back().step["text"].get<std::string>(), fmt::format("{} intersection points", 3 * n / 2)))
        << algo;
    EXPECT_TRUE(has(steps[1].svg, "<path")) << "the segments are drawn";
  }
}

TEST_F(AnimateSegmentsCli, BadInputExits2AndSegmentsOffTheFrontExit3) {
  ASSERT_EQ(t2("gen segments --n 101 -o big.t2").status, 0);
  Result r = t2("animate intersect-circular big.t2 -o p.html");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(has(r.err, "big.t2: 202 points")) << r.err;
  write("bad.t2", "segment\n 1 0 0\n -1 0 0\nend\n");  // antipodal ends
  r = t2("animate intersect bad.t2 -o p.html");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(has(r.err, "bad.t2:")) << r.err;
  write("back.t2", "segment\n 1 0 0\n 1 1 1\nend\nsegment\n -1 0 1\n 1 1 0\nend\n");
  r = t2("animate intersect back.t2 -o p.html");
  EXPECT_EQ(r.status, 3);
  EXPECT_TRUE(has(r.err, "back.t2: segment 1")) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "p.html"));
  r = t2("animate intersect-circular back.t2 -o p.html");  // the circular sweep takes it
  EXPECT_EQ(r.status, 0) << r.err;
}

}  // namespace
}  // namespace t2::testing
