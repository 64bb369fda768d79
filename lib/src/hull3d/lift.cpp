// The lifting map and the Delaunay triangulation as the lower hull of the lifted points.
#include "t2/hull3d/lift.hpp"

#include <algorithm>
#include <cmath>

#include "t2/kernel/error.hpp"
#include "t2/hull3d/convex_hull_3d.hpp"
#include "t2/kernel/detail/orient_double.hpp"

namespace t2 {

Point3 lift(const Point& p) {
  if (p.w() != 1) throw Undefined("lift: the point " + to_string(p) + " is not Cartesian [1, x, y]");
  const double x = p.x(), y = p.y(), xx = x * x, yy = y * y, s = xx + yy;
  // exact iff both squares and their sum are: fma gives each rounding error exactly
  if (std::fma(x, x, -xx) != 0 || std::fma(y, y, -yy) != 0 || s - xx != yy || s - yy != xx || !std::isfinite(s))
    throw Undefined("lift: x² + y² of " + to_string(p) + " is not a double");
  return {x, y, s};
}

std::vector<Triangle3> delaunay_by_lifting(std::span<const Point> points) {
  std::vector<Point3> lifted;
  lifted.reserve(points.size());
  for (const Point& p : points) lifted.push_back(lift(p));
  std::vector<Triangle3> out;
  for (auto f : hull_facets_3d(lifted)) {  // lower facets: clockwise seen from above
    const Point3 &a = lifted[f[0]], &b = lifted[f[1]], &c = lifted[f[2]];
    if (detail::orient2(a.x, a.y, b.x, b.y, c.x, c.y) != NEGATIVE) continue;
    std::reverse(f.begin() + 1, f.end());  // counter-clockwise in the plane, f[0] still smallest
    for (std::size_t k = 1; k + 1 < f.size(); ++k) out.push_back({f[0], f[k], f[k + 1]});
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace t2
