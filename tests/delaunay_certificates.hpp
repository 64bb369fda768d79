#pragma once
// Exact certificates that a t2::Triangulation is the Delaunay triangulation of its points,
// independent of how it was built: structure (validate), every point a vertex or a reported
// duplicate, every edge locally Delaunay (exact and perturbed), the hull edges the convex hull,
// and the triangles tiling the hull (areas summed in exact rationals).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <vector>

#include "t2/kernel/orient.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "testing.hpp"

namespace t2::testing {

using Tri = std::array<Triangulation::Index, 3>;

/// Twice the signed area of a, b, c in exact rationals (front points).
inline Rational area2(const Point& a, const Point& b, const Point& c) {
  const Rational ax = q(a.x()) / q(a.w()), ay = q(a.y()) / q(a.w()), bx = q(b.x()) / q(b.w()),
                 by = q(b.y()) / q(b.w()), cx = q(c.x()) / q(c.w()), cy = q(c.y()) / q(c.w());
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

/// Checks every certificate; `exact_areas` adds the O(n) rational area sum and the O(h·n) hull test.
inline void expect_delaunay(const Triangulation& tr, bool exact_areas = true) {
  ASSERT_EQ(tr.validate(), "");
  const auto& pts = tr.points();
  const std::size_t n = pts.size();
  // Every point is a vertex or a duplicate of a kept vertex equal to it.
  std::vector<char> is_vertex(n, 0);
  for (const Tri& t : tr.finite_triangles())
    for (auto v : t) is_vertex[v] = 1;
  for (const auto& [e0, e1] : tr.hull_edges()) is_vertex[e0] = is_vertex[e1] = 1;
  std::vector<char> dropped(n, 0);
  for (const auto& [d, k] : tr.duplicates()) {
    ASSERT_LT(k, d);
    EXPECT_TRUE(pts[d] == pts[k]) << d << " reported equal to " << k;
    EXPECT_TRUE(is_vertex[k] || tr.dimension() < 2);
    dropped[d] = 1;
  }
  if (tr.dimension() < 2) {
    EXPECT_TRUE(tr.finite_triangles().empty());
    return;
  }
  for (std::size_t v = 0; v < n; ++v) EXPECT_NE(is_vertex[v] != 0, dropped[v] != 0) << "point " << v;
  // Every edge between two finite triangles is locally Delaunay: exactly (not strictly inside)
  // and under the perturbation (strictly outside).
  for (Triangulation::Index t = 0; t < tr.size(); ++t) {
    if (tr.is_infinite(t)) continue;
    const Point &a = pts[tr.vertex(t, 0)], &b = pts[tr.vertex(t, 1)], &c = pts[tr.vertex(t, 2)];
    for (int i = 0; i < 3; ++i) {
      const auto e = tr.twin(t, i);
      if (tr.is_infinite(e / 3)) continue;
      const Point& d = pts[tr.vertex(e / 3, static_cast<int>(e % 3))];
      ASSERT_NE(in_circle(a, b, c, d), POSITIVE) << "edge " << i << " of triangle " << t << " is not Delaunay";
      ASSERT_EQ(perturbed_in_circle(DelaunayTraits{}, a, b, c, d), NEGATIVE)
          << "edge " << i << " of triangle " << t << " is not Delaunay under the perturbation";
    }
  }
  if (!exact_areas) return;
  // The hull edges are the convex hull: one counter-clockwise cycle, every point on the left or
  // on the line, none strictly inside an edge (it would be a vertex there).
  const auto hull = tr.hull_edges();
  std::map<Triangulation::Index, Triangulation::Index> next;
  for (auto [a, b] : hull) ASSERT_TRUE(next.emplace(a, b).second) << "two hull edges leave " << a;
  Triangulation::Index v = hull.front().first;
  for (std::size_t k = 0; k < hull.size(); ++k) v = next.at(v);
  ASSERT_EQ(v, hull.front().first);
  Rational hull_area = 0;
  for (auto [a, b] : hull) {
    hull_area += area2(pts[hull.front().first], pts[a], pts[b]);
    for (std::size_t p = 0; p < n; ++p) {
      const Sign o = orient(pts[a], pts[b], pts[p]);
      ASSERT_NE(o, NEGATIVE) << "point " << p << " outside hull edge " << a << " " << b;
      if (o == ZERO && !(pts[p] == pts[a]) && !(pts[p] == pts[b])) {
        ASSERT_NE(compare_xy(pts[a], pts[p]), compare_xy(pts[p], pts[b])) << "point " << p << " inside hull edge";
      }
    }
  }
  // The triangles, all counter-clockwise (validate), cover exactly the hull's area: with the
  // structure (every edge shared by two triangles, every star one cycle) they tile the hull.
  Rational sum = 0;
  for (const Tri& t : tr.finite_triangles()) sum += area2(pts[t[0]], pts[t[1]], pts[t[2]]);
  EXPECT_EQ(sum, hull_area);
}

/// The finite triangles, sorted (each rotated smallest index first by finite_triangles()).
inline std::vector<Tri> triangle_set(const Triangulation& tr) {
  auto t = tr.finite_triangles();
  std::sort(t.begin(), t.end());
  return t;
}

/// A triangle with its indices renamed by `map`, rotated smallest first.
inline Tri renamed(const Tri& t, const std::vector<Triangulation::Index>& map) {
  Tri r = {map[t[0]], map[t[1]], map[t[2]]};
  std::rotate(r.begin(), std::min_element(r.begin(), r.end()), r.end());
  return r;
}

}  // namespace t2::testing
