#pragma once
// What the registry's entries (registry.hpp) share: an answer as a scene, and the first and
// last steps of a recording (the input, the answer) and the checks every animation makes.
#include <cstddef>
#include <string>
#include <vector>

#include "algorithms/registry.hpp"
#include "t2/trace/step.hpp"
#include "t2/triangulation/triangulation.hpp"

namespace t2::trace {
class Recording;
}

namespace t2cli::algorithms {

/// The polygons of the indices into P (a hull, the layers), one ScenePolygon each, in order.
t2::Scene polygons_scene(const Points& P, const std::vector<std::vector<std::size_t>>& polygons);
/// The finite triangles of `t` (sorted), one ScenePolygon each.
t2::Scene triangles_scene(const Points& P, const t2::Triangulation& t);

/// The number of finite triangles of `t`, counted in place: what a timed triangulation returns
/// (finite_triangles() would copy them, 24 bytes a point, and hull_edges() the hull: memory in
/// the measured peak that CGAL's number_of_faces() does not pay).
std::size_t finite_count(const t2::Triangulation& t);

/// A step of `kind` with its text and structure ("hull", "triangles", or "").
t2::trace::Step make_step(const char* kind, std::string text, const char* structure);
/// "p3, p1, p4"
std::string point_list(const std::vector<std::size_t>& v);
/// The last step of a hull algorithm: the hull h (indices, counter-clockwise).
void record_hull_answer(const std::vector<std::size_t>& h, t2::trace::Recording& rec);
/// The last step of a triangulation: the answer `t` (`what` it is).
void record_triangles_answer(const t2::Triangulation& t, const std::string& what, t2::trace::Recording& rec);
/// Throws t2::BadInput unless every point is in front (w > 0): `algo` is animated for those only.
void require_front(const Points& P, const std::string& name, const std::string& algo);

}  // namespace t2cli::algorithms
