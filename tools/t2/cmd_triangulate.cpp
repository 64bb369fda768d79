// t2 triangulate: a triangulation of a scene's points (t2/triangulation/triangulate.hpp).

#include <memory>

#include "command.hpp"
#include "t2/triangulation/triangulate.hpp"
#include "triangles_command.hpp"

namespace t2cli {
namespace cmd_triangulate {

Action setup(Arguments& app) {
  auto o = std::make_shared<TrianglesOptions>();
  app.description(
      "Prints a triangulation of the points of the scene file FILE (- for standard input). Front\n"
      "points: the sweep of chapter 09 (points sorted by x, then y; each added outside the hull\n"
      "of the previous ones). Points behind or on Omega: Algorithm 9 on T2 (input order; the\n"
      "point that destroys the hull replaces the infinite vertex; the antipode of a hull vertex\n"
      "z is joined to z along the bisector of the hull angle, and the two faces at that edge\n"
      "are lunes, printed with their three vertices). Every point is a vertex; the triangles\n"
      "are not Delaunay (t2 delaunay).");
  return triangles_setup(app, o, "triangulate",
                         [](std::span<const t2::Point> P, const TrianglesOptions&) { return t2::triangulate(P); });
}

}  // namespace cmd_triangulate

T2_COMMAND({"triangulate", "a triangulation of a scene's points (triangles as index triples)", cmd_triangulate::setup});

}  // namespace t2cli
