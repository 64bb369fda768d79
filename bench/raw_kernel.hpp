#pragma once
// What the Delaunay benchmarks share (bench_delaunay and t2_bench_worker): the points handed to
// CGAL, and the Delaunay code's kernel on raw double predicates (no filter, not exact), which
// measures what exactness costs.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <vector>

#include "t2/kernel/filter.hpp"
#include "t2/kernel/incircle.hpp"
#include "t2/kernel/point.hpp"
#include "t2/triangulation/delaunay.hpp"

namespace t2bench {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;

/// The same points (w = 1) as CGAL's.
inline std::vector<Epick::Point_2> to_cgal(const std::vector<t2::Point>& pts) {
  std::vector<Epick::Point_2> out;
  out.reserve(pts.size());
  for (const auto& p : pts) out.emplace_back(p.x(), p.y());
  return out;
}

/// The sign of a double, as it is (no error bound).
inline t2::Sign raw_sign(double v) { return v > 0 ? t2::POSITIVE : v < 0 ? t2::NEGATIVE : t2::ZERO; }

/// Orientation evaluated once in doubles: naive, inexact.
inline t2::Sign raw_orient(const t2::Point& p, const t2::Point& q, const t2::Point& r) {
  return raw_sign(t2::det3(p.w(), p.x(), p.y(), q.w(), q.x(), q.y(), r.w(), r.x(), r.y()));
}

/// The Delaunay code on plain double predicates: not exact (uniform input only).
struct RawDelaunayTraits : t2::DelaunayTraits {
  /// orient in doubles
  static t2::Sign orient(const t2::Point& p, const t2::Point& q, const t2::Point& r) { return raw_orient(p, q, r); }
  /// in_circle in doubles
  static t2::Sign in_circle(const t2::Point& a, const t2::Point& b, const t2::Point& c, const t2::Point& d) {
    return raw_sign(t2::detail::lifted_det4(a.w(), a.x(), a.y(), b.w(), b.x(), b.y(), c.w(), c.x(), c.y(), d.w(),
                                            d.x(), d.y()));
  }
};

}  // namespace t2bench
