// Segment intersection (chapter 13): t2's sweep and brute force against CGAL's
// compute_intersection_points (the surface sweep, exact kernel Epeck) on the same segments
// (t2::gen::segments: n segments with exactly n crossings). Wall time per run, one iteration
// each (they are long); the brute force only up to 10^4 segments (it is quadratic).
//
//   build/default/bench/bench_intersect
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Surface_sweep_2_algorithms.h>
#include <benchmark/benchmark.h>

#include <iterator>
#include <map>
#include <vector>

#include "t2/gen/generate.hpp"
#include "t2/intersect/intersections.hpp"

namespace {

using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;

const std::vector<t2::Segment>& input(std::size_t n) {
  static std::map<std::size_t, std::vector<t2::Segment>> cache;
  auto it = cache.find(n);
  if (it == cache.end()) {
    t2::gen::Options o;
    o.n = n;
    o.crossings = n;
    o.seed = 1;
    it = cache.emplace(n, t2::gen::segments(o)).first;
  }
  return it->second;
}

void BM_Sweep(benchmark::State& st) {
  const auto& S = input(static_cast<std::size_t>(st.range(0)));
  std::size_t k = 0;
  for (auto _ : st) k = t2::intersections_sweep(S).size();
  st.counters["points"] = static_cast<double>(k);
}

void BM_Brute(benchmark::State& st) {
  const auto& S = input(static_cast<std::size_t>(st.range(0)));
  std::size_t k = 0;
  for (auto _ : st) k = t2::intersections_brute(S).size();
  st.counters["points"] = static_cast<double>(k);
}

void BM_Cgal(benchmark::State& st) {
  const auto& S = input(static_cast<std::size_t>(st.range(0)));
  std::vector<Epeck::Segment_2> in;
  for (const auto& s : S)  // the generator's points have w = 1
    in.emplace_back(Epeck::Point_2(s.source().x(), s.source().y()), Epeck::Point_2(s.target().x(), s.target().y()));
  std::size_t k = 0;
  for (auto _ : st) {
    std::vector<Epeck::Point_2> out;
    CGAL::compute_intersection_points(in.begin(), in.end(), std::back_inserter(out), false);
    k = out.size();
  }
  st.counters["points"] = static_cast<double>(k);
}

}  // namespace

BENCHMARK(BM_Sweep)->Arg(10'000)->Arg(100'000)->Iterations(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Cgal)->Arg(10'000)->Arg(100'000)->Iterations(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Brute)->Arg(10'000)->Iterations(1)->Unit(benchmark::kMillisecond)->UseRealTime();
