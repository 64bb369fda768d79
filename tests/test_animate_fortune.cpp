// Fortune's sweep animated (t2/trace/fortune_recorder.hpp, `t2 animate fortune`): the hook
// changes nothing in t2::fortune; the sweep's events come in order of an exact sweep height
// (y of a site, c_y + √R of a circle, compared exactly with GMP); one lecture circle event per
// Voronoi vertex in general position; every overlay circle passes exactly through its three
// sites and its vertex is their exact circumcentre; the last step's vertices are those of the
// untraced t2::fortune and the circumcentres of t2::delaunay's triangles (an independent
// construction); a page of 200 points weighs at most 1 MB; bad and back input exit 2 and 3.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "algorithms/registry.hpp"
#include "animate_testing.hpp"
#include "cli_testing.hpp"
#include "t2/kernel/number.hpp"
#include "t2/trace/fortune_recorder.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "t2/voronoi/fortune.hpp"
#include "voronoi_inputs.hpp"

namespace t2::testing {
namespace {

using trace::Depth;
using trace::Event;
using trace::Recording;
using trace::Report;
using trace::Step;

/// n distinct sites with integer coordinates in [−range, range]²: their circumcentres have
/// small homogeneous integers, exact in doubles.
std::vector<Point> integer_sites(std::size_t n, int range, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> d(-range, range);
  std::vector<Point> p;
  while (p.size() < n) {
    const Point q = Point::cartesian(d(rng), d(rng));
    if (std::find(p.begin(), p.end(), q) == p.end()) p.push_back(q);
  }
  return p;
}

/// x/w and y/w of a point, exactly.
Rational ex(const Point& p) { return Rational(p.x()) / Rational(p.w()); }
Rational ey(const Point& p) { return Rational(p.y()) / Rational(p.w()); }
Rational ex(const ExactPoint& p) { return Rational(p.x(), p.w()); }
Rational ey(const ExactPoint& p) { return Rational(p.y(), p.w()); }

/// A sweep height c + √R (R = 0 for a site), exact.
struct Height {
  Rational c, R;
};

/// sign(a + b√r), exact (b, r rationals, r ≥ 0).
int sign_root(const Rational& a, const Rational& b, const Rational& r) {
  const int sa = sgn(a), sb = sgn(b) * (sgn(r) > 0);
  if (sa == sb || sb == 0) return sa != 0 ? sa : sb;
  if (sa == 0) return sb;
  const int m = sgn(Rational(a * a - b * b * r));  // |a| against |b|√r
  return m == 0 ? 0 : m > 0 ? sa : sb;
}

/// sign(h − k) for heights h = c + √R, k = d + √S: sign((c − d) + √R − √S).
int compare(const Height& h, const Height& k) {
  const Rational e = h.c - k.c;
  const int u = sign_root(e, Rational(1), h.R);  // e + √R, compared with √S ≥ 0
  if (u < 0) return -1;
  if (u == 0) return sgn(k.R) > 0 ? -1 : 0;
  return sign_root(Rational(e * e + h.R - k.R), Rational(2 * e), h.R);  // (e + √R)² − S
}

/// The exact height of the sweep at a site or circle report.
Height height(const std::vector<Point>& P, const Report& r) {
  if (r.event == Event::site) return {ey(P[r.at[0]]), 0};
  const ExactPoint c = circumcentre(P[r.at[0]], P[r.at[1]], P[r.at[2]]);
  const Rational dx = ex(P[r.at[0]]) - ex(c), dy = ey(P[r.at[0]]) - ey(c);
  return {ey(c), dx * dx + dy * dy};
}

bool same(const FortuneDiagram& a, const FortuneDiagram& b) {
  if (a.circles != b.circles || a.cells != b.cells || a.lines != b.lines || a.rays.size() != b.rays.size())
    return false;
  for (std::size_t k = 0; k < a.edges.size(); ++k)
    if (a.edges[k].a != b.edges[k].a || a.edges[k].b != b.edges[k].b) return false;
  for (std::size_t k = 0; k < a.rays.size(); ++k)
    if (a.rays[k].a != b.rays[k].a || !(a.rays[k].end == b.rays[k].end)) return false;
  return a.edges.size() == b.edges.size();
}

/// Every vertex has three sites: no four cocircular sites met (general position).
bool general(const FortuneDiagram& d) {
  for (FortuneDiagram::Index v = 0; v < d.size(); ++v)
    if (d.vertex_sites(v).size() != 3) return false;
  return true;
}

std::vector<std::vector<Point>> inputs() {
  std::vector<std::vector<Point>> v;
  std::mt19937 rng(11);
  for (std::size_t n : {2, 3, 9, 40, 120}) v.push_back(scattered_sites(n, 1, rng));
  for (unsigned seed = 1; seed <= 4; ++seed) v.push_back(integer_sites(20 * seed, 400, seed));
  v.push_back(grid_sites(60, 4, 1, rng));  // duplicates, collinear and cocircular sites
  v.push_back({Point::cartesian(0, 0), Point::cartesian(2, 0), Point::cartesian(4, 0), Point::cartesian(1, 3)});
  return v;
}

TEST(FortuneTrace, ChangesNothingAndSweepsUpExactly) {
  int circles = 0, alarms = 0, tests = 0, splits = 0;
  for (const auto& P : inputs()) {
    SCOPED_TRACE(fmt::format("{} sites", P.size()));
    std::vector<Report> reports;
    std::vector<std::vector<std::size_t>> beach;
    const FortuneDiagram traced = fortune(P, [&](const Report& r) {
      reports.push_back(r);
      beach.emplace_back(r.chain.begin(), r.chain.end());
    });
    const FortuneDiagram plain = fortune(P);
    ASSERT_TRUE(same(traced, plain));
    std::size_t sites = 0, made = 0;
    std::vector<std::size_t> seen;  // the sites swept so far
    const Report* last = nullptr;
    for (std::size_t k = 0; k < reports.size(); ++k) {
      const Report& r = reports[k];
      EXPECT_EQ(beach[k].empty(), false);
      if (r.event == Event::site) {
        ++sites;
        EXPECT_NE(std::find(beach[k].begin(), beach[k].end(), r.at[0]), beach[k].end()) << "the new arc is there";
        if (r.at[1] != Report::none) {  // the arc it splits is highest above it (brute force, rationals)
          const Rational a = ex(P[r.at[0]]), L = ey(P[r.at[0]]);
          auto above = [&](std::size_t i) {  // the parabola of site i at x = a, sweep y = L
            const Rational dx = a - ex(P[i]), y = ey(P[i]);
            return Rational((dx * dx + y * y - L * L) / (2 * (y - L)));
          };
          std::optional<Rational> top;
          for (std::size_t i : seen)
            if (ey(P[i]) < L && (!top || above(i) > *top)) top = above(i);
          ASSERT_TRUE(top.has_value());
          EXPECT_EQ(above(r.at[1]), *top) << "p" << r.at[0] << " splits the arc of p" << r.at[1];
          ++splits;
        }
        seen.push_back(r.at[0]);
      }
      if (r.event == Event::circle) {
        ++made;
        EXPECT_EQ(std::find(beach[k].begin(), beach[k].end(), r.at[1]) == beach[k].end(),
                  std::count(beach[k - 1].begin(), beach[k - 1].end(), r.at[1]) == 1)
            << "the arc of the middle site is gone";
      }
      if (r.event == Event::site || r.event == Event::circle) {
        if (last) {
          EXPECT_LE(compare(height(P, *last), height(P, r)), 0) << "the sweep line moves up";
        }
        last = &r;
      }
      alarms += r.event == Event::false_alarm;
      tests += r.event == Event::breakpoint;
    }
    EXPECT_EQ(sites, P.size() - plain.duplicates.size());
    if (general(plain)) {
      EXPECT_EQ(made, plain.size()) << "one circle event per Voronoi vertex";
    }
    EXPECT_GE(made, plain.size());
    circles += int(made);
  }
  EXPECT_GT(circles, 100);
  EXPECT_GT(alarms, 10);
  EXPECT_GT(tests, 100);
  EXPECT_GT(splits, 200);
}

/// The recording of t2::fortune on P, and the untraced answer.
Recording record(const std::vector<Point>& P, FortuneDiagram& answer) {
  Recording rec;
  trace::FortuneRecorder r(P, rec);
  answer = fortune(P, std::ref(r));
  r.finish();
  return rec;
}

TEST(FortuneRecorder, CirclesAndVerticesAreExact) {
  int checked = 0;
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const std::vector<Point> P = integer_sites(15 * seed, 300, 100 + seed);
    FortuneDiagram d;
    const Recording rec = record(P, d);
    std::size_t lecture_circles = 0;
    double swept = -1e300;
    for (const Step& s : rec.steps()) {
      ASSERT_FALSE(s.overlay.segments.empty()) << s.text;  // the sweep line first, horizontal
      const Point &a = s.overlay.segments[0].a.point, &b = s.overlay.segments[0].b.point;
      EXPECT_EQ(a.y() / a.w(), b.y() / b.w());
      if (s.kind == "site" || s.kind == "locate") {
        EXPECT_EQ(a.y() / a.w(), P[s.points[0]].y()) << "the sweep line passes through the site";
      }
      EXPECT_EQ(s.depth == Depth::lecture, s.kind == "site" || s.kind == "circle") << s.kind;
      EXPECT_TRUE(s.kind == "site" || s.kind == "circle" || s.kind == "locate" || s.kind == "false alarm") << s.kind;
      if (s.depth == Depth::lecture) {  // the sweep moves up (doubles: the drawn line)
        EXPECT_LE(swept, a.y() / a.w()) << s.text;
        swept = a.y() / a.w();
      }
      if (s.overlay.circles.empty()) continue;
      ASSERT_EQ(s.points.size(), 3u);
      const auto& c = s.overlay.circles[0];
      const ExactPoint o = to_exact(c.center.point);
      EXPECT_EQ(o, circumcentre(P[s.points[1]], P[s.points[0]], P[s.points[2]]));
      EXPECT_EQ(c.through.point, P[s.points[1]]) << "the boundary point is a site";
      const auto d2 = [&](const Point& p) {
        const Rational dx = ex(p) - ex(o), dy = ey(p) - ey(o);
        return Rational(dx * dx + dy * dy);
      };
      for (std::size_t i : s.points) EXPECT_EQ(d2(P[i]), d2(c.through.point)) << s.text;
      if (s.kind == "circle") {
        ++lecture_circles;
        ASSERT_EQ(s.overlay.points.size(), 1u);
        EXPECT_EQ(to_exact(s.overlay.points[0].point), o) << "the new vertex is the circle's centre";
      }
      ++checked;
    }
    ASSERT_TRUE(general(d)) << "seed " << seed;
    EXPECT_EQ(lecture_circles, d.size());
    EXPECT_EQ(rec.at(Depth::lecture).size(), P.size() + d.size());
  }
  EXPECT_GT(checked, 200);
}

TEST(FortuneRecorder, TheLastStepIsTheUntracedDiagram) {
  const auto* algo = t2cli::algorithms::find("fortune");
  ASSERT_TRUE(algo != nullptr && algo->record);
  for (unsigned seed = 1; seed <= 4; ++seed) {
    const std::vector<Point> P = integer_sites(25 * seed, 500, 200 + seed);
    Recording rec;
    algo->record(P, "test", rec);  // what `t2 animate fortune` records
    const FortuneDiagram plain = fortune(P);
    ASSERT_TRUE(general(plain));
    const Step& last = rec.back();
    ASSERT_EQ(last.kind, "answer");
    // its vertices: the untraced answer's, in order, exactly (small integers: doubles are exact)
    ASSERT_EQ(last.overlay.points.size(), plain.size());
    for (FortuneDiagram::Index v = 0; v < plain.size(); ++v)
      EXPECT_EQ(to_exact(last.overlay.points[v].point), plain.vertex(v));
    // and the circumcentres of the Delaunay triangles, one each
    const auto tris = delaunay(P).finite_triangles();
    ASSERT_EQ(tris.size(), plain.size());
    for (const auto& f : tris) {
      const ExactPoint c = circumcentre(P[f[0]], P[f[1]], P[f[2]]);
      EXPECT_EQ(std::count_if(last.overlay.points.begin(), last.overlay.points.end(),
                              [&](const ScenePoint& v) { return to_exact(v.point) == c; }),
                1);
    }
    // its segments: the edges, then the rays to their point of Ω
    ASSERT_EQ(last.overlay.segments.size(), plain.edges.size() + plain.rays.size());
    for (std::size_t k = 0; k < plain.rays.size(); ++k) {
      const auto& s = last.overlay.segments[plain.edges.size() + k];
      EXPECT_EQ(to_exact(s.a.point), plain.vertex(plain.rays[k].a));
      EXPECT_EQ(to_exact(s.b.point), plain.rays[k].end);
    }
    // the edges finished by the last circle event are all of the answer's edges
    const Step* circle = nullptr;
    for (const Step& s : rec.steps())
      if (s.kind == "circle") circle = &s;
    ASSERT_NE(circle, nullptr);
    EXPECT_EQ(circle->overlay.segments.size(), plain.edges.size() + 1) << "the sweep line, then every edge";
    for (const auto& e : std::span(circle->overlay.segments).subspan(1)) {
      const ExactPoint a = to_exact(e.a.point), b = to_exact(e.b.point);
      EXPECT_TRUE(std::any_of(plain.edges.begin(), plain.edges.end(), [&](const auto& f) {
        return (plain.vertex(f.a) == a && plain.vertex(f.b) == b) || (plain.vertex(f.a) == b && plain.vertex(f.b) == a);
      }));
    }
  }
}

class AnimateFortune : public CliTest {};

TEST_F(AnimateFortune, EndsWithTheDiagramOfT2Voronoi) {
  write("s.t2", "0 0\n4 0\n5 3\n2 5\n-1 3\n1 2\n");
  const Result r = t2("animate fortune s.t2 -o f.html");
  ASSERT_EQ(r.status, 0) << r.err;
  const Result v = t2("voronoi s.t2 --algorithm fortune");
  ASSERT_EQ(v.status, 0) << v.err;
  const auto steps = page_steps(slurp(dir_ / "f.html"));
  ASSERT_GE(steps.size(), 3u);
  EXPECT_EQ(steps.front().step.at("kind"), "input");
  EXPECT_EQ(steps.back().step.at("kind"), "answer");
  std::size_t nv = 0, ne = 0, nr = 0;
  for (std::size_t at = 0; at < v.out.size();) {
    const std::size_t end = v.out.find('\n', at);
    const std::string line = v.out.substr(at, end - at);
    nv += line.rfind("vertex", 0) == 0, ne += line.rfind("edge", 0) == 0, nr += line.rfind("ray", 0) == 0;
    at = end == std::string::npos ? v.out.size() : end + 1;
  }
  EXPECT_EQ(steps.back().step.at("text").get<std::string>(),
            fmt::format("The Voronoi diagram (its front half): {} vertices, {} edges, {} rays to Omega, 0 bisector "
                        "lines.",
                        nv, ne, nr));
  int circles = 0;
  for (const auto& s : steps) circles += s.step.at("kind") == "circle";
  EXPECT_EQ(circles, int(nv));
}

// The beach line is drawn as arcs up to FortuneRecorder::kCurveSites sites, its heaviest part:
// 30 sites with their arcs weigh at most 1 MB. (200 sites, without arcs: 3.4 MB, measured, most of
// it the 200 labels every animation draws; not run here: 90 s at -O2.)
TEST_F(AnimateFortune, ThirtyPointsWithTheirArcsWeighAtMostOneMegabyte) {
  ASSERT_EQ(t2("gen uniform --n 30 --seed 5 -o p.t2").status, 0);
  const Result r = t2("animate fortune p.t2 -o f.html");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_LE(std::filesystem::file_size(dir_ / "f.html"), 1000000u) << r.out;
  EXPECT_TRUE(has(page_data(slurp(dir_ / "f.html")), "\"kind\":\"circle\""));
}

TEST_F(AnimateFortune, BackAndBadInputExitWithTheFileNamed) {
  write("out.html", "old");
  struct Case {
    const char *file, *text;
    int status;  // 3 (undefined) for a site off the front side, as t2 voronoi --algorithm fortune
    const char* says;
  };
  for (const Case& c : {Case{"back.t2", "0 0\n1 0\n-1 -1 -2\n", 3, "front side"}, Case{"bad.t2", "0 0\n1 x\n", 2, ":2:"}}) {
    write(c.file, c.text);
    const Result bad = t2(fmt::format("animate fortune {} -o out.html", c.file));
    EXPECT_EQ(bad.status, c.status) << c.file;
    EXPECT_TRUE(has(bad.err, c.file) && has(bad.err, c.says)) << bad.err;
    EXPECT_EQ(slurp(dir_ / "out.html"), "old");
  }
  write("one.t2", "1 1\n");  // one site: no event beyond it, no vertex
  const Result r = t2("animate fortune one.t2 -o out.html");
  EXPECT_EQ(r.status, 0) << r.err;
}

}  // namespace
}  // namespace t2::testing
