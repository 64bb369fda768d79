// The kernel of a polygon: Lee and Preparata's O(n) algorithm (t2::polygon_kernel) against the
// O(n k) cuts the library had before (tests/polygon_kernel_oracle.hpp: every cut scans the whole
// region), on convex polygons (k = n: the old one is quadratic there) and star polygons (a small
// kernel: the old one is nearly linear too). Counters: ms (CPU time of the calling thread, one
// run) and corners; the slope of log ms against log n (least squares) is the exponent
// chapter 07 reports.
//
//   build/default/bin/bench_polygon_kernel                          # new: n = 10^3 ... 10^6
//   build/default/bin/bench_polygon_kernel --benchmark_filter=Old   # old: convex to 10^4
#include <benchmark/benchmark.h>

#include <ctime>
#include <map>
#include <utility>
#include <vector>

#include "polygon_kernel_oracle.hpp"
#include "t2/gen/generate.hpp"
#include "t2/hull/polygon_kernel.hpp"

namespace {

const t2::Polygon& input(t2::gen::Kind k, std::size_t n) {
  static std::map<std::pair<t2::gen::Kind, std::size_t>, t2::Polygon> cache;
  auto it = cache.find({k, n});
  if (it == cache.end()) {
    t2::gen::Options o;
    o.n = n;
    o.seed = 1;
    it = cache.emplace(std::make_pair(k, n), t2::gen::polygon(k, o)).first;
  }
  return it->second;
}

double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

void kernel_run(benchmark::State& state, t2::gen::Kind k, bool old) {
  const t2::Polygon& P = input(k, static_cast<std::size_t>(state.range(0)));
  double ms = 0;
  std::size_t corners = 0;
  for (auto _ : state) {
    const double t0 = thread_seconds();
    if (old) {
      corners = t2::testing::oracle_kernel(P).size();  // gen's polygons: counter-clockwise, distinct
    } else {
      corners = t2::polygon_kernel(P).vertices.size();
    }
    ms = 1e3 * (thread_seconds() - t0);
  }
  state.counters["ms"] = ms;
  state.counters["corners"] = static_cast<double>(corners);
  state.SetComplexityN(state.range(0));
}

void sizes(benchmark::internal::Benchmark* b, long top) {
  for (long n = 1000; n <= top; n *= 10) {
    b->Arg(n);
    if (3 * n <= top) b->Arg(3 * n);
  }
  b->Unit(benchmark::kMillisecond)->Iterations(1);
}

void BM_Kernel(benchmark::State& state, t2::gen::Kind k) { kernel_run(state, k, false); }
void BM_KernelOld(benchmark::State& state, t2::gen::Kind k) { kernel_run(state, k, true); }

}  // namespace

BENCHMARK_CAPTURE(BM_Kernel, convex, t2::gen::Kind::convex_polygon)->Apply([](auto* b) { sizes(b, 1'000'000); });
BENCHMARK_CAPTURE(BM_Kernel, star, t2::gen::Kind::star_polygon)->Apply([](auto* b) { sizes(b, 1'000'000); });
BENCHMARK_CAPTURE(BM_KernelOld, convex, t2::gen::Kind::convex_polygon)->Apply([](auto* b) { sizes(b, 10'000); });
BENCHMARK_CAPTURE(BM_KernelOld, star, t2::gen::Kind::star_polygon)->Apply([](auto* b) { sizes(b, 1'000'000); });
