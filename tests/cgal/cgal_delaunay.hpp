#pragma once
// CGAL's Delaunay_triangulation_2 (Epick) as the oracle of the Delaunay tests of front points
// (cgal_oracle.cpp): its finite triangles as index triples in the form of t2's, with CGAL's
// choice among equal points renamed to t2's (the smallest index). CGAL breaks cocircular ties
// with the same symbolic perturbation as t2, so the triangle sets must be equal on every input.
#include <gtest/gtest.h>

#include <vector>

#include "cgal/cgal_oracle.hpp"
#include "delaunay_certificates.hpp"

namespace t2::testing {

/// Expects the finite triangles of `tr` (built on `pts`) to be CGAL's.
inline void expect_cgal_triangles(const Triangulation& tr, const std::vector<Point>& pts) {
  const auto theirs = cgal::delaunay_triangles(pts, tr.duplicates());
  const auto ours = triangle_set(tr);
  EXPECT_EQ(ours.size(), theirs.size());
  EXPECT_TRUE(ours == theirs) << "the triangle sets of t2 and CGAL differ";
}

}  // namespace t2::testing
