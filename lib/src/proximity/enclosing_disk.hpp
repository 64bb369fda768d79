#pragma once
// What the three smallest-enclosing-circle algorithms share (t2/proximity/enclosing_circle.hpp,
// enclosing_circle_voronoi.hpp), written once in enclosing_circle.cpp: the T² rules (which
// sets have no smallest circle), the circles of one, two or three sites with their exact side
// tests, and the answer built from the circle found, so that the three give the same centre,
// the same sites on the circle and the same support. Private to lib/src/proximity.
#include <array>
#include <span>
#include <vector>

#include "t2/kernel/point.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/proximity/enclosing_circle.hpp"

namespace t2::detail {

using EnclosingIndex = EnclosingCircle::Index;

/// A circle of the algorithms: the sites that define it (1, 2 or 3 of them), as points, so that
/// a test reads no other memory, and as input indices. Three sites are kept counter-clockwise
/// (in the T² orientation), so that in_circle alone says inside (POSITIVE) or out.
struct Disk {
  std::array<Point, 3> p{Point(1, 0, 0), Point(1, 0, 0), Point(1, 0, 0)};
  std::array<EnclosingIndex, 3> s{};
  int k = 0;  ///< how many sites: 1 a point, 2 a diameter, 3 a circumcircle
};

/// The circle with diameter ab.
inline Disk diameter(const Point& a, EnclosingIndex i, const Point& b, EnclosingIndex j) {
  return Disk{{a, b, a}, {i, j, i}, 2};
}

/// The circle through a, b, c (not collinear), counter-clockwise.
inline Disk circumcircle(const Point& a, EnclosingIndex i, const Point& b, EnclosingIndex j, const Point& c,
                         EnclosingIndex k) {
  if (orient(a, b, c) == NEGATIVE) return Disk{{a, c, b}, {i, k, j}, 3};
  return Disk{{a, b, c}, {i, j, k}, 3};
}

/// The side of p relative to the closed disk with diameter ab (proper points of one side):
/// POSITIVE inside, ZERO on the circle, NEGATIVE outside (enclosing_circle.cpp).
Sign in_diameter_disk(const Point& a, const Point& b, const Point& p);

/// The side of q relative to the closed disk of d (POSITIVE inside, ZERO on, NEGATIVE out).
Sign side(const Disk& d, const Point& q);

/// The rules of T² (enclosing_circle.hpp): throws `BadInput` for no sites or too many,
/// `UndefinedEnclosing` for sites on both sides or a site on Ω; else the sites' side.
Sign enclosing_side(std::span<const Point> points);

/// The drawn positions of sites all on side `sigma`: the sites, or their antipodes behind.
std::vector<Point> drawn_sites(std::span<const Point> points, Sign sigma);

/// The answer for the drawn sites P, P[i] being input site id[i] (site i when `id` is empty),
/// whose smallest enclosing circle is d: the
/// exact centre (put back on side `sigma`), the squared radius, every site on the circle, and
/// the support as Welzl's run on those sites alone picks it (so it does not depend on how d was
/// found).
EnclosingCircle enclosing_answer(const std::vector<Point>& P, const std::vector<EnclosingIndex>& id, const Disk& d,
                                 Sign sigma);

}  // namespace t2::detail
