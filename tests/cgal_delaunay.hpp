#pragma once
// CGAL's Delaunay_triangulation_2 (Epick) as the oracle of the Delaunay tests of front points:
// its finite triangles as index triples in the form of t2's, with CGAL's choice among equal
// points renamed to t2's (the smallest index). CGAL breaks cocircular ties with the same
// symbolic perturbation as t2, so the triangle sets must be equal on every input.
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <numeric>
#include <utility>
#include <vector>

#include "delaunay_certificates.hpp"

namespace t2::testing {

/// CGAL's finite triangles of `pts` (front points with w = 1), counter-clockwise, smallest
/// index first, sorted; an index dropped by `duplicates` (t2's (dropped, kept) pairs) is
/// written as the kept one.
inline std::vector<Tri> cgal_triangles(const std::vector<Point>& pts,
                                       const std::vector<std::pair<Triangulation::Index, Triangulation::Index>>& duplicates) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<Triangulation::Index, K>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb>;
  std::vector<std::pair<K::Point_2, Triangulation::Index>> in;
  for (Triangulation::Index k = 0; k < pts.size(); ++k) in.emplace_back(K::Point_2(pts[k].x(), pts[k].y()), k);
  CGAL::Delaunay_triangulation_2<K, Tds> dt(in.begin(), in.end());
  std::vector<Triangulation::Index> canonical(pts.size());
  std::iota(canonical.begin(), canonical.end(), 0);
  for (auto [dropped, kept] : duplicates) canonical[dropped] = kept;
  std::vector<Tri> out;
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
    out.push_back(renamed({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()}, canonical));
  std::sort(out.begin(), out.end());
  return out;
}

/// Expects the finite triangles of `tr` (built on `pts`) to be CGAL's.
inline void expect_cgal_triangles(const Triangulation& tr, const std::vector<Point>& pts) {
  const auto theirs = cgal_triangles(pts, tr.duplicates());
  const auto ours = triangle_set(tr);
  EXPECT_EQ(ours.size(), theirs.size());
  EXPECT_TRUE(ours == theirs) << "the triangle sets of t2 and CGAL differ";
}

}  // namespace t2::testing
