// The locus method of counting (range/locus.hpp): Algorithms 17 and 18 of seed 000.
#include "t2/range/locus.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "t2/kernel/bbox.hpp"

namespace t2 {
namespace {

bool less(const ExactT1& a, const ExactT1& b) { return compare(a, b) == NEGATIVE; }

// The distinct values, increasing.
std::vector<ExactT1> distinct(std::vector<ExactT1> v) {
  std::sort(v.begin(), v.end(), less);
  v.erase(std::unique(v.begin(), v.end(), [](const ExactT1& a, const ExactT1& b) { return compare(a, b) == ZERO; }),
          v.end());
  return v;
}

// The number of values of v below x, and at most x.
std::size_t below(const std::vector<ExactT1>& v, const ExactT1& x) {
  return static_cast<std::size_t>(std::lower_bound(v.begin(), v.end(), x, less) - v.begin());
}
std::size_t at_most(const std::vector<ExactT1>& v, const ExactT1& x) {
  return static_cast<std::size_t>(std::upper_bound(v.begin(), v.end(), x, less) - v.begin());
}

}  // namespace

LocusCounter::LocusCounter(std::span<const Point> points) {
  if (points.size() > std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("LocusCounter: more points than 32-bit counts hold");
  std::vector<ExactPoint> on[2];
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point& p = points[i];
    if (p.w() == 0)
      omega_.add(p, static_cast<std::uint32_t>(i));
    else
      on[p.w() > 0 ? 0 : 1].push_back(to_exact(p));
  }
  for (int s = 0; s < 2; ++s) {
    Grid& g = side_[s];
    std::vector<ExactT1> xs, ys;
    for (const ExactPoint& p : on[s]) {
      xs.push_back(detail::cartesian_t1(p.w(), p.x()));
      ys.push_back(detail::cartesian_t1(p.w(), p.y()));
    }
    g.xs = distinct(xs);
    g.ys = distinct(ys);
    const std::size_t ny = g.ys.size() + 1;
    g.q.assign((g.xs.size() + 1) * ny, 0);
    //> locus-build
    // C: each point counts at the grid corner above and right of it.
    for (std::size_t k = 0; k < xs.size(); ++k)
      ++g.q[(below(g.xs, xs[k]) + 1) * ny + below(g.ys, ys[k]) + 1];
    // Q(i, j): the points with x rank < i and y rank < j (prefix sums).
    for (std::size_t i = 1; i <= g.xs.size(); ++i)
      for (std::size_t j = 1; j < ny; ++j) {
        const std::size_t at = i * ny + j;
        g.q[at] += g.q[at - ny] + g.q[at - 1] - g.q[at - ny - 1];
      }
    //< locus-build
  }
}

std::size_t LocusCounter::count(const ExactIsoRect& r) const {
  const ExactBBox b = bbox(r);
  // Ω: the vertex b or d, or the quarter from b to d (both axis directions and the quadrant).
  std::size_t n = omega_.count(b);
  //> locus-query
  const Grid& g = side_[r.a().w() > 0 ? 0 : 1];
  const std::size_t i0 = below(g.xs, b.xmin()), i1 = at_most(g.xs, b.xmax());
  const std::size_t j0 = below(g.ys, b.ymin()), j1 = at_most(g.ys, b.ymax());
  n += g.at(i1, j1) - g.at(i0, j1) - g.at(i1, j0) + g.at(i0, j0);
  //< locus-query
  return n;
}

std::size_t LocusCounter::count(const IsoRect& r) const {
  return count(ExactIsoRect(to_exact(r.a()), to_exact(r.dx()), to_exact(r.dy()), r.orientation()));
}

}  // namespace t2
