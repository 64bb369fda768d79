// t2 delaunay: the Delaunay triangulation of a scene's points (t2/triangulation/delaunay.hpp,
// incremental; divide.hpp, divide and conquer; lawson.hpp, flips).

#include <memory>

#include "command.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "t2/triangulation/divide.hpp"
#include "t2/triangulation/lawson.hpp"
#include "triangles_command.hpp"

namespace t2cli {
namespace cmd_delaunay {

Action setup(Arguments& app) {
  auto o = std::make_shared<TrianglesOptions>();
  o->algorithm = "incremental";
  app.description(
      "Prints the Delaunay triangulation of the points of the scene file FILE (- for standard\n"
      "input). Cocircular points are triangulated as if perturbed (chapter 10), so the answer\n"
      "is unique and every algorithm gives the same triangles. Points on both sides of T2 give\n"
      "the dual of the T2 Voronoi diagram (incremental only), which covers the whole sphere\n"
      "when the points have no hull; divide and flip refuse them (exit 3).");
  app.add_option("--algorithm", o->algorithm,
                 "incremental (default: randomized incremental with a spatial sort), divide\n"
                 "(Guibas-Stolfi divide and conquer on the quad-edge) or flip (Lawson: the\n"
                 "sweep triangulation, then flips)")
      ->type_name("A")
      ->check(IsMember({"incremental", "divide", "flip"}));
  return triangles_setup(app, o, "delaunay", [](std::span<const t2::Point> P, const TrianglesOptions& opt) {
    if (opt.algorithm == "flip") return t2::delaunay_by_flips(P);
    if (opt.algorithm == "divide") return t2::delaunay_divide(P);
    return t2::delaunay(P);
  });
}

}  // namespace cmd_delaunay

T2_COMMAND({"delaunay", "the Delaunay triangulation of a scene's points (index triples)", cmd_delaunay::setup});

}  // namespace t2cli
