// Point location (chapter 14, t2/location/), timed by `t2 bench locate`: the walk of seed
// 000's Algorithm 15 on the Delaunay triangulation of the input points, each query starting at
// the last query found inside a face (before there is one, at a vertex of the last answer's
// face). The triangulation and the queries are made before the clock starts (the worker's peers
// get the same queries: locate_queries).
#include "algorithms/location.hpp"

#include <algorithm>
#include <memory>
#include <random>

#include "algorithms/registry.hpp"
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

// The timed run: every query walked, from the last query inside a face.
Timed walk_run(BenchInput& in, bool sorted) {
  const t2::Triangulation T = t2::delaunay(in.points);
  std::vector<std::vector<t2::Subdivision::Index>> F;
  for (const auto& t : T.finite_triangles()) F.push_back({t[0], t[1], t[2]});
  auto S = std::make_shared<const t2::Subdivision>(in.points, F);
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

T2_ALGORITHM({.name = "walk-sorted",
              .problem = "locate",
              .summary = "t2::walk with the queries in spatial order (each starts near the last answer)",
              .title = "point location by walking, spatially sorted queries",
              .time = [](BenchInput& in) -> Timed { return walk_run(in, true); }});

}  // namespace
}  // namespace t2cli::algorithms
