// The 3-D hull entry points: the algorithm by name, triangles, the hull as a polyhedron.
#include "t2/hull3d/convex_hull_3d.hpp"

namespace t2 {

std::string_view name(Hull3dAlgorithm a) {
  switch (a) {
    case Hull3dAlgorithm::incremental: return "incremental";
    case Hull3dAlgorithm::quickhull: return "quickhull";
    case Hull3dAlgorithm::gift_wrap: return "gift-wrap";
  }
  return "?";
}

Facets hull_facets_3d(std::span<const Point3> points, Hull3dAlgorithm a) {
  if (a == Hull3dAlgorithm::gift_wrap) return gift_wrap_3d(points);
  return incremental_3d(points, a == Hull3dAlgorithm::quickhull);
}

std::vector<Triangle3> convex_hull_3d(std::span<const Point3> points, Hull3dAlgorithm a) {
  return fan_triangles(hull_facets_3d(points, a));
}

Polyhedron hull_polyhedron(std::span<const Point3> points, Hull3dAlgorithm a) {
  return polyhedron_of(points, hull_facets_3d(points, a));
}

}  // namespace t2
