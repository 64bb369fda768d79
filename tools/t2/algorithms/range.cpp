// Range search (chapter 15, t2/range/), timed by `t2 bench kdtree` and `t2 bench rangetree`
// (the problem `range`): building the structure on the points and reporting the points of
// every window (range_windows, made before the clock starts, the same for the worker's peers). The answer's size is the number of reports summed
// over the windows, which every exact implementation shares.
#include "algorithms/range.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

#include "algorithms/registry.hpp"
#include "t2/range/kdtree.hpp"
#include "t2/range/range_tree.hpp"

namespace t2cli::algorithms {

std::vector<std::array<double, 4>> range_windows(std::span<const t2::Point> points) {
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  if (!points.empty()) x0 = x1 = points[0].x(), y0 = y1 = points[0].y();
  for (const auto& p : points) {
    x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x());
    y0 = std::min(y0, p.y()), y1 = std::max(y1, p.y());
  }
  const std::size_t m = std::max<std::size_t>(1, points.size() / 10);
  const double f = 1 / std::sqrt(double(m)), hx = (x1 - x0) * f / 2, hy = (y1 - y0) * f / 2;
  std::mt19937_64 rng(0x1515);
  std::uniform_real_distribution<double> X(x0, x1), Y(y0, y1);
  std::vector<std::array<double, 4>> W;
  W.reserve(m);
  for (std::size_t k = 0; k < m; ++k) {
    const double cx = X(rng), cy = Y(rng);
    W.push_back({cx - hx, cy - hy, cx + hx, cy + hy});
  }
  return W;
}

namespace {

T2_PROBLEM({"range", "reported points", Input::plane});

// The timed run of structure S: built on the points, then every window reported.
template <class S>
Timed range_run(BenchInput& in) {
  auto R = std::make_shared<std::vector<t2::ExactIsoRect>>();
  for (const auto& w : range_windows(in.points))
    R->push_back(t2::iso_rect(t2::to_exact(t2::Point::cartesian(w[0], w[1])),
                              t2::to_exact(t2::Point::cartesian(w[2], w[3]))));
  return [&P = in.points, R] {
    const S tree(P);
    std::size_t k = 0;
    for (const auto& r : *R) k += tree.report(r).size();
    return k;
  };
}

T2_ALGORITHM({.name = "kdtree",
              .problem = "range",
              .summary = "t2::KdTree: a kd-tree per side of T2, O(sqrt n + k) a window (built, then n/10 windows)",
              .title = "range search with a kd-tree",
              .time = range_run<t2::KdTree>,
              .peers = {"nanoflann", "rtree", "rangetree"}});

T2_ALGORITHM({.name = "rangetree",
              .problem = "range",
              .summary = "t2::RangeTree: a range tree with fractional cascading, O(log n + k) a window",
              .title = "range search with a range tree",
              .time = range_run<t2::RangeTree>});

}  // namespace
}  // namespace t2cli::algorithms
