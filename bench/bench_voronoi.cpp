// t2::voronoi (the dual of the Delaunay complex, exact) against t2::delaunay, Boost.Polygon's
// Voronoi sweep and CGAL's Delaunay dual, on the same points in one run: CPU times and ratios.
//
//   bench_voronoi --benchmark_filter=Dual     10⁵ and 10⁶ uniform points
//   bench_voronoi --benchmark_filter=Fortune  t2::fortune against Boost.Polygon, 10⁵ and 10⁶,
//                                             uniform (circle:0) and a rounded circle (circle:1)
//
// The points: t2::gen's uniform points of [-1, 1)², scaled by 2³⁰ and rounded to integers,
// because Boost.Polygon takes 32-bit integer coordinates; every library gets these integers
// (as doubles, exact, w = 1 for t2). What each timing covers:
//  - delaunay: t2::delaunay (the planar triangulation with v∞);
//  - complex: t2::delaunay_complex (the whole-sphere complex, with its twins);
//  - voronoi: t2::voronoi(points) — the complex and its dual: vertices (cocircular faces merged
//    by the exact in-circle test), their cells counter-clockwise, the edges; the exact centres
//    are constructed on demand by `vertex(v)`, not here;
//  - boost: boost::polygon::construct_voronoi into a voronoi_diagram<double> (the sweep, exact
//    predicates, vertices as doubles);
//  - fortune: t2::fortune (Fortune's sweep, exact, the front half: exact vertices as GMP
//    integers, their cells, the edges and the rays to Ω);
//  - cgal_dt: CGAL's Delaunay_triangulation_2 with Epick (range insertion, spatially sorted);
//  - cgal_dual: cgal_dt plus, for every finite face, its dual (the circumcentre, a double
//    construction) and a pass over the finite edges (the Voronoi edges) — the Delaunay-dual
//    diagram as CGAL users build it, without the merge of cocircular faces.
// CPU time of the process (CLOCK_PROCESS_CPUTIME_ID): less disturbed by other load than wall time.
#include <benchmark/benchmark.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <boost/polygon/voronoi.hpp>

#include <cmath>
#include <ctime>
#include <utility>
#include <vector>

#include "t2/gen/generate.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "t2/voronoi/fortune.hpp"
#include "t2/voronoi/voronoi.hpp"

namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalDelaunay = CGAL::Delaunay_triangulation_2<Epick>;

double cpu_now() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

/// Uniform points rounded to integers of at most 2³⁰ in absolute value; with `circle`, n points
/// of the circle of radius 2³⁰ by cos and sin, rounded (jc_voronoi's "pathological" circles:
/// nearly cocircular, symmetric left to right).
std::vector<std::pair<int, int>> integer_points(std::size_t n, bool circle = false) {
  std::vector<std::pair<int, int>> out;
  if (circle) {
    for (std::size_t k = 0; k < n; ++k) {
      const double t = 2 * M_PI * double(k) / double(n);
      out.emplace_back(static_cast<int>(std::lround(std::cos(t) * 1073741824.0)),
                       static_cast<int>(std::lround(std::sin(t) * 1073741824.0)));
    }
    return out;
  }
  t2::gen::Options o;
  o.n = n;
  o.seed = 42;
  for (const t2::Point& p : t2::gen::points(t2::gen::Kind::uniform, o))
    out.emplace_back(static_cast<int>(std::lround(p.x() / p.w() * 1073741824.0)),
                     static_cast<int>(std::lround(p.y() / p.w() * 1073741824.0)));
  return out;
}

/// Boost.Polygon's sweep on bp: its CPU time; its vertex count goes to a counter.
double time_boost(const std::vector<boost::polygon::point_data<int>>& bp, benchmark::State& state) {
  boost::polygon::voronoi_diagram<double> bvd;
  const double t0 = cpu_now();
  boost::polygon::construct_voronoi(bp.begin(), bp.end(), &bvd);
  benchmark::DoNotOptimize(bvd.num_vertices());
  const double t = cpu_now() - t0;
  state.counters["boost_vertices"] = double(bvd.num_vertices());
  return t;
}

void Dual(benchmark::State& state) {
  const auto ip = integer_points(static_cast<std::size_t>(state.range(0)));
  std::vector<t2::Point> pts;
  std::vector<boost::polygon::point_data<int>> bp;
  std::vector<Epick::Point_2> cp;
  for (auto [x, y] : ip) {
    pts.push_back(t2::Point::cartesian(x, y));
    bp.emplace_back(x, y);
    cp.emplace_back(x, y);
  }
  double td = 0, tc = 0, tv = 0, tb = 0, tg = 0, tgd = 0;
  for (auto _ : state) {
    double t0 = cpu_now();
    benchmark::DoNotOptimize(t2::delaunay(pts).size());
    double t1 = cpu_now();
    td += t1 - t0;
    benchmark::DoNotOptimize(t2::delaunay_complex(pts).faces.size());
    t0 = cpu_now();
    tc += t0 - t1;
    {
      const t2::VoronoiDiagram vd = t2::voronoi(pts);
      benchmark::DoNotOptimize(vd.size());
      t1 = cpu_now();
      tv += t1 - t0;
      state.counters["t2_vertices"] = double(vd.size());
    }
    tb += time_boost(bp, state);
    {
      t0 = cpu_now();
      CgalDelaunay dt(cp.begin(), cp.end());
      benchmark::DoNotOptimize(dt.number_of_faces());
      t1 = cpu_now();
      double sx = 0;
      std::size_t edges = 0;
      for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) sx += dt.dual(f).x();
      for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) ++edges;
      benchmark::DoNotOptimize(sx);
      benchmark::DoNotOptimize(edges);
      const double t2c = cpu_now();
      tg += t1 - t0;
      tgd += t2c - t0;
    }
  }
  const double k = double(state.iterations());
  state.counters["delaunay_s"] = td / k;
  state.counters["complex_s"] = tc / k;
  state.counters["voronoi_s"] = tv / k;
  state.counters["boost_s"] = tb / k;
  state.counters["cgal_dt_s"] = tg / k;
  state.counters["cgal_dual_s"] = tgd / k;
  state.counters["voronoi/delaunay"] = tv / td;
  state.counters["voronoi/boost"] = tv / tb;
}
BENCHMARK(Dual)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->Iterations(1);

void Fortune(benchmark::State& state) {
  const auto ip = integer_points(static_cast<std::size_t>(state.range(0)), state.range(1) == 1);
  std::vector<t2::Point> pts;
  std::vector<boost::polygon::point_data<int>> bp;
  for (auto [x, y] : ip) {
    pts.push_back(t2::Point::cartesian(x, y));
    bp.emplace_back(x, y);
  }
  double tf = 0, tb = 0;
  for (auto _ : state) {
    const double t0 = cpu_now();
    {
      const t2::FortuneDiagram fd = t2::fortune(pts);
      benchmark::DoNotOptimize(fd.size());
      state.counters["t2_vertices"] = double(fd.size());
    }
    tf += cpu_now() - t0;
    tb += time_boost(bp, state);
  }
  const double k = double(state.iterations());
  state.counters["fortune_s"] = tf / k;
  state.counters["boost_s"] = tb / k;
  state.counters["fortune/boost"] = tf / tb;
}
BENCHMARK(Fortune)
    ->ArgsProduct({{100000, 1000000}, {0, 1}})
    ->ArgNames({"n", "circle"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace
