// `t2 bench`: the harness's arithmetic (the fitted exponent on data with a known one, the log
// steps, medians), its plot, the worker's line, and the command itself on small n: the table,
// the plot and CSV files, the answers of t2 and its peers compared, a disagreement reported
// loudly (through a fake worker), a missing worker named, bad arguments exiting 2.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <t2/draw/loglog.hpp>

#include "bench_progress.hpp"
#include "bench_run.hpp"
#include "bench_stats.hpp"
#include "cli_testing.hpp"
#include "testing.hpp"

namespace {

using t2::testing::has;
using t2::testing::slurp;

TEST(BenchFit, RecoversAKnownExponent) {
  for (double e : {0.5, 1.0, 1.5, 2.0}) {
    std::vector<double> n, t;
    for (double x : {10.0, 100.0, 3000.0, 1e5, 1e7}) n.push_back(x), t.push_back(3e-9 * std::pow(x, e));
    const t2::draw::PowerLaw f = t2::draw::fit_power_law(n, t);
    EXPECT_NEAR(f.exponent, e, 1e-12);
    EXPECT_NEAR(f.constant / 3e-9, 1, 1e-9);
    EXPECT_EQ(f.points, 5u);
  }
}

TEST(BenchFit, LeastSquaresOfScatteredPoints) {
  // log t = 1, 2, 2, 3 at log n = 0, 1, 1, 2 (natural logs): slope 1 by hand.
  const double e = std::exp(1.0);
  const std::vector<double> n = {1, e, e, e * e}, t = {e, e * e, e * e, e * e * e};
  EXPECT_NEAR(t2::draw::fit_power_law(n, t).exponent, 1, 1e-12);
  // log t = 0, 1, 0, 1 at log n = 0, 0, 1, 1: slope 0.
  const std::vector<double> n2 = {1, 1, e, e}, t2v = {1, e, 1, e};
  EXPECT_NEAR(t2::draw::fit_power_law(n2, t2v).exponent, 0, 1e-12);
}

TEST(BenchFit, UndefinedWithOneSize) {
  const std::vector<double> n = {1000, 1000}, t = {0.1, 0.2};
  EXPECT_FALSE(t2::draw::fit_defined(n, t));
  const std::vector<double> n2 = {1000, 2000}, t2v = {0.1, 0};  // a zero time is left out
  EXPECT_FALSE(t2::draw::fit_defined(n2, t2v));
}

TEST(BenchSteps, LogarithmicFromN1ToN2) {
  EXPECT_EQ(t2bench::log_steps(1000, 1000000, 2),
            (std::vector<std::size_t>{1000, 3162, 10000, 31623, 100000, 316228, 1000000}));
  EXPECT_EQ(t2bench::log_steps(1000, 5000, 1), (std::vector<std::size_t>{1000, 5000}));
  EXPECT_EQ(t2bench::log_steps(7, 7, 3), (std::vector<std::size_t>{7}));
  EXPECT_EQ(t2bench::log_steps(1, 3, 10), (std::vector<std::size_t>{1, 2, 3}));  // strictly increasing
}

TEST(BenchSteps, ParseRange) {
  EXPECT_EQ(t2bench::parse_range("10..200"), (std::pair<std::size_t, std::size_t>{10, 200}));
  for (const char* bad : {"10", "10..", "..5", "5..1", "0..5", "1e3..1e4", "-1..5", "a..b"})
    EXPECT_THROW(t2bench::parse_range(bad), std::invalid_argument) << bad;
}

TEST(BenchStats, Median) {
  EXPECT_EQ(t2bench::median({3, 1, 2}), 2);
  EXPECT_EQ(t2bench::median({4, 1, 3, 2}), 2.5);
  EXPECT_EQ(t2bench::median({}), 0);
}

TEST(BenchRun, WorkerLine) {
  const auto m = t2bench::parse_worker_line("size=12 wall=0.5 cpu=0.25 input_rss_kb=2048\n");
  EXPECT_EQ(m.size, 12u);
  EXPECT_EQ(m.wall, 0.5);
  EXPECT_EQ(m.cpu, 0.25);
  EXPECT_EQ(m.input_rss_kb, 2048);
  EXPECT_THROW(t2bench::parse_worker_line("size=12 wall=0.5 cpu=0.25"), std::runtime_error);
  EXPECT_THROW(t2bench::parse_worker_line("size=x wall=0.5 cpu=0.25 input_rss_kb=1"), std::runtime_error);
}

std::size_t count(const std::string& text, const std::string& part) {
  std::size_t k = 0;
  for (auto p = text.find(part); p != std::string::npos; p = text.find(part, p + 1)) ++k;
  return k;
}

// The progress line is kept current during one long run: with a tick of 20 ms the line appears
// once the benchmark has lasted a tick, is rewritten in place (each write begins with "\r" and
// the erase-line sequence, none ends a line) during the run, and is erased at the end. Nothing
// at all when it is not shown, or for a benchmark shorter than a tick.
TEST(BenchProgress, ALongRunIsShownWhileItRuns) {
  using namespace std::chrono_literals;
  const std::string erase = "\r\033[K";
  ::testing::internal::CaptureStderr();
  {
    t2bench::Progress p(2, 20ms, true);
    std::this_thread::sleep_for(30ms);
    p.start(1, "layers", 5000);
    std::this_thread::sleep_for(300ms);  // one long run
  }
  const std::string err = ::testing::internal::GetCapturedStderr();
  const std::string text = erase + "t2 bench: run 1/2: layers on n = 5000 (";
  EXPECT_EQ(err.rfind(text, 0), 0u) << err;                     // at the start of the run
  EXPECT_GE(count(err, text), 3u) << err;                         // and again while it lasts
  EXPECT_EQ(count(err, erase), count(err, text) + 1) << err;      // then erased
  EXPECT_EQ(err.substr(err.size() - erase.size()), erase) << err;
  EXPECT_EQ(err.find('\n'), std::string::npos) << err;           // in place: never a new line
  for (bool shown : {false, true}) {
    ::testing::internal::CaptureStderr();
    {
      t2bench::Progress p(3, shown ? 10s : 10ms, shown);
      p.start(1, "hull", 10);
      std::this_thread::sleep_for(30ms);
    }
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "") << shown;
  }
  EXPECT_EQ(t2bench::Progress::line(3, 8, "delaunay", 100000, 61.4, 12.6),
            "t2 bench: run 3/8: delaunay on n = 100000 (61 s so far, this run 13 s)");
}

// Shown on a terminal every second, on any stderr with T2_BENCH_PROGRESS=SECONDS; a bad value
// is refused.
TEST(BenchProgress, Setting) {
  using t2bench::Progress;
  EXPECT_TRUE(Progress::setting(true, nullptr).shown);
  EXPECT_EQ(Progress::setting(true, nullptr).tick.count(), 1.0);
  EXPECT_FALSE(Progress::setting(false, nullptr).shown);
  EXPECT_TRUE(Progress::setting(false, "0.25").shown);
  EXPECT_EQ(Progress::setting(false, "0.25").tick.count(), 0.25);
  for (const char* bad : {"", "0", "-1", "x", "1s", "nan", "1e9"})
    EXPECT_THROW(Progress::setting(false, bad), std::invalid_argument) << bad;
}

TEST(BenchPlot, SvgWithOneLinePerSeries) {
  const t2::draw::Series a{"a", {1e3, 1e4, 1e5}, {1e-3, 1e-2, 1e-1}};
  const t2::draw::Series b{"b", {1e3, 1e4, 1e5}, {1e-3, 1e-1, 10}};
  const std::string one = t2::draw::loglog_svg({a}, "title", "seconds");
  const std::string two = t2::draw::loglog_svg({a, b}, "title", "seconds");
  for (const auto* svg : {&one, &two}) {
    EXPECT_EQ(svg->rfind("<?xml", 0), 0u);
    EXPECT_TRUE(has(*svg, "<svg")) << *svg;
    EXPECT_TRUE(has(*svg, "width=\"640pt\"")) << *svg;
    EXPECT_TRUE(has(*svg, "</svg>"));
  }
  EXPECT_GT(count(two, "<path"), count(one, "<path"));  // the second series adds its lines
  EXPECT_EQ(one, t2::draw::loglog_svg({a}, "title", "seconds"));  // deterministic
}

// Rows of the table: impl -> (n -> size).
std::map<std::string, std::map<std::size_t, std::size_t>> table(const std::string& out) {
  std::map<std::string, std::map<std::size_t, std::size_t>> rows;
  std::istringstream in(out);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("impl", 0) == 0 || line.rfind("growth", 0) == 0 ||
        line.rfind("note", 0) == 0)
      continue;
    std::istringstream f(line);
    std::string name;
    std::size_t n = 0, size = 0;
    if (f >> name >> n >> size) rows[name][n] = size;
  }
  return rows;
}

class CliBench : public t2::testing::CliTest {};

TEST_F(CliBench, HullAgainstCgalAndQhull) {
  const auto r = t2("bench hull --n 1000 --plot p.svg --csv t.csv");
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  const auto rows = table(r.out);
  ASSERT_EQ(rows.size(), 3u) << r.out;
  const std::size_t h = rows.at("hull").at(1000);
  EXPECT_GT(h, 3u);
  EXPECT_EQ(rows.at("cgal").at(1000), h) << r.out;
  EXPECT_EQ(rows.at("qhull").at(1000), h) << r.out;
  EXPECT_TRUE(has(slurp(dir_ / "p.svg"), "<svg"));
  const std::string csv = slurp(dir_ / "t.csv");
  EXPECT_EQ(count(csv, "\n"), 4u) << csv;
  EXPECT_TRUE(has(csv, "cgal,1000," + std::to_string(h) + ",")) << csv;
  EXPECT_EQ(files(), (std::vector<std::string>{"p.svg", "t.csv"}));  // no temporary left behind
}

TEST_F(CliBench, DelaunayExactnessPeersAgree) {
  const auto r = t2("bench delaunay --n 2000 --input clustered --vs cgal,raw,exact");
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  const auto rows = table(r.out);
  ASSERT_EQ(rows.size(), 4u) << r.out;
  const std::size_t t = rows.at("delaunay").at(2000);
  EXPECT_GT(t, 2000u);
  for (const char* peer : {"cgal", "exact"}) EXPECT_EQ(rows.at(peer).at(2000), t) << peer << "\n" << r.out;
  const auto h = t2("bench hull --n 2000 --input disk --vs raw,exact,monotone,quickhull,merge");
  ASSERT_EQ(h.status, 0) << h.err << h.out;
  const auto hull_rows = table(h.out);
  ASSERT_EQ(hull_rows.size(), 6u) << h.out;
  for (const auto& [name, sizes] : hull_rows) EXPECT_EQ(sizes.at(2000), hull_rows.at("hull").at(2000)) << name;
}

TEST_F(CliBench, RangeFitsAGrowthExponent) {
  const auto r = t2("bench graham --range 300..3000 --per-decade 1 --input circle --repeat 2 --plot gj.svg");
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  const auto rows = table(r.out);
  ASSERT_EQ(rows.at("graham").size(), 2u);
  ASSERT_EQ(rows.at("jarvis").size(), 2u);
  EXPECT_EQ(rows.at("graham").at(3000), rows.at("jarvis").at(3000));
  EXPECT_TRUE(has(r.out, "growth (least squares on log cpu time against log n): graham n^")) << r.out;
  EXPECT_TRUE(has(r.out, ", jarvis n^")) << r.out;
  EXPECT_TRUE(has(slurp(dir_ / "gj.svg"), "</svg>"));
}

// t2 and the exact peers give answers of the same size on every input of issues 13 and 14: 1000
// points, or 1000 * T2_SCALE under the `long` label (tests/long.cmake).
TEST_F(CliBench, PeersAgreeOnEveryInput) {
  const std::size_t n = 1000 * static_cast<std::size_t>(t2::testing::scale());
  const std::pair<const char*, const char*> runs[] = {
      {"hull --vs cgal,qhull", "uniform"},       {"hull --vs cgal,qhull", "disk"},
      {"hull --vs cgal,qhull", "circle"},        {"hull --vs cgal,qhull", "kuzmin"},
      {"delaunay --vs divide,cgal", "uniform"},  {"delaunay --vs divide,cgal", "normal"},
      {"delaunay --vs divide,cgal", "grid"},     {"delaunay --vs divide,cgal", "circle"},
      {"delaunay --vs divide,cgal", "clustered"}};
  for (const auto& [what, input] : runs) {
    const auto r = t2(std::string("bench ") + what + " --n " + std::to_string(n) + " --input " + input);
    EXPECT_EQ(r.status, 0) << what << " " << input << "\n" << r.err << r.out;
    const auto rows = table(r.out);
    const std::size_t size = rows.begin()->second.at(n);
    for (const auto& [name, sizes] : rows)  // qhull too, though the harness only notes its differences
      EXPECT_EQ(sizes.at(n), size) << name << " " << what << " " << input << "\n" << r.out;
  }
}

// The convex layers both ways of seed 003 (Jarvis and Graham peeling) give the same layers.
TEST_F(CliBench, ConvexLayersBothWays) {
  const auto r = t2("bench layers --n 400 --input disk");
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  const auto rows = table(r.out);
  ASSERT_EQ(rows.size(), 2u) << r.out;
  EXPECT_GT(rows.at("layers").at(400), 5u);
  EXPECT_EQ(rows.at("layers-graham").at(400), rows.at("layers").at(400));
  EXPECT_EQ(t2("bench layers --vs cgal").status, 2);
}

// Hulls in R³: t2's three algorithms, CGAL's convex_hull_3 and qhull find the same number of
// vertices on the cube and on the sphere (hull3d takes no plane input, and plane algorithms no
// 3-D input).
TEST_F(CliBench, Hull3dAgainstCgalAndQhull) {
  for (const char* input : {"cube", "sphere"}) {
    const auto r = t2(std::string("bench hull3d --n 600 --input ") + input + " --vs incremental,gift-wrap,cgal,qhull");
    ASSERT_EQ(r.status, 0) << input << "\n" << r.err << r.out;
    const auto rows = table(r.out);
    ASSERT_EQ(rows.size(), 5u) << r.out;
    const std::size_t v = rows.at("hull3d").at(600);
    EXPECT_GT(v, 20u) << r.out;
    for (const auto& [name, sizes] : rows) EXPECT_EQ(sizes.at(600), v) << name << " " << input << "\n" << r.out;
  }
  const auto d = t2("bench hull3d --n 300");  // the default input is the cube, the peers CGAL and qhull
  ASSERT_EQ(d.status, 0) << d.err;
  EXPECT_TRUE(has(d.out, "--input cube")) << d.out;
  EXPECT_EQ(table(d.out).size(), 3u) << d.out;
  for (const char* args : {"bench hull3d --input uniform", "bench hull --input sphere", "bench hull --vs gift-wrap",
                           "bench hull3d --vs raw", "bench hull3d --vs jarvis", "bench delaunay --vs incremental"})
    EXPECT_EQ(t2(args).status, 2) << args;
}

// The progress line goes to stderr only, and only when stderr is a terminal or it is asked for:
// forced at a 1 ms tick on a run of several sizes, stderr holds the lines rewritten in place and
// then erased, and stdout is the same table as without it (same rows, no control character).
TEST_F(CliBench, ProgressLineOnStderrOnly) {
  const std::string args = "bench graham --range 300..3000 --per-decade 1 --repeat 2";
  const auto plain = t2(args);  // stderr is a pipe here: no line
  ASSERT_EQ(plain.status, 0) << plain.err << plain.out;
  EXPECT_EQ(plain.err, "");
  ::setenv("T2_BENCH_PROGRESS", "0.001", 1);
  const auto shown = t2(args);
  ::setenv("T2_BENCH_PROGRESS", "soon", 1);
  const auto bad = t2(args);
  ::unsetenv("T2_BENCH_PROGRESS");
  ASSERT_EQ(shown.status, 0) << shown.err << shown.out;
  EXPECT_TRUE(has(shown.err, "\r\033[Kt2 bench: run 8/8: jarvis on n = 3000 (")) << shown.err;
  EXPECT_EQ(shown.err.substr(shown.err.size() - 4), "\r\033[K") << shown.err;
  EXPECT_EQ(shown.err.find('\n'), std::string::npos) << shown.err;
  EXPECT_EQ(table(shown.out), table(plain.out)) << shown.out;
  EXPECT_EQ(count(shown.out, "\n"), count(plain.out, "\n")) << shown.out;
  for (char c : {'\r', '\033'}) EXPECT_EQ(shown.out.find(c), std::string::npos) << shown.out;
  EXPECT_FALSE(has(shown.out, "t2 bench: run")) << shown.out;
  EXPECT_EQ(bad.status, 2) << bad.err;
  EXPECT_TRUE(has(bad.err, "T2_BENCH_PROGRESS=soon")) << bad.err;
}

// A worker that answers 8 for t2 and 7 for CGAL: the command must fail and say so.
TEST_F(CliBench, DisagreementFailsLoudly) {
  const auto fake = write("fake_worker",
                          "#!/bin/sh\ncase \"$2\" in cgal) s=7;; *) s=8;; esac\n"
                          "echo \"size=$s wall=0.01 cpu=0.01 input_rss_kb=100\"\n");
  ::chmod(fake.c_str(), 0755);
  ::setenv("T2_BENCH_WORKER", fake.c_str(), 1);
  const auto r = t2("bench hull --n 100 --vs cgal");
  ::unsetenv("T2_BENCH_WORKER");
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_TRUE(has(r.err, "ANSWERS DIFFER: n = 100: hull has 8 vertices, cgal has 7")) << r.err;
  EXPECT_TRUE(has(r.out, "NO")) << r.out;
}

TEST_F(CliBench, MissingWorkerIsNamed) {
  ::setenv("T2_BENCH_WORKER", (dir_ / "no_such_worker").c_str(), 1);
  const auto r = t2("bench hull --n 100 --plot p.svg");
  ::unsetenv("T2_BENCH_WORKER");
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(has(r.err, "t2_bench_worker is not built")) << r.err;
  EXPECT_TRUE(has(r.err, "--target t2_bench_worker")) << r.err;
  EXPECT_TRUE(files().empty());
}

TEST_F(CliBench, BadArgumentsExit2) {
  for (const char* args : {"bench", "bench sort", "bench hull --input nope", "bench delaunay --vs qhull",
                           "bench graham --vs raw", "bench hull --vs raw,frob", "bench hull --n 0", "bench hull --range 10..5",
                           "bench hull --range 1000", "bench hull --n 5 --range 1..10", "bench hull --repeat 0",
                           "bench hull --vs hull", "bench hull --frob"}) {
    const auto r = t2(args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
    EXPECT_TRUE(has(r.err, "t2 bench")) << args << "\n" << r.err;
    EXPECT_TRUE(files().empty());
  }
}

}  // namespace
