// The smallest enclosing circle on the farthest-point Voronoi diagram: Shamos's algorithm and
// Bhattacharya–Toussaint's (t2/proximity/enclosing_circle_voronoi.hpp).
#include "t2/proximity/enclosing_circle_voronoi.hpp"

#include <array>
#include <stdexcept>
#include <vector>

#include "enclosing_disk.hpp"
#include "t2/hull/calipers.hpp"
#include "t2/hull/convex_hull.hpp"
#include "t2/kernel/distance.hpp"
#include "t2/voronoi/complex.hpp"

namespace t2 {
namespace {

using namespace detail;
using Index = EnclosingIndex;
using Face = std::array<Index, 3>;

/// Does every site of P[at] lie in the closed disk d? (`at` empty: every site of P.)
bool holds(const Disk& d, const std::vector<Point>& P, const std::vector<Index>& at) {
  if (at.empty()) {
    for (const Point& p : P)
      if (side(d, p) == NEGATIVE) return false;
    return true;
  }
  for (Index i : at)
    if (side(d, P[i]) == NEGATIVE) return false;
  return true;
}

//> sec-acute
/// The circle of the acute face among the farthest-point Delaunay faces F (site
/// indices into P): the one whose circumcentre lies strictly inside it, each vertex
/// strictly outside the disk on the opposite edge. When the diameter's circle fails,
/// exactly the smallest enclosing circle's face is acute (chapter 12, Theorem 9),
/// whatever the fan of cocircular sites.
Disk acute_face(const std::vector<Point>& P, const std::vector<Face>& F) {
  for (const auto& [a, b, c] : F)
    if (in_diameter_disk(P[b], P[c], P[a]) == NEGATIVE &&  // the angle at a is acute
        in_diameter_disk(P[c], P[a], P[b]) == NEGATIVE &&  // at b
        in_diameter_disk(P[a], P[b], P[c]) == NEGATIVE)    // at c
      return circumcircle(P[a], a, P[b], b, P[c], c);
  throw std::logic_error("no acute farthest-point face (cannot happen)");
}
//< sec-acute

/// Collinear sites, or fewer than three distinct: the two ends of their segment (the farthest
/// site from site 0, then the farthest from it), whose diameter's circle holds them all.
Disk segment_ends(const std::vector<Point>& P) {
  Index a = 0, b = 0;
  for (Index i = 1; i < P.size(); ++i)
    if (compare_distance(P[0], P[a], P[0], P[i]) < 0) a = i;
  for (Index i = 0; i < P.size(); ++i)
    if (compare_distance(P[a], P[b], P[a], P[i]) < 0) b = i;
  return diameter(P[a], a, P[b], b);
}

}  // namespace

EnclosingCircle smallest_enclosing_circle_shamos(std::span<const Point> points) {
  const Sign sigma = enclosing_side(points);  // the rules of T²: throws where undefined
  const std::vector<Point> P = drawn_sites(points, sigma);
  //> sec-shamos
  // The back half of the T² Voronoi diagram of front sites is their farthest-point
  // diagram: its vertices are the clockwise faces of the Delaunay complex.
  const DelaunayComplex dc = delaunay_complex(P);
  std::vector<Face> far;
  for (std::size_t f = 0; f < dc.faces.size(); ++f)
    if (dc.turns[f] == NEGATIVE) far.push_back(dc.faces[f]);
  if (far.empty()) return enclosing_answer(P, {}, segment_ends(P), sigma);  // collinear
  // The longest edge of the farthest-point Delaunay triangulation; its circle, if it
  // holds every site, is the answer (it is then a diameter of the sites).
  Index a = far[0][0], b = far[0][1];
  for (const Face& t : far)
    for (int m = 0; m < 3; ++m)
      if (compare_distance(P[a], P[b], P[t[m]], P[t[(m + 1) % 3]]) < 0)
        a = t[m], b = t[(m + 1) % 3];
  Disk d = diameter(P[a], a, P[b], b);
  if (!holds(d, P, {})) d = acute_face(P, far);  // else a farthest-point Voronoi vertex
  //< sec-shamos
  return enclosing_answer(P, {}, d, sigma);
}

EnclosingCircle smallest_enclosing_circle_bt(std::span<const Point> points) {
  const Sign sigma = enclosing_side(points);
  const std::vector<Point> P = drawn_sites(points, sigma);
  //> sec-bt
  // The hull's strict corners, counter-clockwise, and the diameter by the calipers
  // (the largest antipodal pair: seed 003 writes "the smallest", a slip).
  const std::vector<std::size_t> hull = convex_hull(std::span<const Point>(P));
  Index a = Index(hull[0]), b = a;
  for (const auto& [i, j] : antipodal_pairs(P, hull))
    if (compare_distance(P[a], P[b], P[i], P[j]) < 0) a = Index(i), b = Index(j);
  Disk d = diameter(P[a], a, P[b], b);
  const std::vector<Index> corners(hull.begin(), hull.end());
  if (!holds(d, P, corners)) {  // the hull's corners suffice: the disk is convex
    // The farthest-point triangulation of the corners alone, then its acute face.
    std::vector<Point> C;
    for (Index i : corners) C.push_back(P[i]);
    std::vector<Face> far;
    for (const auto& t : farthest_delaunay(C))
      far.push_back({corners[t[0]], corners[t[1]], corners[t[2]]});
    d = acute_face(P, far);
  }
  //< sec-bt
  return enclosing_answer(P, {}, d, sigma);
}

}  // namespace t2
