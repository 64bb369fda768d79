#pragma once
// Exercise 08b: the API you implement in facet.cpp. Do not change this file.
#include <vector>

#include <t2/kernel/orient3d.hpp>

namespace ex08b {

/// The step of gift wrapping (chapter 08, section 6), with FACET. P: points of R³, not all
/// coplanar; equal points may occur. f: a facet of the hull of P — its strict vertices (no
/// point inside an edge), counter-clockwise seen from outside, each the smallest index among
/// the points equal to it. k: an index into f, naming the edge a -> b with a = f[k] and
/// b = f[(k + 1) % f.size()].
///
/// Returns the other facet through the edge a b, in the same form: its strict vertices,
/// counter-clockwise seen from outside, each the smallest index among the points equal to it,
/// starting with b, a (the new facet runs along the edge from b to a). All points of P lying in
/// its plane are in the facet (a polygon, maybe with many vertices), and none outside it
/// (t2::orient3d decides, exactly).
std::vector<long> next_facet(const std::vector<t2::Point3>& P, const std::vector<long>& f, long k);

}  // namespace ex08b
