// t2 lec: the largest empty circle of a scene's points in T² with its centre in their hull
// (t2/proximity/empty_circle.hpp, Algorithm 13).
#include <fmt/format.h>

#include <memory>
#include <string>

#include "command.hpp"
#include "proximity_answer.hpp"
#include "scene_argument.hpp"
#include "t2/kernel/error.hpp"
#include "t2/proximity/empty_circle.hpp"

namespace t2cli {
namespace cmd_lec {

int run(const ProximityOptions& o) {
  const t2::Scene scene = read_scene_argument(o.file);
  const std::vector<t2::Point> P = scene_points(scene);
  if (P.empty()) throw t2::BadInput(fmt::format("{}: the largest empty circle needs at least one point", scene.name));
  t2::EmptyCircle c;
  try {
    c = t2::largest_empty_circle(P);
  } catch (const t2::UndefinedEmptyCircle& e) {
    throw undefined_at(scene, e.site, e.other, e.what());
  }
  print_circle(o.drawing, scene, P, c.center, c.on_circle,
               fmt::format("t2 lec {}: the largest empty circle and its centre (draw it over its input: t2 draw FILE "
                           "THIS)",
                           scene.name));
  return kOk;
}

Action setup(Arguments& app) {
  auto o = std::make_shared<ProximityOptions>();
  app.description(
      "Prints the largest empty circle of the points of the scene file FILE (- for standard\n"
      "input) whose centre is a proper point of their convex hull (Algorithm 13: the Voronoi\n"
      "vertices in the hull and the crossings of Voronoi edges with the hull, exact rationals).\n"
      "Empty: no point strictly inside. For points all on one side it is the classic circle of\n"
      "their drawn positions, centred on that side; collinear points: the midpoint of the widest\n"
      "gap. A point on Omega, points on both sides (the hull reaches Omega: no largest circle)\n"
      "or all points equal (radius 0): undefined, exit 3.");
  app.add_option("FILE", o->file, "the scene file, - for standard input")->required();
  add_drawing_options(app, o->drawing, "the points, the circle and its centre");
  app.footer(
      "Output: a line 'W X Y', the exact centre as integer homogeneous coordinates with no\n"
      "common factor (W > 0 for front points, W < 0 for back points), then a line with the\n"
      "0-based indices of every point on the circle, ascending (equal points all listed). Among\n"
      "centres of equal radius, the smallest drawn position (x, then y).\n"
      "Exit status: 0 done; 2 bad usage or bad input (file:line: what is wrong; no points);\n"
      "3 undefined in T2 (file:line of a point on Omega, of a front and a back point, or of the\n"
      "first point when all are equal).");
  return [o] { return run(*o); };
}

}  // namespace cmd_lec

T2_COMMAND({"lec", "the largest empty circle of a scene's points in T2 ('W X Y', the points on it)", cmd_lec::setup});

}  // namespace t2cli
