// t2::delaunay against CGAL's Delaunay_triangulation_2 (Epick, range insertion, which sorts
// spatially) on the same points in one run: both CPU times, their ratio, t2's bytes per point.
//
//   bench_delaunay --benchmark_filter='Compare'        times and ratio, 10⁶ points per input
//   bench_delaunay --benchmark_filter='Rss/t2/uniform' peak memory of one construction alone
//   bench_delaunay --benchmark_filter='Rss/cgal/uniform'  (run each Rss case in its own process:
//                                                       maxrss never goes down)
//   bench_delaunay --benchmark_filter='Raw'            the same code on raw doubles (inexact)
//   bench_delaunay --benchmark_filter='Trace'          the trace hooks off against counting
//   bench_delaunay --benchmark_filter='Sides'          T² input (both-sides, antipodal) against
//                                                       uniform front input of the same size
//
// Inputs come from t2::gen: uniform, normal (one cluster), grid, circle (rounded), clustered
// (64 normal clusters). Set T2_BENCH_N to change the size (default 10⁶).
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <ctime>
#include <cstdlib>
#include <string>
#include <vector>

#include "t2/kernel/filter.hpp"
#include "t2/gen/generate.hpp"
#include "t2/kernel/incircle.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "raw_kernel.hpp"

namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalDelaunay = CGAL::Delaunay_triangulation_2<Epick>;

std::size_t bench_n() {
  const char* s = std::getenv("T2_BENCH_N");
  return s != nullptr ? std::stoul(s) : 1000000;
}

const char* const kInputs[] = {"uniform", "normal", "grid", "circle", "clustered"};

std::vector<t2::Point> make_input(int which, std::size_t n) {
  t2::gen::Options o;
  o.n = n;
  o.seed = 42;
  const std::string name = kInputs[which];
  t2::gen::Kind k = t2::gen::Kind::uniform;
  if (name == "normal") {
    k = t2::gen::Kind::normal;
    o.clusters = 1;
  } else if (name == "clustered") {
    k = t2::gen::Kind::normal;
    o.clusters = 64;
  } else if (name == "grid") {
    k = t2::gen::Kind::grid;
  } else if (name == "circle") {
    k = t2::gen::Kind::circle;
    o.cartesian = true;
  }
  auto pts = t2::gen::points(k, o);
  for (auto& p : pts)  // w = 1 for both libraries (already so for these kinds)
    if (p.w() != 1) p = t2::Point::cartesian(p.x() / p.w(), p.y() / p.w());
  return pts;
}

// CPU time of the process (single-threaded code): less disturbed by other load than wall time.
double cpu_now() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// Times and ratio on the same points, in the same process.
void Compare(benchmark::State& state) {
  const int which = static_cast<int>(state.range(0));
  const auto pts = make_input(which, bench_n());
  const auto cpts = t2bench::to_cgal(pts);
  double t2_time = 0, cgal_time = 0, bytes = 0, exact = 0;
  std::size_t triangles = 0, cgal_faces = 0;
  for (auto _ : state) {
    t2::filter_stats().reset();
    double t0 = cpu_now();
    const t2::Triangulation tr = t2::delaunay(pts);
    t2_time += (cpu_now() - t0);
    exact = double(t2::filter_stats().exact) / double(std::max<std::uint64_t>(1, t2::filter_stats().calls));
    bytes = double(tr.memory_bytes()) / double(pts.size());
    triangles = tr.finite_triangles().size();
    t0 = cpu_now();
    CgalDelaunay dt;
    dt.insert(cpts.begin(), cpts.end());
    cgal_time += (cpu_now() - t0);
    cgal_faces = dt.number_of_faces();
    benchmark::DoNotOptimize(cgal_faces);
  }
  const double it = double(state.iterations());
  state.counters["t2_s"] = t2_time / it;
  state.counters["cgal_s"] = cgal_time / it;
  state.counters["ratio"] = t2_time / cgal_time;
  state.counters["t2_B/pt"] = bytes;
  state.counters["exact_share"] = exact;
  state.counters["same_count"] = triangles == cgal_faces ? 1 : 0;
  state.SetLabel(kInputs[which]);
}
BENCHMARK(Compare)->DenseRange(0, 4)->Iterations(2)->Unit(benchmark::kSecond);

// Peak resident memory of one construction: run each case alone (maxrss never decreases).
void Rss(benchmark::State& state, bool t2_side) {
  const int which = static_cast<int>(state.range(0));
  for (auto _ : state) {
    auto pts = make_input(which, bench_n());
    const std::size_t n = pts.size();
    if (t2_side) {
      const t2::Triangulation tr = t2::delaunay(pts);  // the input stays alive, as a caller's would
      benchmark::DoNotOptimize(tr.size());
    } else {
      const auto cpts = t2bench::to_cgal(pts);
      pts = {};
      pts.shrink_to_fit();
      CgalDelaunay dt;
      dt.insert(cpts.begin(), cpts.end());
      benchmark::DoNotOptimize(dt.number_of_faces());
    }
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    state.counters["maxrss_B/pt"] = double(u.ru_maxrss) * 1024.0 / double(n);
  }
  state.SetLabel(std::string(t2_side ? "t2/" : "cgal/") + kInputs[which]);
}
BENCHMARK_CAPTURE(Rss, t2, true)->DenseRange(0, 4)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(Rss, cgal, false)->DenseRange(0, 4)->Iterations(1)->Unit(benchmark::kSecond);

void Raw(benchmark::State& state) {
  const auto pts = make_input(0, bench_n());
  double exact_time = 0, raw_time = 0;
  for (auto _ : state) {
    double t0 = cpu_now();
    benchmark::DoNotOptimize(t2::delaunay(pts).size());
    exact_time += (cpu_now() - t0);
    t0 = cpu_now();
    benchmark::DoNotOptimize(t2::delaunay_with<t2bench::RawDelaunayTraits>(pts).size());
    raw_time += (cpu_now() - t0);
  }
  state.counters["exact_s"] = exact_time / double(state.iterations());
  state.counters["raw_s"] = raw_time / double(state.iterations());
  state.counters["exact/raw"] = exact_time / raw_time;
}
BENCHMARK(Raw)->Iterations(2)->Unit(benchmark::kSecond);

// The trace hook of delaunay_with (t2/trace/hook.hpp, which t2 animate's recorder fills):
// NoTrace, the default, against a hook that counts every report (each insertion, flip and
// in-circle test), on the same points in one run. The default's time against plain `delaunay`
// before the hook existed says that it costs nothing when off.
struct CountingHook {
  long* calls;
  void operator()(const t2::trace::Report&) { ++*calls; }
};

void Trace(benchmark::State& state) {
  const auto pts = make_input(0, bench_n());
  double off = 0, counting = 0;
  long calls = 0;
  for (auto _ : state) {
    double t0 = cpu_now();
    benchmark::DoNotOptimize(t2::delaunay(pts).size());
    off += cpu_now() - t0;
    t0 = cpu_now();
    benchmark::DoNotOptimize(t2::delaunay_with(pts, t2::DelaunayTraits{}, CountingHook{&calls}).size());
    counting += cpu_now() - t0;
  }
  const double it = double(state.iterations());
  state.counters["off_s"] = off / it;
  state.counters["counting_s"] = counting / it;
  state.counters["counting/off"] = counting / off;
  state.counters["hook_calls"] = double(calls) / it;
}
BENCHMARK(Trace)->Iterations(3)->Unit(benchmark::kSecond);

// T² input (delaunay_t2.hpp): gen's both-sides (half behind, a hull across Ω) and antipodal (no
// hull: the sphere), timed against uniform front points of the same size in the same run.
void Sides(benchmark::State& state) {
  t2::gen::Options o;
  o.n = bench_n();
  o.seed = 42;
  o.back = 0.5;
  const auto front = make_input(0, o.n);
  const auto kind = state.range(0) == 0 ? t2::gen::Kind::both_sides : t2::gen::Kind::antipodal;
  const auto pts = t2::gen::points(kind, o);
  double front_time = 0, t2_time = 0;
  for (auto _ : state) {
    double t0 = cpu_now();
    benchmark::DoNotOptimize(t2::delaunay(front).size());
    front_time += (cpu_now() - t0);
    t0 = cpu_now();
    benchmark::DoNotOptimize(t2::delaunay(pts).size());
    t2_time += (cpu_now() - t0);
  }
  state.counters["front_s"] = front_time / double(state.iterations());
  state.counters["t2_s"] = t2_time / double(state.iterations());
  state.counters["t2/front"] = t2_time / front_time;
  state.SetLabel(std::string(t2::gen::name(kind)));
}
BENCHMARK(Sides)->DenseRange(0, 1)->Iterations(2)->Unit(benchmark::kSecond);

}  // namespace
