// t2::convex_hull against CGAL's ch_akl_toussaint on the same points, in one run: for each
// input, the counters t2_ms, cgal_ms (best of the iterations, in CPU time of the thread, so that
// other processes on a shared machine do not count) and ratio = t2 / CGAL.
//
//   build/default/bin/bench_hull                      # 10^7 points (T2_BENCH_N to change)
//   build/default/bin/bench_hull --benchmark_filter=Trace   # the cost of the trace hook
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/ch_akl_toussaint.h>
#include <benchmark/benchmark.h>

#include <algorithm>
#include <ctime>
#include <cstdlib>
#include <map>
#include <vector>

#include "t2/gen/generate.hpp"
#include "t2/hull.hpp"

namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;

std::size_t bench_n() {
  const char* s = std::getenv("T2_BENCH_N");
  return s ? static_cast<std::size_t>(std::atoll(s)) : 10'000'000;
}

// The points of a kind (circle: rounded Cartesian, as CGAL's Cartesian kernel needs), cached.
const std::vector<t2::Point>& input(t2::gen::Kind k) {
  static std::map<t2::gen::Kind, std::vector<t2::Point>> cache;
  auto it = cache.find(k);
  if (it == cache.end()) {
    t2::gen::Options o;
    o.n = bench_n();
    o.seed = 1;
    o.cartesian = true;
    it = cache.emplace(k, t2::gen::points(k, o)).first;
  }
  return it->second;
}

// The CPU time of this thread that f takes, in seconds.
template <class F>
double seconds(F&& f) {
  const auto now = [] {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
  };
  const double t0 = now();
  f();
  return now() - t0;
}

void BM_HullVsCgal(benchmark::State& state, t2::gen::Kind k) {
  const auto& P = input(k);
  std::vector<Epick::Point_2> C;
  C.reserve(P.size());
  for (const auto& p : P) C.emplace_back(p.x(), p.y());
  double best_t2 = 1e300, best_cgal = 1e300;
  std::size_t h_t2 = 0, h_cgal = 0;
  for (auto _ : state) {
    best_t2 = std::min(best_t2, seconds([&] { h_t2 = t2::convex_hull(P).size(); }));
    std::vector<Epick::Point_2> out;
    best_cgal = std::min(best_cgal, seconds([&] {
      CGAL::ch_akl_toussaint(C.begin(), C.end(), std::back_inserter(out));
      h_cgal = out.size();
    }));
  }
  state.counters["n"] = static_cast<double>(P.size());
  state.counters["h"] = static_cast<double>(h_t2);
  state.counters["same_h"] = h_t2 == h_cgal;
  state.counters["t2_ms"] = best_t2 * 1e3;
  state.counters["cgal_ms"] = best_cgal * 1e3;
  state.counters["ratio"] = best_t2 / best_cgal;
}

BENCHMARK_CAPTURE(BM_HullVsCgal, uniform, t2::gen::Kind::uniform)->Iterations(3)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_HullVsCgal, circle, t2::gen::Kind::circle)->Iterations(3)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_HullVsCgal, disk, t2::gen::Kind::disk)->Iterations(3)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_HullVsCgal, kuzmin, t2::gen::Kind::kuzmin)->Iterations(3)->Unit(benchmark::kMillisecond);

// The trace hook: NoTrace (the default) against a trace that counts the steps, on 10^6 points:
// the monotone chain on uniform points, and the merge of the hemisphere hulls on both sides of
// T² (its negative half's chain goes through a renumbering trace only when a trace listens).
struct CountingTrace {
  long steps = 0;
  void operator()(const t2::trace::Report&) { ++steps; }
};

std::vector<t2::Point> trace_input(t2::gen::Kind k) {
  t2::gen::Options o;
  o.n = 1'000'000;
  return t2::gen::points(k, o);
}

void BM_TraceOff(benchmark::State& state, t2::gen::Kind k, t2::HullAlgorithm a) {
  const auto P = trace_input(k);
  for (auto _ : state) benchmark::DoNotOptimize(t2::convex_hull(P, a));
}
void BM_TraceCounting(benchmark::State& state, t2::gen::Kind k, t2::HullAlgorithm a) {
  const auto P = trace_input(k);
  CountingTrace trace;
  for (auto _ : state) benchmark::DoNotOptimize(t2::convex_hull(P, a, trace));
  state.counters["steps"] = static_cast<double>(trace.steps) / static_cast<double>(state.iterations());
}
BENCHMARK_CAPTURE(BM_TraceOff, monotone, t2::gen::Kind::uniform, t2::HullAlgorithm::monotone)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_TraceCounting, monotone, t2::gen::Kind::uniform, t2::HullAlgorithm::monotone)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_TraceOff, merge, t2::gen::Kind::both_sides, t2::HullAlgorithm::merge)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_TraceCounting, merge, t2::gen::Kind::both_sides, t2::HullAlgorithm::merge)
    ->Unit(benchmark::kMillisecond);

}  // namespace
