// The 3-D hull: t2 (Quickhull order and random incremental order, exact orient3d) against
// CGAL's convex_hull_3 (Epick, into a Surface_mesh) on the same points, in one run: for each
// input, the counters t2_ms, cgal_ms (best of the iterations, in CPU time of the calling thread:
// both are single-threaded, and CPU time stays meaningful on a shared machine), ratio = t2 /
// CGAL, the number of hull triangles (same_f: CGAL has as many).
//
//   build/default/bin/bench_hull3d                    # 10^6 points (T2_BENCH_N to change)
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>
#include <benchmark/benchmark.h>

#include <algorithm>
#include <ctime>
#include <cstdlib>
#include <map>
#include <vector>

#include "t2/gen/generate.hpp"
#include "t2/hull3d.hpp"

namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;

std::size_t bench_n() {
  const char* s = std::getenv("T2_BENCH_N");
  return s ? static_cast<std::size_t>(std::atoll(s)) : 1'000'000;
}

const std::vector<t2::Point3>& input(t2::gen::Kind k) {
  static std::map<t2::gen::Kind, std::vector<t2::Point3>> cache;
  auto it = cache.find(k);
  if (it == cache.end()) {
    t2::gen::Options o;
    o.n = bench_n();
    o.seed = 1;
    std::vector<t2::Point3> P;
    for (const auto& [x, y, z] : t2::gen::points3(k, o)) P.push_back({x, y, z});
    it = cache.emplace(k, std::move(P)).first;
  }
  return it->second;
}

double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

template <class F>
double seconds(F&& f) {
  const double t0 = thread_seconds();
  f();
  return thread_seconds() - t0;
}

void BM_Hull3dVsCgal(benchmark::State& state, t2::gen::Kind k, t2::Hull3dAlgorithm a) {
  const auto& P = input(k);
  std::vector<Epick::Point_3> C;
  C.reserve(P.size());
  for (const auto& p : P) C.emplace_back(p.x, p.y, p.z);
  double best_t2 = 1e300, best_cgal = 1e300;
  std::size_t f_t2 = 0, f_cgal = 0;
  for (auto _ : state) {
    best_t2 = std::min(best_t2, seconds([&] { f_t2 = t2::convex_hull_3d(P, a).size(); }));
    best_cgal = std::min(best_cgal, seconds([&] {
      CGAL::Surface_mesh<Epick::Point_3> m;
      CGAL::convex_hull_3(C.begin(), C.end(), m);
      f_cgal = m.number_of_faces();
    }));
  }
  state.counters["n"] = static_cast<double>(P.size());
  state.counters["faces"] = static_cast<double>(f_t2);
  state.counters["same_f"] = f_t2 == f_cgal;
  state.counters["t2_ms"] = best_t2 * 1e3;
  state.counters["cgal_ms"] = best_cgal * 1e3;
  state.counters["ratio"] = best_t2 / best_cgal;
}

using K = t2::gen::Kind;
using A = t2::Hull3dAlgorithm;
BENCHMARK_CAPTURE(BM_Hull3dVsCgal, cube_quickhull, K::cube, A::quickhull)->Iterations(3)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Hull3dVsCgal, cube_incremental, K::cube, A::incremental)->Iterations(3)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Hull3dVsCgal, sphere_quickhull, K::sphere, A::quickhull)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Hull3dVsCgal, sphere_incremental, K::sphere, A::incremental)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace
