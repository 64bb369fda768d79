// The registry of the algorithms (tools/t2/algorithms/registry.hpp) is the one list: its entries
// are complete (a registered problem, peers that solve it, a scene for every plane algorithm);
// an entry's plain run and its animation give the same answer; and everything else that names
// algorithms agrees with it: the help of t2 animate and t2 bench, the benchmark worker (it runs
// every registered implementation of every problem it solves, and the exact ones agree), and the
// book (every animated algorithm has a page, and no page names another). An algorithm added
// without its registration, or registered without its page, fails here.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "algorithms/registry.hpp"
#include "cli_testing.hpp"
#include "t2/gen/generate.hpp"
#include "t2/trace/recording.hpp"

namespace t2::testing {
namespace {

namespace reg = t2cli::algorithms;

bool serves(const reg::Peer& p, const std::string& problem) {
  return std::find(p.problems.begin(), p.problems.end(), problem) != p.problems.end();
}

TEST(Registry, EveryEntryIsComplete) {
  ASSERT_GE(reg::all().size(), 10u);
  std::set<std::string> names;
  for (const auto& a : reg::all()) {
    SCOPED_TRACE(a.name);
    EXPECT_TRUE(names.insert(a.name).second);
    const reg::Problem* pr = reg::find_problem(a.problem);
    ASSERT_NE(pr, nullptr) << "unregistered problem " << a.problem;
    EXPECT_FALSE(a.summary.empty());
    EXPECT_FALSE(a.title.empty());
    EXPECT_TRUE(a.animates() || a.time) << "neither animated nor timed: nothing reads it";
    if (a.run) {
      EXPECT_EQ(pr->input, reg::Input::plane) << "only a plane algorithm's answer is a scene";
    }
    if (a.record) {  // an animation's last step is checked against the plain run's scene
      EXPECT_EQ(pr->input, reg::Input::plane);
      EXPECT_TRUE(a.run);
    }
    if (a.record_segments) {  // its answer is checked by tests/test_animate_segments.cpp
      EXPECT_EQ(pr->input, reg::Input::segments);
      EXPECT_FALSE(a.record) << "one recorder an entry";
    }
    for (const auto& p : a.peers) {
      const reg::Algorithm* other = reg::find(p);
      const reg::Peer* peer = reg::find_peer(p);
      EXPECT_TRUE((other && other->time && other->problem == a.problem) || (peer && serves(*peer, a.problem)))
          << p << " is no peer of " << a.name;
      EXPECT_TRUE(a.time) << "peers, but no timed run";
    }
  }
  for (const auto& p : reg::peers()) {
    EXPECT_TRUE(names.insert(p.name).second) << p.name << " names an algorithm and a peer";
    for (const auto& pr : p.problems) EXPECT_NE(reg::find_problem(pr), nullptr) << p.name << ": " << pr;
  }
  // what `t2 hull`, `t2 triangulate`, `t2 delaunay` and `t2 hull3d` run has the command's name
  for (const char* name : {"hull", "triangulate", "delaunay", "hull3d", "layers", "intersect", "voronoi"}) EXPECT_NE(reg::find(name), nullptr);
}

// The vertices of each polygon of a scene, as points.
std::vector<std::vector<Point>> polygons(const Scene& s) {
  std::vector<std::vector<Point>> v;
  for (const auto& p : s.polygons) {
    v.emplace_back();
    for (const auto& q : p.vertices) v.back().push_back(q.point);
  }
  return v;
}

// On front and on both-sides input, an animated algorithm's last step is its plain run's answer:
// the same hull (as a cycle of points) or the same triangles.
TEST(Registry, TheAnimationEndsWithTheRunsAnswer) {
  gen::Options o;
  o.n = 9;
  int compared = 0;
  for (gen::Kind k : {gen::Kind::uniform, gen::Kind::both_sides})
    for (const auto* a : reg::animated()) {
      if (!a->record) continue;  // a recorder of segments (tests/test_animate_segments.cpp)
      SCOPED_TRACE(a->name + (k == gen::Kind::uniform ? " uniform" : " both sides"));
      const std::vector<Point> P = gen::points(k, o);
      trace::Recording rec;
      try {
        a->record(P, "in.t2", rec);
      } catch (const BadInput& e) {  // animated on front points only
        EXPECT_NE(k, gen::Kind::uniform) << e.what();
        continue;
      } catch (const Undefined& e) {  // off the front side (Fortune), no answer on both sides (lec)
        EXPECT_NE(k, gen::Kind::uniform) << e.what();
        continue;
      }
      ASSERT_FALSE(rec.steps().empty());
      const trace::Step& last = rec.steps().back();
      ASSERT_EQ(last.kind, "answer");
      const auto want = polygons(a->run(P));
      std::vector<std::vector<Point>> got;
      if (last.structure == "hull") {
        got.emplace_back();
        for (std::size_t i : last.chain) got.back().push_back(P[i]);
        ASSERT_EQ(want.size(), 1u);
        ASSERT_EQ(got[0].size(), want[0].size());
        auto at = std::find(want[0].begin(), want[0].end(), got[0].front());  // the same cycle, from its start
        ASSERT_NE(at, want[0].end());
        std::vector<Point> cycle(at, want[0].end());
        cycle.insert(cycle.end(), want[0].begin(), at);
        EXPECT_EQ(got[0], cycle);
      } else if (last.structure == "Voronoi diagram") {  // the same scene: vertices, edges, rays
        const Scene run = a->run(P);
        ASSERT_EQ(last.overlay.points.size(), run.points.size());
        for (std::size_t v = 0; v < run.points.size(); ++v) EXPECT_EQ(last.overlay.points[v].point, run.points[v].point);
        ASSERT_EQ(last.overlay.segments.size(), run.segments.size());
        EXPECT_GT(run.segments.size(), 0u);
      } else {
        for (const auto& t : last.triangles) got.push_back({P[t[0]], P[t[1]], P[t[2]]});
        EXPECT_EQ(got, want);
      }
      ++compared;
    }
  EXPECT_GE(compared, 8);
}

class RegistryCli : public CliTest {};

// The help of t2 animate lists exactly the animated algorithms, that of t2 bench the timed
// ones and every peer, each with its summary.
TEST_F(RegistryCli, TheHelpTextsListTheRegistry) {
  const Result animate = t2("help animate"), bench = t2("help bench");
  ASSERT_EQ(animate.status, 0) << animate.err;
  ASSERT_EQ(bench.status, 0) << bench.err;
  std::vector<std::string> animated, timed;
  for (const auto* a : reg::animated()) animated.push_back(a->name);
  for (const auto* a : reg::timed()) timed.push_back(a->name);
  EXPECT_TRUE(has(animate.out, reg::words(animated))) << animate.out;  // ALGO's help line
  EXPECT_TRUE(has(bench.out, "the t2 algorithm: " + reg::words(timed))) << bench.out;
  for (const auto& a : reg::all()) {
    EXPECT_EQ(has(animate.out, a.name + " ") && has(animate.out, a.summary), a.animates()) << a.name;
    if (a.time) {
      EXPECT_TRUE(has(bench.out, a.summary)) << a.name;
    }
  }
  for (const auto& p : reg::peers()) EXPECT_TRUE(has(bench.out, p.summary)) << p.name;
  for (const char* gone : {"merge-hull", "  sweep "}) EXPECT_FALSE(has(animate.out, gone)) << gone;  // old names
}

// The worker runs every registered implementation of every problem it solves, refuses others,
// and the exact ones agree on the answer's size.
TEST_F(RegistryCli, TheWorkerRunsEveryRegisteredImplementation) {
  const fs::path worker = fs::path(T2_BINARY_DIR) / "bin" / "t2_bench_worker";
  if (!fs::exists(worker)) GTEST_SKIP() << "t2_bench_worker is not built (libqhull-dev missing)";
  std::map<std::string, std::vector<std::pair<std::string, bool>>> by_problem;  // name, exact
  for (const auto* a : reg::timed()) by_problem[a->problem].push_back({a->name, true});
  for (const auto& p : reg::peers())
    for (const auto& pr : p.problems) by_problem[pr].push_back({p.name, p.exact});
  for (const auto& [problem, impls] : by_problem) {
    const reg::Input kind = reg::find_problem(problem)->input;
    const std::string input = kind == reg::Input::space ? "cube" : kind == reg::Input::segments ? "segments" : "disk";
    std::set<std::string> exact_sizes;
    for (const auto& [name, exact] : impls) {
      const Shell r = shell(worker.string() + " " + problem + " " + name + " " + input + " 300 7");
      EXPECT_EQ(r.status, 0) << problem << " " << name << ": " << r.out;
      std::smatch m;
      ASSERT_TRUE(std::regex_search(r.out, m, std::regex("^size=(\\d+) "))) << problem << " " << name << r.out;
      if (exact) exact_sizes.insert(m[1]);
    }
    EXPECT_EQ(exact_sizes.size(), 1u) << problem << ": the exact implementations disagree";
    EXPECT_EQ(shell(worker.string() + " " + problem + " frob " + input + " 10 1").status, 2) << problem;
  }
  EXPECT_EQ(shell(worker.string() + " frob hull disk 10 1").status, 2);
}

// Every animated algorithm has a page in the book, and every page's command names one.
TEST(RegistryBook, EveryAnimatedAlgorithmHasAPage) {
  const std::regex command(R"(t2 animate ([a-z0-9-]+) (\S+) -o ([a-z0-9-]+\.html))");
  std::set<std::string> in_book, registered;
  for (const auto& e : fs::recursive_directory_iterator(fs::path(T2_SOURCE_DIR) / "chapters")) {
    if (!std::regex_match(e.path().filename().string(), std::regex("chapter(-[0-9]+)?\\.md"))) continue;
    const std::string md = slurp(e.path());
    for (std::sregex_iterator m(md.begin(), md.end(), command), end; m != end; ++m) in_book.insert((*m)[1]);
  }
  for (const auto* a : reg::animated()) registered.insert(a->name);
  EXPECT_EQ(in_book, registered);
}

}  // namespace
}  // namespace t2::testing
