#pragma once
// The figures of chapter 10 beyond the first ones of main.cpp: the flip of an illegal edge, the
// merge of divide and conquer, a band face with its lune disk, and the antipodal edge with its
// two lunes (added to the figure of main.cpp).
#include <t2/t2.hpp>
#include <t2/triangulation/triangulation.hpp>

#include <vector>

namespace chapter10 {

/// Adds to f, for every antipodal edge z → ¬z recorded by tr, its two lunes (shaded) and the
/// edge itself: the half great circle that leaves z along the outward bisector
/// (t2/triangulation/antipodal_edge.hpp). Returns, for each edge, its point a quarter of
/// the way from its front end, for centring the sphere on them.
std::vector<t2::Point> add_antipodal_lunes(t2::draw::Figure& f, const t2::Triangulation& tr,
                                           const std::vector<t2::Point>& P);

/// Writes the figures flip-*, merge-* and band-* (both models) through out.
void more_figures(t2::draw::FigurePairs& out);

}  // namespace chapter10
