// t2::voronoi (the dual of the Delaunay complex) against t2::delaunay on the same uniform front
// points in one run: CPU times of delaunay, delaunay_complex and voronoi, and their ratios.
//
//   bench_voronoi --benchmark_filter=Dual     10⁵ and 10⁶ uniform points
#include <benchmark/benchmark.h>

#include <ctime>
#include <vector>

#include "t2/gen/generate.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "t2/voronoi/voronoi.hpp"

namespace {

double cpu_now() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

void Dual(benchmark::State& state) {
  t2::gen::Options o;
  o.n = static_cast<std::size_t>(state.range(0));
  o.seed = 42;
  const std::vector<t2::Point> pts = t2::gen::points(t2::gen::Kind::uniform, o);
  double td = 0, tc = 0, tv = 0;
  for (auto _ : state) {
    double t0 = cpu_now();
    benchmark::DoNotOptimize(t2::delaunay(pts).size());
    double t1 = cpu_now();
    benchmark::DoNotOptimize(t2::delaunay_complex(pts).faces.size());
    double t2c = cpu_now();
    const t2::VoronoiDiagram vd = t2::voronoi(pts);
    benchmark::DoNotOptimize(vd.vertices.size());
    double t3 = cpu_now();
    td += t1 - t0, tc += t2c - t1, tv += t3 - t2c;
  }
  const double k = double(state.iterations());
  state.counters["delaunay_s"] = td / k;
  state.counters["complex_s"] = tc / k;
  state.counters["voronoi_s"] = tv / k;
  state.counters["voronoi/delaunay"] = tv / td;
}
BENCHMARK(Dual)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
