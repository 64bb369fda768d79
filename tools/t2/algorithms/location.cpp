// Point location (chapter 14, t2/location/), timed by `t2 bench locate`: the walk of seed
// 000's Algorithm 15 on the Delaunay triangulation of the input points, each query starting at
// the last query found inside a face (before there is one, at a vertex of the last answer's
// face). The triangulation and the queries are made before the clock starts (the worker's peers
// get the same queries: locate_queries). The trapezoidal maps of trapezoid_locate.hpp answer the
// same queries with their structure built before the clock; `locate-build` times what each
// method builds from the points: the Delaunay triangulation and the half-edges (walk-build),
// and the trapezoidal maps on top (trapezoid-build); CGAL's is its triangulation.
#include "algorithms/location.hpp"

#include <algorithm>
#include <memory>
#include <random>

#include "algorithms/registry.hpp"
#include "t2/location/trapezoid_locate.hpp"
#include "t2/location/walk.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "t2/triangulation/spatial_sort.hpp"

namespace t2cli::algorithms {

std::vector<t2::Point> locate_queries(std::span<const t2::Point> points, bool sorted) {
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  if (!points.empty()) {
    x0 = x1 = points[0].x() / points[0].w();
    y0 = y1 = points[0].y() / points[0].w();
  }
  for (const auto& p : points) {
    x0 = std::min(x0, p.x() / p.w()), x1 = std::max(x1, p.x() / p.w());
    y0 = std::min(y0, p.y() / p.w()), y1 = std::max(y1, p.y() / p.w());
  }
  std::mt19937_64 rng(0x1414);
  std::uniform_real_distribution<double> X(x0, x1), Y(y0, y1);
  std::vector<t2::Point> Q;
  Q.reserve(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) Q.push_back(t2::Point::cartesian(X(rng), Y(rng)));
  if (sorted) {
    const auto order = t2::spatial_order(Q);
    std::vector<t2::Point> S;
    S.reserve(Q.size());
    for (const auto i : order) S.push_back(Q[i]);
    Q.swap(S);
  }
  return Q;
}

namespace {

T2_PROBLEM({"locate", "queries in a face", Input::plane});
T2_PROBLEM({"locate-build", "faces", Input::plane});

// The map of the bench: the Delaunay triangles of the points.
std::shared_ptr<const t2::Subdivision> delaunay_map(const std::vector<t2::Point>& points) {
  const t2::Triangulation T = t2::delaunay(points);
  std::vector<std::vector<t2::Subdivision::Index>> F;
  for (const auto& t : T.finite_triangles()) F.push_back({t[0], t[1], t[2]});
  return std::make_shared<const t2::Subdivision>(points, F);
}

// The timed run: every query walked, from the last query inside a face.
Timed walk_run(BenchInput& in, bool sorted) {
  auto S = delaunay_map(in.points);
  auto Q = std::make_shared<const std::vector<t2::Point>>(locate_queries(in.points, sorted));
  return [S, Q] {
    std::size_t inside = 0;
    t2::Subdivision::Index from = S->org(0);
    const t2::Point* last = nullptr;  // the last query strictly inside a face, and that face
    t2::Subdivision::Index face = 0;
    for (const auto& q : *Q) {
      const t2::Location l = last ? t2::walk(*S, q, *last, face) : t2::walk(*S, q, from);
      if (l.kind == t2::Location::Kind::outside) continue;
      ++inside;
      from = S->org(S->first(l.face) + l.k);
      if (l.kind == t2::Location::Kind::face) last = &q, face = l.face;
    }
    return inside;
  };
}

T2_ALGORITHM({.name = "walk",
              .problem = "locate",
              .summary = "t2::walk: seed 000's Algorithm 15 on the Delaunay triangulation, queries in random order",
              .title = "point location by walking (Algorithm 15)",
              .time = [](BenchInput& in) -> Timed { return walk_run(in, false); },
              .peers = {"cgal", "walk-sorted", "cgal-sorted"}});

// The timed run: every query answered by the trapezoidal maps (built before the clock).
Timed trapezoid_run(BenchInput& in) {
  auto S = delaunay_map(in.points);
  auto L = std::make_shared<const t2::TrapezoidLocator>(*S);
  auto Q = std::make_shared<const std::vector<t2::Point>>(locate_queries(in.points, false));
  return [S, L, Q] {
    std::size_t inside = 0;
    for (const auto& q : *Q) inside += L->locate(q).kind != t2::Location::Kind::outside;
    return inside;
  };
}

T2_ALGORITHM({.name = "trapezoid",
              .problem = "locate",
              .summary = "t2::TrapezoidLocator: the trapezoidal map and its history DAG (randomized incremental) "
                         "on the Delaunay triangulation, queries in random order",
              .title = "point location by a trapezoidal map",
              .time = [](BenchInput& in) -> Timed { return trapezoid_run(in); },
              .peers = {"walk", "cgal"}});

T2_ALGORITHM({.name = "walk-build",
              .problem = "locate-build",
              .summary = "what the walk needs: t2::delaunay of the points and the t2::Subdivision of its triangles",
              .title = "the walk's preprocessing",
              .time = [](BenchInput& in) -> Timed {
                return [&P = in.points] { return delaunay_map(P)->faces(); };
              }});

T2_ALGORITHM({.name = "trapezoid-build",
              .problem = "locate-build",
              .summary = "walk-build, then t2::TrapezoidLocator's trapezoidal maps on the triangles",
              .title = "the trapezoidal map's preprocessing",
              .time = [](BenchInput& in) -> Timed {
                return [&P = in.points] {
                  const auto S = delaunay_map(P);
                  const t2::TrapezoidLocator L(*S);
                  return S->faces();
                };
              },
              .peers = {"walk-build", "cgal"}});

T2_ALGORITHM({.name = "walk-sorted",
              .problem = "locate",
              .summary = "t2::walk with the queries in spatial order (each starts near the last answer)",
              .title = "point location by walking, spatially sorted queries",
              .time = [](BenchInput& in) -> Timed { return walk_run(in, true); }});

}  // namespace
}  // namespace t2cli::algorithms
