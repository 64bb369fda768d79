// Algorithm 9 on T² (t2::triangulate_t2): the points inserted in the spatial order on the sphere
// (sphere_order, the default) against the input order of the seed, on the generators with points
// behind (antipodal: no hull, the sphere covered; both-sides: a hull across Ω all along). One run
// per size (single-threaded: the CPU column is the time); the slope of log time against log n
// between sizes is the growth chapter 09 §6 reports.
//
//   build/default/bin/bench_triangulate_t2                              # spatial, n = 10^3 ... 10^6
//   build/default/bin/bench_triangulate_t2 --benchmark_filter=Input     # input order, to 10^4
#include <benchmark/benchmark.h>

#include <vector>

#include "t2/gen/generate.hpp"
#include "t2/triangulation/triangulate_t2.hpp"

namespace {

void run(benchmark::State& state, t2::gen::Kind k, t2::InsertionOrder how) {
  t2::gen::Options o;
  o.n = static_cast<std::size_t>(state.range(0));
  o.seed = 1;
  const std::vector<t2::Point> P = t2::gen::points(k, o);  // outside the timed loop
  std::size_t faces = 0;
  for (auto _ : state) faces = t2::triangulate_t2(P, how).tr.size();
  state.counters["faces"] = static_cast<double>(faces);
  state.SetComplexityN(state.range(0));
}

void sizes(benchmark::internal::Benchmark* b, long top) {
  b->RangeMultiplier(10)->Range(1000, top)->Unit(benchmark::kMillisecond)->Iterations(1);
}

void BM_Spatial(benchmark::State& state, t2::gen::Kind k) { run(state, k, t2::InsertionOrder::spatial); }
void BM_Input(benchmark::State& state, t2::gen::Kind k) { run(state, k, t2::InsertionOrder::input); }

}  // namespace

BENCHMARK_CAPTURE(BM_Spatial, antipodal, t2::gen::Kind::antipodal)->Apply([](auto* b) { sizes(b, 1'000'000); });
BENCHMARK_CAPTURE(BM_Spatial, both_sides, t2::gen::Kind::both_sides)->Apply([](auto* b) { sizes(b, 1'000'000); });
BENCHMARK_CAPTURE(BM_Input, antipodal, t2::gen::Kind::antipodal)->Apply([](auto* b) { sizes(b, 10'000); });
BENCHMARK_CAPTURE(BM_Input, both_sides, t2::gen::Kind::both_sides)->Apply([](auto* b) { sizes(b, 10'000); });
