// The peers of `t2 bench` that are not t2's algorithms: what they are called and what they
// solve. Their runs are the worker's (bench/t2_bench_worker.cpp), which alone links CGAL, qhull
// and GEOS (and alone includes nanoflann, Boost.Geometry and Boost.Polygon, header-only); tests/test_registry.cpp
// checks that the worker runs every one registered here.
#include "algorithms/registry.hpp"

namespace t2cli::algorithms {
namespace {

T2_PEER({"cgal", {"hull", "delaunay", "hull3d", "intersect", "locate", "locate-build", "sec"},
         "CGAL: ch_akl_toussaint (hull), Delaunay_triangulation_2<Epick> (delaunay and locate-build; its locate "
         "from the last face, for locate), convex_hull_3 (hull3d), compute_intersection_points<Epeck> (intersect), "
         "Min_circle_2<Epeck> shuffled (sec)",
         true});
T2_PEER({"cgal-sorted", {"locate"},
         "CGAL's Delaunay_triangulation_2<Epick>::locate from the last face, the queries in t2's spatial order", true});
T2_PEER({"qhull", {"hull", "hull3d"}, "qhull (libqhull_r, default options: merges nearly coplanar facets)", false});
T2_PEER({"nanoflann", {"range"},
         "nanoflann 1.4's kd-tree (leaves of 10), each window a radius search under a 0/1 window metric", true});
T2_PEER({"rtree", {"range"}, "Boost.Geometry's rtree<rstar<16>>, bulk loaded, covered_by queries", true});
T2_PEER({"boost", {"voronoi-front"},
         "Boost.Polygon's construct_voronoi (Fortune's sweep) on the points rounded to the grid 2^-24 (it takes "
         "32-bit integers only): the vertex count of the rounded points",
         false});
T2_PEER({"geos", {"lec"},
         "GEOS 3.11's GEOSLargestEmptyCircle (a grid refined by branch and bound, centre in the hull, in doubles) "
         "to within a thousandth of the points' mean spacing",
         false});
T2_PEER({"raw", {"hull", "delaunay"},
         "ALGO's t2 code (convex_hull, delaunay) on plain double predicates (naive, inexact)", false, true});
T2_PEER({"exact", {"hull", "delaunay"}, "ALGO's t2 code with exact GMP arithmetic on every call (no filter)", true,
         true});

}  // namespace
}  // namespace t2cli::algorithms
