#pragma once
/// @file enclosing_circle_voronoi.hpp
/// @brief The smallest enclosing circle of sites of T² on the farthest-point Voronoi diagram:
/// Shamos's algorithm and Bhattacharya–Toussaint's (seed 003 §2.1.2.3 and §4.3.4.1, figures
/// 4.32 and 4.33), with the T² definition, the undefined cases and the exact answer of
/// enclosing_circle.hpp: the three algorithms give the same `EnclosingCircle`, support included.
///
/// **The candidates** (chapter 12 proves them). Let C be the smallest enclosing circle of front
/// sites S, with centre z and radius r, and Q the sites on C. Then z lies in the hull of Q. So
/// either two sites of Q are the ends of a diameter of C — a diametral pair of S, since no two
/// sites of the disk are farther apart than 2r — and C is the circle on the diameter of S; or z
/// lies strictly inside a triangle of three sites of Q, an acute triangle whose circumcircle C
/// holds every site: a face of the farthest-point Delaunay triangulation, whose circumcentre is
/// a farthest-point Voronoi vertex. Conversely, any acute triangle of sites whose circumcircle
/// holds every site has that circle as the answer. In T², for front sites, the farthest-point
/// Voronoi diagram is the back half of the Voronoi diagram (voronoi/complex.hpp, part 1): its
/// vertices are the clockwise faces of the Delaunay complex.
///
/// **Exactness.** The seed picks "the smallest of the circles of the faces", which compares
/// circumradii (rationals of high degree). Here no radius is compared: the face taken is the
/// acute one, three signs of the diameter disk (P − A)·(P − B) each (the sign Welzl's code
/// uses), and the diameter test is the same sign against the sites. Diameters are compared by
/// `compare_distance` (kernel/distance.hpp). Whatever fan the complex chooses in a polygon of
/// cocircular sites, the answer is the same circle (chapter 12), and the support is chosen from
/// the sites on it as enclosing_circle.hpp says.
///
/// **Cost.** Shamos: the Delaunay complex of all the sites, O(n log n) expected, with Chew's
/// randomized farthest-point triangulation of the h hull corners, O(h) expected (complex.hpp),
/// then O(n) signs. Bhattacharya–Toussaint: the hull (O(n log n)), the calipers' diameter
/// (O(h)), the diameter test against the h corners, and the farthest-point triangulation of the
/// corners alone (the same insertion). Both O(n log n), expected.

#include <span>

#include "t2/kernel/point.hpp"
#include "t2/proximity/enclosing_circle.hpp"

namespace t2 {

/// The smallest enclosing circle of `points` by Shamos's algorithm (file comment): the
/// farthest-point Delaunay faces of the complex, the longest of their edges as the diameter
/// candidate, else the acute face. Throws as `smallest_enclosing_circle` (enclosing_circle.hpp).
EnclosingCircle smallest_enclosing_circle_shamos(std::span<const Point> points);

/// The smallest enclosing circle of `points` by Bhattacharya–Toussaint (file comment): the hull,
/// its diameter by the calipers, tested against the hull corners, else the acute face of the
/// farthest-point triangulation of the corners. Throws as `smallest_enclosing_circle`.
EnclosingCircle smallest_enclosing_circle_bt(std::span<const Point> points);

}  // namespace t2
