#pragma once
// Exercise 11: the API you implement in vertex.cpp. Do not change this file.
#include <t2/kernel/point.hpp>

namespace ex11 {

/// The Voronoi vertex of the face (a, b, c) of the Delaunay complex (chapter 11, section 5), as
/// an exact homogeneous point; any positive multiple of the answer is accepted. a, b, c: three
/// distinct sites of T².
///  - a, b, c proper, on one side, not collinear: the point equidistant in T² from the three,
///    drawn at the Euclidean circumcentre of their drawn positions ([w, x, y] is drawn at
///    (x/w, y/w)), on the side of the sites when t2::orient(a, b, c) > 0 and on the other side
///    when t2::orient(a, b, c) < 0.
///  - Otherwise, when two sites p → q, consecutive in the cycle a → b → c → a, are proper and on
///    one side (for three collinear sites of one side, the pair that does not hold the third
///    strictly between its ends): the pole [0, l_x, l_y] of their line l = p ∨ q = p × q, a point
///    of Ω perpendicular to the line, on the left of P → Q, their drawn positions (on either side).
///  - Otherwise (no two consecutive sites proper on one side): throws t2::Undefined.
t2::ExactPoint voronoi_vertex(const t2::Point& a, const t2::Point& b, const t2::Point& c);

}  // namespace ex11
