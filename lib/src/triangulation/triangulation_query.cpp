// The queries of t2::Triangulation (triangulation.hpp): edges, the public exact locate and
// nearest_vertex. The stars (incident_faces, neighbors) are inline in the header.
#include <stdexcept>
#include <string>
#include <vector>

#include "t2/kernel/distance.hpp"
#include "t2/kernel/error.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/triangulation/triangulation.hpp"

namespace t2 {

std::vector<Triangulation::Index> Triangulation::edges() const {
  std::vector<Index> out;
  out.reserve(n_.size() / 2);
  for (Index h = 0; h < n_.size(); ++h)
    if (h < n_[h]) out.push_back(h);
  return out;
}

namespace {

/// Throws unless tr is a planar triangulation (dimension 2, v∞ a vertex) and p is a front point.
void check_planar(const Triangulation& tr, const Point& p, const char* what) {
  if (tr.dimension() != 2)
    throw std::logic_error(std::string(what) + ": the triangulation has no triangle (dimension " +
                           std::to_string(tr.dimension()) + ")");
  if (tr.face_of(Triangulation::infinite) == Triangulation::none)
    throw Undefined(std::string(what) + ": the triangulation covers T2 without a hull (no v-infinity); "
                    "the planar walk needs a hull");
  if (p.w() <= 0)
    throw Undefined(std::string(what) + ": " + to_string(p) +
                    " is not on the front side (w > 0), which the planar triangulation covers");
}

}  // namespace

Triangulation::Location Triangulation::locate(const Point& p, Index hint) const {
  check_planar(*this, p, "locate");
  std::uint32_t rng = 2463534242u;
  return locate(p, static_cast<Index>(hint % size()),
                [](const Point& a, const Point& b, const Point& c) { return orient(a, b, c); }, rng);
}

//> nearest-vertex
// Why the greedy walk stops at a nearest vertex of a Delaunay triangulation. Let v be a vertex
// that is not a nearest one to p. The closed Voronoi cell of v is convex with nonempty interior
// (the vertices are distinct), so it is the intersection of the closed half-planes
// {x : |x − v| ≤ |x − w|} of the sites w whose cells share an edge with it; p lies outside it,
// hence |p − w| < |p − v| for one of those w. Two cells share an edge exactly when the sites
// are joined in the Delaunay subdivision, which every Delaunay triangulation refines (the
// perturbation of delaunay.hpp only adds diagonals to its cocircular faces): w is a neighbour
// of v. Each step makes the distance strictly smaller, so no vertex repeats and the walk stops,
// at a vertex with no nearer neighbour: a nearest one.
Triangulation::Index Triangulation::nearest_vertex(const Point& p, Index hint) const {
  const Location loc = locate(p, hint);
  Index v = vertex(loc.t, loc.i);  // a vertex: loc.i is its slot; otherwise any finite one
  if (loc.kind == Location::vertex) return v;
  for (int k = 0; v == infinite; ++k) v = vertex(loc.t, k);
  for (bool moved = true; moved;) {
    moved = false;
    for (Index w : neighbors(v)) {
      if (w == infinite || compare_distance(points_[w], points_[v], p) != NEGATIVE) continue;
      v = w;
      moved = true;
      break;
    }
  }
  return v;
}
//< nearest-vertex

}  // namespace t2
