// The kernel of a polygon: the tangent-finger cuts (t2::polygon_kernel) against the O(n k) cuts
// the library had before (tests/polygon_kernel_oracle.hpp: every cut scans the whole region), on
// convex polygons (k = n: the old one is quadratic there) and star polygons (a small kernel: the
// old one is nearly linear too). Counters: ms (CPU time of the calling thread, one run) and
// corners; the slope of log ms against log n (least squares) is the exponent chapter 07 reports.
//
// The spiral family is the finger cuts' bad case: a thin band that winds first around an m-gon,
// then through T turns of three vertices each (n = 2(2m + 3T) about). The region left of the
// first edges keeps about m corners, the band's kernel is empty but no cut empties the region
// before the inner side comes, and each turn sends both fingers around all m corners: Θ(m·T)
// climbing steps. The counter `steps` is m·T.
//
//   build/default/bin/bench_polygon_kernel                             # n = 10^3 ... 10^6
//   build/default/bin/bench_polygon_kernel --benchmark_filter=Old      # old: convex to 10^4
//   build/default/bin/bench_polygon_kernel --benchmark_filter=Spiral   # m = 10^3, 10^4; T up to 10^3
#include <benchmark/benchmark.h>

#include <cmath>
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

// The band of /work/notes/spiral_kernel_gen.py: turn j of the outer side has k_j vertices at
// angles 2π(j + i/k_j), k_0 = m, then halving down to 3, then T turns of 3; each turn's radius
// is grown so that it clears the previous one. The inner side is the outer one scaled by 0.995,
// walked back. Coordinates rounded to integers (up to about 10^10 for T = 1000).
t2::Polygon spiral(long m, long T) {
  std::vector<long> ks{m};
  for (long k = m; k > 3;) ks.push_back(k = std::max(3L, k / 2));
  ks.insert(ks.end(), static_cast<std::size_t>(T), 3);
  std::vector<std::pair<double, double>> outer;  // (angle, radius)
  double rho = 1e9;
  for (std::size_t j = 0; j < ks.size(); ++j) {
    const double k = static_cast<double>(ks[j]);
    if (j > 0) rho = ks[j - 1] != 3 || ks[j] != 3 ? rho * 1.01 / std::cos(M_PI / k) * 1.03 : rho * 1.01;
    for (long i = 0; i < ks[j]; ++i)
      outer.emplace_back(2 * M_PI * (static_cast<double>(j) + static_cast<double>(i) / k),
                         rho * std::pow(1.01, static_cast<double>(i) / k));
  }
  t2::Polygon P;
  for (const auto& [t, r] : outer) P.push_back(t2::Point::cartesian(std::round(r * std::cos(t)), std::round(r * std::sin(t))));
  for (auto it = outer.rbegin(); it != outer.rend(); ++it)
    P.push_back(t2::Point::cartesian(std::round(0.995 * it->second * std::cos(it->first)),
                                     std::round(0.995 * it->second * std::sin(it->first))));
  return P;
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

void BM_KernelSpiral(benchmark::State& state) {
  const t2::Polygon P = spiral(state.range(0), state.range(1));
  double ms = 0;
  std::size_t corners = 0;
  for (auto _ : state) {
    const double t0 = thread_seconds();
    corners = t2::polygon_kernel(P).vertices.size();
    ms = 1e3 * (thread_seconds() - t0);
  }
  state.counters["ms"] = ms;
  state.counters["n"] = static_cast<double>(P.size());
  state.counters["corners"] = static_cast<double>(corners);
  state.counters["steps"] = static_cast<double>(state.range(0) * state.range(1));
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
BENCHMARK(BM_KernelSpiral)
    ->ArgsProduct({{1000}, {10, 30, 100, 300, 1000}})
    ->ArgsProduct({{10000}, {10, 30, 100}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
